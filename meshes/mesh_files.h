// Reading triangle meshes from OBJ, PLY, OFF and STL files (mesh_files.cpp), then repaired
// and oriented as mesh_repair.h says.
#pragma once

#include "mesh_error.h"
#include "mesh_file_check.h"

#include "primitives/mesh_data.h"

#include <memory>
#include <string>

namespace lucent {

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

}  // namespace lucent
