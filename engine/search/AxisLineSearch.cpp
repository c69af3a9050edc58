#include "search/AxisLineSearch.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"

namespace fm {

void runAxisLineSearch(SearchProblem& problem, const AxisLineSearchSettings& s) {
    if (s.axis < 0 || s.axis >= problem.dimension() || s.rounds < 1 || s.pointsPerRound < 3 ||
        s.pointsPerRound % 2 == 0 || !(s.shrink > 0.0 && s.shrink < 1.0))
        throw Error("axis line search: inconsistent settings");
    Point center = problem.start();
    double h = 0.5 * problem.radius()[s.axis];
    const int half = s.pointsPerRound / 2;
    for (int round = 0; round < s.rounds && !problem.done(); ++round) {
        std::vector<Point> points;
        for (int k = -half; k <= half; ++k) {
            Point p = center;
            p[s.axis] += k * h;
            points.push_back(p);
        }
        const std::vector<double> cost = problem.evaluate(points);
        // Least squares c0 + c1 x + c2 x^2 on x = k (in units of h): the k are symmetric, so
        // the normal equations decouple: c1 = sum(k f) / sum(k^2), and c2 from the even part.
        double sk2 = 0, sk4 = 0, sf = 0, skf = 0, sk2f = 0;
        const int n = s.pointsPerRound;
        bool finite = true;
        for (int i = 0; i < n; ++i) {
            const double k = i - half, f = cost[i];
            finite = finite && std::isfinite(f);
            sk2 += k * k, sk4 += k * k * k * k, sf += f, skf += k * f, sk2f += k * k * f;
        }
        if (!finite) break;
        const double c1 = skf / sk2;
        const double c2 = (n * sk2f - sk2 * sf) / (n * sk4 - sk2 * sk2);
        const double lowest = problem.result().best[s.axis];
        double step;
        if (c2 > 0.0) {
            step = std::clamp(-c1 / (2.0 * c2), double(-half), double(half));
            center[s.axis] += step * h;
        } else {
            center[s.axis] = lowest;  // no minimum in the fit: go to the best point seen
        }
        center = problem.clamp(center);
        h *= s.shrink;
    }
    // The last vertex has not been evaluated yet.
    if (!problem.done()) problem.evaluate(center);
}

}  // namespace fm
