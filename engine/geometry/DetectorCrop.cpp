#include "geometry/DetectorCrop.h"

#include <string>

#include "core/Error.h"

namespace fm {

ProjectionGeometry cropDetector(const ProjectionGeometry& g, int col0, int row0, int cols,
                                int rows) {
    const glm::ivec2 size = g.detector.size;
    if (cols < 1 || rows < 1 || col0 < 0 || row0 < 0 || col0 + cols > size.x ||
        row0 + rows > size.y)
        throw Error("detector crop [" + std::to_string(col0) + "+" + std::to_string(cols) + ", " +
                    std::to_string(row0) + "+" + std::to_string(rows) + "] leaves the " +
                    std::to_string(size.x) + "x" + std::to_string(size.y) + " detector");
    ProjectionGeometry c = g;
    c.detector.origin = g.detector.pixelCenter(col0, row0);
    c.detector.size = {cols, rows};
    return c;
}

}  // namespace fm
