// Helpers shared by the mesh tests: test data paths, temporary files, and properties of a
// MeshData computed independently of CGAL (signed volume, closedness by edge pairing).
#pragma once

#include "../support/paths.h"
#include "../temp_dir.h"
#include "primitives/mesh_data.h"

#include <catch2/catch.hpp>

#include <unistd.h>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <tuple>

namespace lucent::meshtest {

inline std::string dataFile(const std::string& name) {
  return std::string(lucentSourceDir()) + "/tests/data/meshes/" + name;
}

// Divergence theorem: the sum of signed tetrahedron volumes (origin, a, b, c). Positive for a
// closed mesh whose triangles are counter-clockwise seen from outside.
inline double signedVolume(const MeshData& m) {
  double v = 0;
  for (const auto& t : m.triangles)
    v += glm::dot(m.positions[t[0]], glm::cross(m.positions[t[1]], m.positions[t[2]])) / 6.0;
  return v;
}

// Closed and consistently oriented as MeshData defines it: every edge (by index) is used
// once in each direction, i.e. by exactly two triangles that traverse it oppositely.
inline bool edgesPairUpByIndex(const MeshData& m) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  for (const auto& [edge, count] : directed) {
    auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1) return false;
  }
  return true;
}

// The same judged by coordinates, for meshes whose positions repeat at normal or uv seams:
// each geometric edge is traversed as often in one direction as in the other.
inline bool edgesBalanceByPosition(const MeshData& m) {
  using Key = std::tuple<double, double, double>;
  auto key = [&](uint32_t i) { return Key(m.positions[i].x, m.positions[i].y, m.positions[i].z); };
  std::map<std::pair<Key, Key>, int> directed;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{key(t[k]), key(t[(k + 1) % 3])}];
  for (const auto& [edge, count] : directed) {
    auto reverse = directed.find({edge.second, edge.first});
    if (reverse == directed.end() || reverse->second != count) return false;
  }
  return true;
}

// What every successfully built mesh must satisfy.
inline void requireWellFormed(const MeshData& m) {
  REQUIRE(!m.triangles.empty());
  for (const Vec3& p : m.positions) REQUIRE(isFinite(p));
  for (const auto& t : m.triangles)
    for (uint32_t i : t) REQUIRE(i < m.positions.size());
  REQUIRE((m.normals.empty() || m.normals.size() == m.positions.size()));
  REQUIRE((m.uvs.empty() || m.uvs.size() == m.positions.size()));
  for (const Vec3& n : m.normals) REQUIRE(std::abs(glm::length(n) - 1.0) < 1e-12);
  if (m.closed && m.normals.empty() && m.uvs.empty()) REQUIRE(edgesPairUpByIndex(m));
  if (m.closed) REQUIRE(edgesBalanceByPosition(m));
}

using lucent::test::TempDir;

}  // namespace lucent::meshtest
