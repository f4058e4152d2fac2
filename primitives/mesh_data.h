// Triangle mesh data as loaded from a file or written inline: shared by every instance.
#pragma once

#include "math.h"

#include <array>
#include <cstdint>
#include <vector>

namespace lucent {

struct MeshData {
  std::vector<Vec3> positions;
  std::vector<std::array<uint32_t, 3>> triangles;  // indices into positions
  std::vector<Vec3> normals;  // empty, or one unit normal per position
  std::vector<Vec2> uvs;      // empty, or one per position
  // Closed (every edge shared by exactly two triangles) and consistently oriented with
  // outward normals (counter-clockwise seen from outside): then the mesh is a solid.
  // Edges are counted between coincident positions: a position is repeated where its
  // corners have different normals or uvs (a seam), so indices alone may not pair up.
  bool closed = false;
};

}  // namespace lucent
