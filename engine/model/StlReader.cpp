// STL: binary when the size is exactly 84 + 50 n (n = the count at byte 80), whatever the
// header says (binary files often begin with "solid" too); otherwise ASCII, which must begin
// with "solid". Each facet gives three new vertices (the format shares none).
#include <cmath>
#include <cstring>
#include <string_view>

#include "core/Error.h"
#include "io/HeaderText.h"
#include "model/MeshFile.h"
#include "model/MeshText.h"

namespace fm {
namespace {

constexpr std::size_t kBinaryHeader = 84;
constexpr std::size_t kBinaryFacet = 50;

std::uint32_t readU32LE(const std::uint8_t* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
           std::uint32_t(p[3]) << 24;
}

float readF32LE(const std::uint8_t* p) {
    const std::uint32_t bits = readU32LE(p);
    float f;
    std::memcpy(&f, &bits, 4);
    return f;
}

Mesh readBinary(const std::vector<std::uint8_t>& bytes, std::size_t count,
                const std::string& what) {
    if (count > kMaxModelElements)
        throw Error(what + ": binary STL facet count " + std::to_string(count) +
                    " is more than a model may have");
    Mesh mesh;
    mesh.positions.resize(3 * count);
    mesh.triangles.resize(count);
    for (std::size_t f = 0; f < count; ++f) {
        const std::uint8_t* p = bytes.data() + kBinaryHeader + f * kBinaryFacet + 12;  // skip normal
        for (int k = 0; k < 3; ++k) {
            glm::vec3 v;
            for (int a = 0; a < 3; ++a) v[a] = readF32LE(p + 12 * k + 4 * a);
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
                throw Error(what + ": facet " + std::to_string(f) + " vertex " +
                            std::to_string(k) + " has a non-finite coordinate");
            mesh.positions[3 * f + k] = v;
        }
        const auto i = static_cast<unsigned>(3 * f);
        mesh.triangles[f] = glm::uvec3(i, i + 1, i + 2);
    }
    return mesh;
}

Mesh readAscii(const std::vector<std::uint8_t>& bytes, const std::string& what) {
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    model::TextCursor in(text, what);
    Mesh mesh;
    std::size_t facets = 0;
    bool inSolid = false;
    while (!in.atEnd()) {
        const std::string_view token = in.next();
        if (io::equalsIgnoreCase(token, "solid")) {
            if (inSolid) in.fail("'solid' inside a solid (missing 'endsolid')");
            inSolid = true;
            in.skipLine();  // the solid's name
            continue;
        }
        if (io::equalsIgnoreCase(token, "endsolid")) {
            if (!inSolid) in.fail("'endsolid' without 'solid'");
            inSolid = false;
            in.skipLine();
            continue;
        }
        if (!io::equalsIgnoreCase(token, "facet"))
            in.fail("expected 'facet' or 'endsolid', found '" +
                    std::string(token.substr(0, 40)) + "'");
        if (!inSolid) in.fail("'facet' outside a solid");
        if (facets >= kMaxModelElements) in.fail("more facets than a model may have");
        const std::string field = "facet " + std::to_string(facets);
        in.expect("normal");
        for (int a = 0; a < 3; ++a) in.number(field + " normal");  // checked, not used
        in.expect("outer");
        in.expect("loop");
        const auto first = static_cast<unsigned>(mesh.positions.size());
        for (int k = 0; k < 3; ++k) {
            in.expect("vertex");
            glm::vec3 v;
            for (int a = 0; a < 3; ++a) {
                const double c = in.number(field + " vertex " + std::to_string(k));
                v[a] = static_cast<float>(c);
                if (!std::isfinite(v[a]))
                    in.fail(field + " vertex " + std::to_string(k) +
                            ": coordinate out of float range");
            }
            mesh.positions.push_back(v);
        }
        in.expect("endloop");
        in.expect("endfacet");
        mesh.triangles.push_back(glm::uvec3(first, first + 1, first + 2));
        ++facets;
    }
    if (inSolid) in.fail("the file ends inside a solid (missing 'endsolid': truncated?)");
    if (facets == 0) throw Error(what + ": the STL holds no facet");
    return mesh;
}

}  // namespace

Mesh readStlBytes(const std::vector<std::uint8_t>& bytes, const std::string& what) {
    if (bytes.size() >= kBinaryHeader) {
        const std::size_t count = readU32LE(bytes.data() + 80);
        if (bytes.size() == kBinaryHeader + kBinaryFacet * count) {
            if (count == 0) throw Error(what + ": the binary STL holds no facet");
            return readBinary(bytes, count, what);
        }
    }
    // Not binary by size: ASCII must start with "solid" in any case (SolidWorks writes
    // "SOLID"), after optional whitespace and a UTF-8 byte-order mark.
    if (bytes.size() >= 3 && bytes[0] == 0xEF && bytes[1] == 0xBB && bytes[2] == 0xBF)
        return readStlBytes(std::vector<std::uint8_t>(bytes.begin() + 3, bytes.end()), what);
    std::size_t i = 0;
    while (i < bytes.size() && (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\r' ||
                                bytes[i] == '\n'))
        ++i;
    const bool solid =
        bytes.size() - i >= 5 &&
        io::equalsIgnoreCase(std::string_view(reinterpret_cast<const char*>(bytes.data() + i), 5), "solid");
    if (!solid) {
        if (bytes.size() < kBinaryHeader)
            throw Error(what + ": " + std::to_string(bytes.size()) +
                        " bytes is too short for a binary STL (84-byte header) and it is not "
                        "ASCII STL (no 'solid')");
        const std::size_t count = readU32LE(bytes.data() + 80);
        throw Error(what + ": binary STL facet count " + std::to_string(count) +
                    " needs a file of 84 + 50 * " + std::to_string(count) + " = " +
                    std::to_string(kBinaryHeader + kBinaryFacet * count) + " bytes, the file has " +
                    std::to_string(bytes.size()) + " (truncated or corrupt)");
    }
    return readAscii(bytes, what);
}

}  // namespace fm
