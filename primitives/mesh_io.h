// Reading triangle meshes from OBJ, PLY, OFF and STL files, and deciding whether a mesh is
// a closed, outward-oriented solid (with CGAL, kept to this one translation unit).
#pragma once

#include "mesh_data.h"
#include "mesh_file_check.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace lucent {

// A mesh file that cannot be read, or holds no usable triangles; the message names the
// reason (the caller adds the file name and scene location).
struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Reads, repairs, triangulates and orients the mesh in `path` (format by extension, any
// letter case). Normals and uvs come from OBJ vn/vt, PLY vertex properties (nx ny nz; s t,
// u v, texture_u texture_v or texture_s texture_t) and NOFF/CNOFF vertex normals, each
// kept only when every face corner has a usable one; PLY and OFF colours are ignored
// (MeshData keeps none), and STL has no per-vertex data. `repairs` tells what orientation
// fixed.
std::shared_ptr<MeshData> loadMeshFile(const std::string& path);

// The same from bytes already in memory (what loadMeshFile does after reading the file;
// the fuzz targets call it directly).
std::shared_ptr<MeshData> loadMeshBytes(std::string bytes, MeshFormat format);

// For meshes built in memory (inline <mesh>): repairs and orients the triangles where that
// is possible and sets `closed`. Throws MeshError if no usable triangle remains.
void finishMesh(MeshData& mesh);

}  // namespace lucent
