// The fast path of mesh loading (meshes/clean_mesh.h): it must take exactly the clean
// closed soups and hand everything else back to CGAL.
#include "meshes/clean_mesh.h"
#include "../primitives/test_meshes.h"
#include "meshes/mesh_repair.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lucent;
using lucent::test::boxMesh;

namespace {

using Triangles = std::vector<std::array<uint32_t, 3>>;

double signedVolume(const MeshData& m) {
  double v = 0.0;
  for (const auto& t : m.triangles)
    v += glm::dot(m.positions[t[0]], glm::cross(m.positions[t[1]], m.positions[t[2]]));
  return v / 6.0;
}

}  // namespace

TEST_CASE("clean mesh: a closed outward box is kept as it is", "[primitives][mesh]") {
  auto box = boxMesh(Vec3(-1.0), Vec3(2.0, 1.0, 1.0));
  auto out = cleanClosedMesh(box->positions, box->triangles);
  REQUIRE(out);
  CHECK(out->closed);
  CHECK(out->triangles.size() == 12);
  CHECK(out->positions.size() == 8);
  CHECK(signedVolume(*out) == Approx(12.0));
  // Positions are numbered in the order the triangles first use them.
  CHECK(out->triangles[0] == std::array<uint32_t, 3>{0, 1, 2});
  CHECK(out->positions[1] == box->positions[4]);
}

TEST_CASE("clean mesh: an inward box is turned outward", "[primitives][mesh]") {
  auto box = boxMesh(Vec3(-1.0), Vec3(1.0));
  Triangles inward = box->triangles;
  for (auto& t : inward) std::swap(t[1], t[2]);
  auto out = cleanClosedMesh(box->positions, inward);
  REQUIRE(out);
  CHECK(signedVolume(*out) == Approx(8.0));
}

TEST_CASE("clean mesh: coincident points are merged into one vertex", "[primitives][mesh]") {
  // Every triangle with its own three points (an STL file's layout).
  auto box = boxMesh(Vec3(0.0), Vec3(1.0));
  std::vector<Vec3> points;
  Triangles soup;
  for (const auto& t : box->triangles) {
    uint32_t first = uint32_t(points.size());
    for (uint32_t v : t) points.push_back(box->positions[v]);
    soup.push_back({first, first + 1, first + 2});
  }
  auto out = cleanClosedMesh(points, soup);
  REQUIRE(out);
  CHECK(out->positions.size() == 8);
  CHECK(signedVolume(*out) == Approx(1.0));
}

TEST_CASE("clean mesh: what needs CGAL is handed back", "[primitives][mesh]") {
  auto box = boxMesh(Vec3(-1.0), Vec3(1.0));
  const auto& P = box->positions;
  SECTION("an open surface (one triangle missing)") {
    Triangles open(box->triangles.begin(), box->triangles.end() - 1);
    CHECK_FALSE(cleanClosedMesh(P, open));
  }
  SECTION("one triangle turned the wrong way") {
    Triangles t = box->triangles;
    std::swap(t[3][1], t[3][2]);
    CHECK_FALSE(cleanClosedMesh(P, t));
  }
  SECTION("a triangle used twice") {
    Triangles t = box->triangles;
    t.push_back(t[0]);
    CHECK_FALSE(cleanClosedMesh(P, t));
  }
  SECTION("two shells (their nesting decides their orientation)") {
    std::vector<Vec3> points = P;
    Triangles t = box->triangles;
    for (const Vec3& p : P) points.push_back(p * 0.5);
    for (auto tri : box->triangles) t.push_back({tri[0] + 8, tri[1] + 8, tri[2] + 8});
    CHECK_FALSE(cleanClosedMesh(points, t));
  }
  SECTION("two boxes touching at one corner (not manifold there)") {
    std::vector<Vec3> points = P;
    Triangles t = box->triangles;
    // The second box's corner 0 is the first box's corner 7 (1, 1, 1).
    for (int i = 0; i < 8; ++i) points.push_back(P[size_t(i)] + Vec3(2.0));
    for (auto tri : box->triangles) {
      std::array<uint32_t, 3> moved;
      for (int k = 0; k < 3; ++k) moved[size_t(k)] = tri[size_t(k)] == 0 ? 7 : tri[size_t(k)] + 8;
      t.push_back(moved);
    }
    CHECK_FALSE(cleanClosedMesh(points, t));
  }
  SECTION("a zero-area triangle in an otherwise clean closed surface") {
    // Triangle 0 is (0, 4, 6); M, the middle of edge 0-4, splits it in two, and the flat
    // triangle (0, 4, M) closes the seam: every edge still has its reverse.
    std::vector<Vec3> points = P;
    points.push_back((P[0] + P[4]) * 0.5);
    Triangles t = box->triangles;
    REQUIRE(t[0] == std::array<uint32_t, 3>{0, 4, 6});
    t[0] = {0, 8, 6};
    t.push_back({8, 4, 6});
    Triangles withoutFlat = t;
    t.push_back({0, 4, 8});
    CHECK_FALSE(cleanClosedMesh(points, t));
    CHECK_FALSE(cleanClosedMesh(points, withoutFlat));  // open along 0-4 without it
  }
}

TEST_CASE("clean mesh: finishMesh gives the same solid either way", "[primitives][mesh]") {
  // An inward closed box takes the fast path and comes out outward; the same box missing
  // a triangle goes through CGAL and comes out open.
  MeshData closed = *boxMesh(Vec3(-1.0), Vec3(1.0));
  for (auto& t : closed.triangles) std::swap(t[1], t[2]);  // all inward
  finishMesh(closed);
  CHECK(closed.closed);
  CHECK(signedVolume(closed) == Approx(8.0));

  MeshData open = *boxMesh(Vec3(-1.0), Vec3(1.0));
  open.triangles.pop_back();
  finishMesh(open);
  CHECK_FALSE(open.closed);
  CHECK(open.triangles.size() == 11);
}

TEST_CASE("clean mesh: vertices of very high valence", "[primitives][mesh]") {
  // A double cone over a 20000-gon: each apex is in 20000 triangles, so a check that looked
  // at each pair of a vertex's edges would take 4e8 steps per apex.
  const uint32_t N = 20000;
  const double pi = 3.14159265358979323846;
  std::vector<Vec3> points;
  for (uint32_t i = 0; i < N; ++i)
    points.emplace_back(std::cos(2 * pi * i / N), std::sin(2 * pi * i / N), 0.0);
  const uint32_t top = N, bottom = N + 1;
  points.emplace_back(0.0, 0.0, 1.0);
  points.emplace_back(0.0, 0.0, -1.0);
  Triangles t;
  for (uint32_t i = 0; i < N; ++i) {
    const uint32_t j = (i + 1) % N;
    t.push_back({top, i, j});  // counter-clockwise seen from above: outward
    t.push_back({bottom, j, i});
  }
  auto out = cleanClosedMesh(points, t);
  REQUIRE(out);
  CHECK(out->triangles.size() == 2 * N);
  CHECK(out->positions.size() == N + 2);
  // Two cones of height 1 over the polygon: 2/3 of its area.
  const double area = 0.5 * N * std::sin(2 * pi / N);
  CHECK(signedVolume(*out) == Approx(2.0 / 3.0 * area));

  // The same with one apex triangle turned: no longer consistently oriented.
  std::swap(t[2 * 777][1], t[2 * 777][2]);
  CHECK_FALSE(cleanClosedMesh(points, t));
}
