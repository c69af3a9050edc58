#pragma once
// Reading triangle meshes of bone and implant models: STL (ASCII and binary), PLY (ASCII,
// binary little and big endian; vertex and face elements, other elements skipped) and OBJ
// (v and f; polygons fanned into triangles; negative indices count back from the last vertex).
// The result is the file's mesh as stored: STL gives three new vertices per facet (weld them,
// model/WeldVertices.h); normals are not read (the winding is what counts).
//
// Bad input throws fm::Error naming the file and the field: truncated or oversized files,
// counts that disagree with the file size (checked before anything is allocated), non-finite
// coordinates, indices out of range, faces with fewer than three vertices.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "mesh/Mesh.h"

namespace fm {

// More triangles or vertices than this in one model is a broken file, not an implant.
inline constexpr std::size_t kMaxModelElements = 100'000'000;

// Format from the extension (.stl, .ply, .obj, any case).
Mesh readMeshFile(const std::filesystem::path& path);

// The same on bytes in memory; `what` names the source in messages.
Mesh readStlBytes(const std::vector<std::uint8_t>& bytes, const std::string& what);
Mesh readPlyBytes(const std::vector<std::uint8_t>& bytes, const std::string& what);
Mesh readObjBytes(const std::vector<std::uint8_t>& bytes, const std::string& what);

}  // namespace fm
