#include "geometry/PatientDirection.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace fm {

std::string patientDirectionLetters(const glm::dvec3& lps) {
    const std::array<const char*, 3> positive{"L", "P", "S"}, negative{"R", "A", "I"};
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return std::abs(lps[a]) > std::abs(lps[b]); });
    const double strongest = std::abs(lps[order[0]]);
    std::string letters;
    if (!(strongest > 0.0)) return letters;
    for (int axis : order)
        if (std::abs(lps[axis]) >= 0.5 * strongest)
            letters += lps[axis] > 0.0 ? positive[axis] : negative[axis];
    return letters;
}

ImageEdgeLetters imageEdgeLetters(const ProjectionGeometry& g) {
    return imageEdgeLetters(g.detector.u, g.detector.v);
}

ImageEdgeLetters imageEdgeLetters(const glm::dvec3& u, const glm::dvec3& v) {
    return {patientDirectionLetters(-u), patientDirectionLetters(u), patientDirectionLetters(-v),
            patientDirectionLetters(v)};
}

}  // namespace fm
