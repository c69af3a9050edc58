#pragma once
// Writing a mesh to disk, format from the extension: .ply (binary little-endian, with
// normals), .stl (binary, facet normals from the winding), .obj (text, with normals).
// Written through io/AtomicFile: checked, atomic, never over a special file.
#include <filesystem>

#include "mesh/Mesh.h"

namespace fm {

// Throws fm::Error naming the file for an unknown extension or a write failure.
void writeMesh(const Mesh& mesh, const std::filesystem::path& path);

// Throws the same fm::Error as writeMesh for an unknown extension (check before working).
void checkMeshPath(const std::filesystem::path& path);

}  // namespace fm
