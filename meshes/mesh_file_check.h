// Guards in front of CGAL 5.5's mesh readers. Those readers trust what a file says: an OFF
// header's vertex count sizes a vector before a single vertex is read, a PLY list count sizes
// a buffer, an ASCII PLY vertex whose x is declared `int` dereferences a null pointer, and an
// out-of-range OBJ index is stored as is. So every file is walked here first, without
// building anything, and refused with a reason (and a line number where one helps) unless
// CGAL can read it safely. CGAL then reads the very same bytes (no second open of the file),
// in a few cases adjusted so that its reader takes the right path (checkStlBytes, scanObj).
#pragma once

#include "primitives/math.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lucent {

enum class MeshFormat { Obj, Ply, Off, Stl };

// Limits that keep a hostile or broken file from exhausting memory. A mesh at the limits
// costs a few GB inside CGAL (soup, then halfedge mesh); real scenes stay far below them.
constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t{1} << 30;  // 1 GiB
constexpr std::size_t kMaxMeshVertices = std::size_t{1} << 24;         // 16,777,216
constexpr std::size_t kMaxMeshFaces = std::size_t{1} << 24;
constexpr std::size_t kMaxFaceVertices = std::size_t{1} << 16;  // corners of one polygon

// "obj", "ply", "off", "stl" in any letter case; anything else is a MeshError.
MeshFormat meshFormatOf(const std::string& path);
const char* meshFormatName(MeshFormat format);  // "OBJ", "PLY", ...

// The whole file, or a MeshError: missing, not a regular file, unreadable, empty, too large.
std::string readMeshFile(const std::string& path);

// What a checked file holds, for sizing the reader's containers before it reads.
struct MeshCounts {
  std::size_t vertices = 0, faces = 0;
};

// Per-vertex attributes a file declares, in the file's vertex order (CGAL's readers drop
// them). Each list is empty or holds one entry per vertex of the file, as written (not
// normalised, possibly zero or not finite: mesh_files.cpp decides what is usable).
struct VertexAttributes {
  std::vector<Vec3> normals;
  std::vector<Vec2> uvs;
};

// Structural checks, one per format; each throws MeshError naming the first problem. With
// `attributes`, the walk also keeps what the vertices carry besides positions:
// OFF: normals of NOFF and CNOFF (colours of COFF are checked and ignored);
// PLY: normals from nx ny nz, texture coordinates from s t, u v, texture_u texture_v or
// texture_s texture_t (each pair only when both are scalars of the vertex element);
// colours are checked and ignored.
void checkOffBytes(std::string_view bytes,
                   VertexAttributes* attributes = nullptr);  // ASCII OFF, COFF, NOFF, CNOFF
MeshCounts checkPlyBytes(std::string_view bytes,
                         VertexAttributes* attributes = nullptr);  // ASCII and binary PLY
// ASCII and binary STL; settles the layout for CGAL's reader, editing the buffer if needed.
void checkStlBytes(std::string& bytes);
// OBJ is walked by scanObj (obj_scan.h), which also collects normals and texture coordinates.

}  // namespace lucent
