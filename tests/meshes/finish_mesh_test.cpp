// finishMesh: inline meshes go through the same repair and orientation as files.
#include "mesh_test_support.h"

#include "meshes/mesh_repair.h"

using namespace lucent;
using namespace lucent::meshtest;

namespace {

const Vec3 kCube[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                       {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const uint32_t kQuads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                               {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
const Vec3 kFaceNormal[6] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}};

// The unit cube as 8 positions and 12 triangles, outward unless `insideOut`.
MeshData cube(bool insideOut = false) {
  MeshData m;
  m.positions.assign(std::begin(kCube), std::end(kCube));
  for (const auto& q : kQuads) {
    std::array<uint32_t, 3> a{q[0], q[1], q[2]}, b{q[0], q[2], q[3]};
    if (insideOut) std::swap(a[1], a[2]), std::swap(b[1], b[2]);
    m.triangles.push_back(a);
    m.triangles.push_back(b);
  }
  return m;
}

}  // namespace

TEST_CASE("an inline cube is closed and outward", "[mesh]") {
  MeshData m = cube();
  finishMesh(m);
  requireWellFormed(m);
  CHECK(m.closed);
  CHECK(m.positions.size() == 8);
  CHECK(m.triangles.size() == 12);
  CHECK(signedVolume(m) == Approx(1.0).margin(1e-12));
}

TEST_CASE("an inline cube given inside-out is turned outward", "[mesh]") {
  MeshData m = cube(true);
  REQUIRE(signedVolume(m) == Approx(-1.0));
  finishMesh(m);
  requireWellFormed(m);
  CHECK(m.closed);
  CHECK(signedVolume(m) == Approx(1.0).margin(1e-12));
}

TEST_CASE("a single inline triangle is an open surface", "[mesh]") {
  MeshData m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}};
  finishMesh(m);
  requireWellFormed(m);
  CHECK_FALSE(m.closed);
  REQUIRE(m.triangles.size() == 1);
  const auto& t = m.triangles[0];  // winding kept: normal +z
  CHECK(glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]).z >
        0);
}

TEST_CASE("degenerate inline triangles are dropped", "[mesh]") {
  MeshData m = cube();
  m.positions.push_back({0.5, 0, 0});  // on the edge from corner 0 to corner 1
  m.triangles.push_back({0, 1, 8});    // zero area
  m.triangles.push_back({2, 2, 3});    // repeated index
  finishMesh(m);
  requireWellFormed(m);
  CHECK(m.triangles.size() == 12);
  CHECK(m.positions.size() == 8);
  CHECK(m.closed);
  CHECK(signedVolume(m) == Approx(1.0).margin(1e-12));
}

TEST_CASE("an inline mesh with no usable triangle is refused", "[mesh]") {
  MeshData collinear;
  collinear.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  collinear.triangles = {{0, 1, 2}};
  CHECK_THROWS_MATCHES(
      finishMesh(collinear), MeshError,
      Catch::Message("no usable triangle: all 1 faces are degenerate (zero area)"));

  MeshData repeated;
  repeated.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  repeated.triangles = {{0, 0, 1}, {2, 2, 2}};
  CHECK_THROWS_MATCHES(
      finishMesh(repeated), MeshError,
      Catch::Message("no usable face: none of the 2 faces has three distinct vertices"));

  MeshData empty;
  empty.positions = {{0, 0, 0}};
  CHECK_THROWS_MATCHES(finishMesh(empty), MeshError, Catch::Message("the mesh has no triangles"));
}

TEST_CASE("inline indices and coordinates are validated", "[mesh]") {
  MeshData outOfRange = cube();
  outOfRange.triangles[3] = {0, 1, 9};
  CHECK_THROWS_MATCHES(
      finishMesh(outOfRange), MeshError,
      Catch::Message("triangle 3 (counting from 0) uses position 9, but there are 8 positions"));

  MeshData notFinite = cube();
  notFinite.positions[5].y = std::nan("");
  CHECK_THROWS_MATCHES(finishMesh(notFinite), MeshError,
                       Catch::Message("position 5 (counting from 0) has a non-finite coordinate"));

  MeshData infinite = cube();
  infinite.positions[2].z = kInf;
  CHECK_THROWS_MATCHES(finishMesh(infinite), MeshError,
                       Catch::Message("position 2 (counting from 0) has a non-finite coordinate"));
}

TEST_CASE("inline normals and uvs must match the positions", "[mesh]") {
  MeshData fewNormals = cube();
  fewNormals.normals.assign(7, Vec3(0, 0, 1));
  CHECK_THROWS_MATCHES(finishMesh(fewNormals), MeshError,
                       Catch::Message("7 normals for 8 positions: give one normal per position"));

  MeshData zeroNormal = cube();
  zeroNormal.normals.assign(8, Vec3(0, 0, 1));
  zeroNormal.normals[4] = Vec3(0);
  CHECK_THROWS_MATCHES(finishMesh(zeroNormal), MeshError,
                       Catch::Message("normal 4 (counting from 0) is zero or not finite"));

  MeshData manyUVs = cube();
  manyUVs.uvs.assign(9, Vec2(0));
  CHECK_THROWS_MATCHES(finishMesh(manyUVs), MeshError,
                       Catch::Message("9 uvs for 8 positions: give one uv per position"));
}

TEST_CASE("inline per-face normals survive the merge that decides closedness", "[mesh]") {
  // 24 positions (4 per face, each with the face's normal, given with length 3): the cube
  // is closed only once coincident corners are merged, yet every corner keeps its normal.
  MeshData m;
  for (int f = 0; f < 6; ++f) {
    const uint32_t base = static_cast<uint32_t>(m.positions.size());
    for (uint32_t j = 0; j < 4; ++j) {
      m.positions.push_back(kCube[kQuads[f][j]]);
      m.normals.push_back(3.0 * kFaceNormal[f]);
      m.uvs.push_back(Vec2(j, f));
    }
    m.triangles.push_back({base, base + 1, base + 2});
    m.triangles.push_back({base, base + 2, base + 3});
  }
  finishMesh(m);
  requireWellFormed(m);
  CHECK(m.closed);
  CHECK(m.positions.size() == 24);
  CHECK(m.triangles.size() == 12);
  CHECK(signedVolume(m) == Approx(1.0).margin(1e-12));
  for (const auto& t : m.triangles) {
    const Vec3 ng = glm::normalize(
        glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]));
    for (uint32_t i : t) {
      CHECK(glm::length(m.normals[i] - ng) < 1e-12);
      const int face = static_cast<int>(m.uvs[i].y);  // uv.y carries the face number
      CHECK(glm::length(kFaceNormal[face] - ng) < 1e-12);
      CHECK(m.positions[i] == kCube[kQuads[face][static_cast<int>(m.uvs[i].x)]]);
    }
  }
}
