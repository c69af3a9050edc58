// Wavefront OBJ: "v x y z [w]" and "f i j k ..." (each corner i, i/t, i//n or i/t/n; 1-based,
// negative = counted back from the last vertex read so far); polygons are fanned into
// triangles. Texture coordinates, normals, groups, materials and lines are ignored.
#include <cmath>
#include <string_view>

#include "core/Error.h"
#include "model/MeshFile.h"
#include "model/MeshText.h"

namespace fm {

Mesh readObjBytes(const std::vector<std::uint8_t>& bytes, const std::string& what) {
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    model::TextCursor in(text, what);
    Mesh mesh;
    std::vector<std::uint32_t> polygon;
    while (!in.atEnd()) {
        const std::string_view key = in.nextOnLine();
        if (key == "v") {
            if (mesh.positions.size() >= kMaxModelElements) in.fail("more vertices than a model may have");
            glm::vec3 v;
            for (int a = 0; a < 3; ++a) {
                double c = 0.0;
                const std::string_view token = in.nextOnLine();
                if (!model::parseDouble(token, c))
                    in.fail("vertex " + std::to_string(mesh.positions.size() + 1) + " coordinate " +
                            std::to_string(a) + " must be a finite number, found '" +
                            std::string(token.substr(0, 40)) + "'");
                v[a] = static_cast<float>(c);
                if (!std::isfinite(v[a])) in.fail("vertex coordinate out of float range");
            }
            mesh.positions.push_back(v);
        } else if (key == "f") {
            polygon.clear();
            for (std::string_view corner = in.nextOnLine(); !corner.empty();
                 corner = in.nextOnLine()) {
                const std::string_view index = corner.substr(0, corner.find('/'));
                std::int64_t i = 0;
                if (!model::parseInteger(index, i) || i == 0)
                    in.fail("face corner '" + std::string(corner.substr(0, 40)) +
                            "' needs a non-zero vertex index");
                const auto n = static_cast<std::int64_t>(mesh.positions.size());
                const std::int64_t zeroBased = i > 0 ? i - 1 : n + i;
                if (zeroBased < 0 || zeroBased >= n)
                    in.fail("face vertex index " + std::to_string(i) + " is out of range (" +
                            std::to_string(n) + " vertices so far)");
                polygon.push_back(static_cast<std::uint32_t>(zeroBased));
            }
            if (polygon.size() < 3)
                in.fail("a face needs at least 3 vertices, has " + std::to_string(polygon.size()));
            for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
                mesh.triangles.push_back(glm::uvec3(polygon[0], polygon[k], polygon[k + 1]));
            if (mesh.triangles.size() > kMaxModelElements) in.fail("more triangles than a model may have");
        }
        // Anything else (comments, vt, vn, g, o, s, usemtl, mtllib, l, w of v) is skipped.
        in.skipLine();
    }
    if (mesh.triangles.empty()) throw Error(what + ": the OBJ has no face");
    return mesh;
}

}  // namespace fm
