// Small closed and open meshes built in code, for the mesh tests.
#pragma once

#include "primitives/mesh_data.h"

#include <memory>

namespace lucent::test {

// The box [lo, hi] as 12 triangles, counter-clockwise seen from outside, closed.
inline std::shared_ptr<MeshData> boxMesh(const Vec3& lo, const Vec3& hi) {
  auto m = std::make_shared<MeshData>();
  for (int i = 0; i < 8; ++i)
    m->positions.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
  // Each face as a quad (a, b, c, d) counter-clockwise from outside.
  const uint32_t quads[6][4] = {
      {0, 4, 6, 2},  // -x
      {1, 3, 7, 5},  // +x
      {0, 1, 5, 4},  // -y
      {2, 6, 7, 3},  // +y
      {0, 2, 3, 1},  // -z
      {4, 5, 7, 6},  // +z
  };
  for (const auto& q : quads) {
    m->triangles.push_back({q[0], q[1], q[2]});
    m->triangles.push_back({q[0], q[2], q[3]});
  }
  m->closed = true;
  return m;
}

// A unit octahedron (vertices on the axes), closed and outward oriented, with unit vertex
// normals pointing along the axes and (u,v) = (x, y) per vertex.
inline std::shared_ptr<MeshData> octahedronMesh() {
  auto m = std::make_shared<MeshData>();
  m->positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m->normals = m->positions;
  for (const Vec3& p : m->positions) m->uvs.push_back({p.x, p.y});
  // Faces (x, y, z) with signs; counter-clockwise from outside.
  m->triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                  {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  m->closed = true;
  return m;
}

// A square [0,1]² in the plane z = 0 as two triangles sharing the diagonal (0,0)-(1,1):
// an open surface.
inline std::shared_ptr<MeshData> squareMesh() {
  auto m = std::make_shared<MeshData>();
  m->positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m->triangles = {{0, 1, 2}, {0, 2, 3}};
  m->closed = false;
  return m;
}

}  // namespace lucent::test
