#include "scene/DisplaySurface.h"

#include <cmath>

#include "volume/BlockMean.h"

namespace fm::app {

DisplaySurface displaySurface(const Volume& volume, const MarchingCubesOptions& options,
                              std::size_t maxTriangles) {
    DisplaySurface s;
    auto mesh = std::make_shared<const Mesh>(marchingCubes(volume, options));
    s.fullTriangles = mesh->triangleCount();
    // A surface's triangles scale with its area: a factor f leaves about 1/f^2 of them. (A
    // region of interest is in the volume's own voxels: kept whole.)
    const bool roi = options.roiMin || options.roiMax;
    while (!roi && mesh->triangleCount() > maxTriangles && s.factor < 16) {
        const double ratio = double(mesh->triangleCount()) / double(maxTriangles);
        s.factor = std::max(s.factor + 1, int(std::ceil(s.factor * std::sqrt(ratio))));
        mesh = std::make_shared<const Mesh>(
            marchingCubes(blockMean(volume, s.factor, options.threads), options));
    }
    s.mesh = std::move(mesh);
    return s;
}

}  // namespace fm::app
