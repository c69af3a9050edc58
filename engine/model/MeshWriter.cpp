#include "model/MeshWriter.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>
#include <vector>

#include "core/Error.h"
#include "io/AtomicFile.h"

namespace fm {
namespace {

void put(std::vector<char>& out, const void* data, std::size_t size) {
    const char* p = static_cast<const char*>(data);
    out.insert(out.end(), p, p + size);
}

// Binary formats below are little-endian; refuse to write garbage on a big-endian host.
static_assert(std::endian::native == std::endian::little, "mesh writers assume little-endian");

std::vector<char> encodePly(const Mesh& mesh) {
    const bool normals = mesh.normals.size() == mesh.positions.size() && !mesh.normals.empty();
    std::string header =
        "ply\nformat binary_little_endian 1.0\ncomment fluoromatch marching cubes\n";
    header += "element vertex " + std::to_string(mesh.positions.size()) + "\n";
    header += "property float x\nproperty float y\nproperty float z\n";
    if (normals) header += "property float nx\nproperty float ny\nproperty float nz\n";
    header += "element face " + std::to_string(mesh.triangles.size()) + "\n";
    header += "property list uchar uint vertex_indices\nend_header\n";
    std::vector<char> out(header.begin(), header.end());
    out.reserve(out.size() + mesh.positions.size() * 24 + mesh.triangles.size() * 13);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        put(out, &mesh.positions[v], 12);
        if (normals) put(out, &mesh.normals[v], 12);
    }
    for (const auto& t : mesh.triangles) {
        const unsigned char three = 3;
        put(out, &three, 1);
        put(out, &t, 12);
    }
    return out;
}

std::vector<char> encodeStl(const Mesh& mesh) {
    std::vector<char> out(80, 0);
    const char title[] = "fluoromatch marching cubes";
    std::memcpy(out.data(), title, sizeof(title) - 1);
    const std::uint32_t count = static_cast<std::uint32_t>(mesh.triangles.size());
    put(out, &count, 4);
    out.reserve(out.size() + mesh.triangles.size() * 50);
    for (const auto& t : mesh.triangles) {
        const glm::vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
        glm::vec3 n = glm::cross(b - a, c - a);
        const float len = glm::length(n);
        n = len > 0.0f ? n / len : glm::vec3(0.0f);
        put(out, &n, 12);
        put(out, &a, 12);
        put(out, &b, 12);
        put(out, &c, 12);
        const std::uint16_t attribute = 0;
        put(out, &attribute, 2);
    }
    return out;
}

std::vector<char> encodeObj(const Mesh& mesh) {
    const bool normals = mesh.normals.size() == mesh.positions.size() && !mesh.normals.empty();
    std::string s = "# fluoromatch marching cubes\n";
    char line[128];
    for (const auto& p : mesh.positions) {
        std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
        s += line;
    }
    if (normals)
        for (const auto& n : mesh.normals) {
            std::snprintf(line, sizeof line, "vn %.9g %.9g %.9g\n", n.x, n.y, n.z);
            s += line;
        }
    for (const auto& t : mesh.triangles) {
        if (normals)
            std::snprintf(line, sizeof line, "f %u//%u %u//%u %u//%u\n", t.x + 1, t.x + 1, t.y + 1,
                          t.y + 1, t.z + 1, t.z + 1);
        else
            std::snprintf(line, sizeof line, "f %u %u %u\n", t.x + 1, t.y + 1, t.z + 1);
        s += line;
    }
    return std::vector<char>(s.begin(), s.end());
}

std::string lowerExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

}  // namespace

void checkMeshPath(const std::filesystem::path& path) {
    const std::string ext = lowerExtension(path);
    if (ext != ".ply" && ext != ".stl" && ext != ".obj")
        throw Error("writing mesh '" + path.string() +
                    "': unknown extension (use .ply, .stl or .obj)");
}

void writeMesh(const Mesh& mesh, const std::filesystem::path& path) {
    checkMeshPath(path);
    const std::string ext = lowerExtension(path);
    for (const auto& t : mesh.triangles)
        if (t.x >= mesh.positions.size() || t.y >= mesh.positions.size() ||
            t.z >= mesh.positions.size())
            throw Error("writing mesh '" + path.string() + "': triangle index out of range");
    std::vector<char> bytes;
    if (ext == ".ply")
        bytes = encodePly(mesh);
    else if (ext == ".stl")
        bytes = encodeStl(mesh);
    else
        bytes = encodeObj(mesh);

    io::writeFileAtomically(path, bytes.data(), bytes.size());
}

}  // namespace fm
