// Triangle mesh data as loaded from a file or written inline: shared by every instance.
#pragma once

#include "math.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lucent {

struct MeshData {
  std::vector<Vec3> positions;
  std::vector<std::array<uint32_t, 3>> triangles;  // indices into positions
  std::vector<Vec3> normals;                       // empty, or one unit normal per position
  std::vector<Vec2> uvs;                           // empty, or one per position
  // Closed (every edge shared by exactly two triangles) and consistently oriented with
  // outward normals (counter-clockwise seen from outside): then the mesh is a solid.
  // Edges are counted between coincident positions: a position is repeated where its
  // corners have different normals or uvs (a seam), so indices alone may not pair up.
  bool closed = false;

  // What loading repaired that the file or the inline lists got wrong, for a warning
  // (scenegraph/shapes/mesh.cpp). Faces counted as read, after duplicates and faces without
  // three distinct corners were dropped.
  struct Repairs {
    std::size_t faces = 0;         // faces read
    std::size_t flippedFaces = 0;  // turned over to agree with their neighbours
    bool onlyTriangles = true;     // every face read was a triangle
  };
  Repairs repairs;
};

}  // namespace lucent
