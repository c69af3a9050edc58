#include "find/OrientedEdges.h"

#include <cmath>

#include "core/Error.h"
#include "similarity/EdgeDistance.h"
#include "similarity/Gradient.h"

namespace fm {

int orientationBin(double angle) {
    double a = std::fmod(angle, 2.0 * M_PI);
    if (a < 0.0) a += 2.0 * M_PI;
    return static_cast<int>(std::lround(a / (2.0 * M_PI / kOrientationBins))) % kOrientationBins;
}

OrientedDistances orientedEdgeDistances(const Image& image, int pool) {
    if (image.width < 3 || image.height < 3) throw Error("find: the scan image is smaller than 3 x 3");
    if (pool < 1) throw Error("find: the edge pooling factor must be at least 1");
    const int cw = image.width / pool, ch = image.height / pool;
    const Mask edges = strongEdges(image);
    const GradientImages g = sobel(image);
    OrientedDistances out;
    std::array<Mask, kOrientationBins> near;
    near.fill(Mask(cw, ch, false));
    for (int r = 0; r < ch * pool; ++r)
        for (int c = 0; c < cw * pool; ++c) {
            if (!edges.at(c, r)) continue;
            const int bin = orientationBin(std::atan2(g.gy.at(c, r), g.gx.at(c, r)));
            for (int d = -1; d <= 1; ++d)
                near[static_cast<std::size_t>((bin + d + kOrientationBins) % kOrientationBins)]
                    .inside[static_cast<std::size_t>(r / pool) * cw + c / pool] = 1;
        }
    for (int k = 0; k < kOrientationBins; ++k) out.distance[static_cast<std::size_t>(k)] = distanceToMask(near[static_cast<std::size_t>(k)]);
    return out;
}

}  // namespace fm
