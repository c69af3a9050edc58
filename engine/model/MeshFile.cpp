#include "model/MeshFile.h"

#include <algorithm>
#include <cctype>

#include "core/Error.h"
#include "io/ByteSource.h"

namespace fm {

namespace {

// A mesh file above this size is refused before reading (the largest element counts fit well
// below it in every format).
constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t(4) << 30;

std::string lowerExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

}  // namespace

Mesh readMeshFile(const std::filesystem::path& path) {
    const std::string what = io::quoted(path);
    const std::string ext = lowerExtension(path);
    if (ext != ".stl" && ext != ".ply" && ext != ".obj")
        throw Error("reading model " + what + ": unknown extension (use .stl, .ply or .obj)");
    const std::uintmax_t size = io::fileSize(path);
    if (size > kMaxMeshFileBytes)
        throw Error("reading model " + what + ": file of " + std::to_string(size) +
                    " bytes is larger than the " + std::to_string(kMaxMeshFileBytes >> 30) +
                    " GiB a model may have");
    const io::Bytes bytes = io::readFileRange(path, 0, static_cast<std::size_t>(size));
    if (ext == ".stl") return readStlBytes(bytes, what);
    if (ext == ".ply") return readPlyBytes(bytes, what);
    return readObjBytes(bytes, what);
}

}  // namespace fm
