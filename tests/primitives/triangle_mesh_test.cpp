#include "shape_checks.h"
#include "test_meshes.h"

#include "primitives/box.h"
#include "primitives/triangle_mesh.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("mesh: a closed box mesh crosses rays exactly where the box does", "[primitives][mesh]") {
  Vec3 lo(-1, -0.5, 0), hi(1, 2, 3);
  TriangleMesh mesh(boxMesh(lo, hi), false);
  Box box(lo, hi);
  CHECK(mesh.isSolid());
  CHECK(mesh.triangleCount() == 12);
  Rng rng(13);
  int compared = 0;
  for (int i = 0; i < 5000; ++i) {
    Ray ray = randomRayAt(rng, box.bounds());
    if (i % 3 == 0) ray.tmin = uniform(rng, 0.0, 1.0);
    CrossingList a, b;
    mesh.crossings(ray, a);
    box.crossings(ray, b);
    INFO("ray " << i);
    REQUIRE(a.startsInside == b.startsInside);
    REQUIRE(a.items.size() == b.items.size());
    for (size_t k = 0; k < a.items.size(); ++k) {
      REQUIRE(a.items[k].entering == b.items[k].entering);
      REQUIRE_THAT(a.items[k].hit.t, WithinRel(b.items[k].hit.t, 1e-12));
    }
    compared += int(a.items.size());
  }
  CHECK(compared > 3000);
}

TEST_CASE("mesh: rays through the diagonals, edges and corners of a box mesh",
          "[primitives][mesh]") {
  TriangleMesh mesh(boxMesh(Vec3(-1.0), Vec3(1.0)), false);
  // Through the face diagonal shared by two triangles, through a face, through two
  // corners along the box's diagonal: one entering and one leaving crossing each, where
  // intersect() finds the entering one.
  const Ray through[] = {Ray(Vec3(0, 0, 5), Vec3(0, 0, -1)),
                         Ray(Vec3(0.25, 0.25, 5), Vec3(0, 0, -1)), Ray(Vec3(3.0), Vec3(-1.0))};
  for (const Ray& ray : through) {
    CrossingList cl;
    mesh.crossings(ray, cl);
    INFO(ray.o.x << " " << ray.o.y << " " << ray.o.z);
    REQUIRE(cl.items.size() == 2);
    CHECK(cl.items[0].entering);
    CHECK_FALSE(cl.items[1].entering);
    Hit h;
    REQUIRE(mesh.intersect(ray, h));
    CHECK(h.t == cl.items[0].hit.t);
  }
  // Along an edge, or lying in a face: the ray only touches the solid. The watertight
  // test decides such rays as if moved by an infinitesimal amount (watertight.cpp), so
  // they either miss or enter and leave, and intersect() agrees with crossings().
  const Ray touching[] = {
      Ray(Vec3(1, 1, 5), Vec3(0, 0, -1)),   Ray(Vec3(1, 0.5, 5), Vec3(0, 0, -1)),
      Ray(Vec3(-1, -1, 5), Vec3(0, 0, -1)), Ray(Vec3(-1, 0.5, 5), Vec3(0, 0, -1)),
      Ray(Vec3(5, 1, 1), Vec3(-1, 0, 0)),   Ray(Vec3(5, -1, -1), Vec3(-1, 0, 0))};
  for (const Ray& ray : touching) {
    CrossingList cl;
    mesh.crossings(ray, cl);
    INFO(ray.o.x << " " << ray.o.y << " " << ray.o.z);
    CHECK_FALSE(cl.startsInside);
    Hit h;
    bool hit = mesh.intersect(ray, h);
    if (cl.items.empty()) {
      CHECK_FALSE(hit);
    } else {
      REQUIRE(cl.items.size() == 2);
      CHECK(cl.items[0].entering);
      CHECK_FALSE(cl.items[1].entering);
      REQUIRE(hit);
      CHECK(h.t == cl.items[0].hit.t);
    }
  }
}

TEST_CASE("mesh: inside() is parity against the analytic solid", "[primitives][mesh]") {
  TriangleMesh cube(boxMesh(Vec3(-1.0), Vec3(1.0)), false);
  TriangleMesh octa(octahedronMesh(), false);
  Rng rng(14);
  for (int i = 0; i < 5000; ++i) {
    Vec3 p = randomInBox(rng, Vec3(-1.5), Vec3(1.5));
    double l1 = std::abs(p.x) + std::abs(p.y) + std::abs(p.z);
    double linf = maxComponent(glm::abs(p));
    if (std::abs(l1 - 1.0) > 1e-9) REQUIRE(octa.inside(p) == (l1 < 1.0));
    if (std::abs(linf - 1.0) > 1e-9) REQUIRE(cube.inside(p) == (linf < 1.0));
  }
  // An open mesh has no inside.
  TriangleMesh square(squareMesh(), false);
  CHECK_FALSE(square.isSolid());
  CHECK_FALSE(square.inside(Vec3(0.5, 0.5, 0)));
}

TEST_CASE("mesh: smooth normals and (u,v) are interpolated", "[primitives][mesh]") {
  auto data = octahedronMesh();
  TriangleMesh smooth(data, true), flat(data, false);
  // The face (+x, +y, +z) at its centre: the interpolated normal is (1,1,1)/√3 both ways;
  // off-centre the smooth one leans towards the nearest corner.
  Vec3 target(0.5, 0.25, 0.25);  // barycentrics (0.5, 0.25, 0.25)
  Ray ray(target + Vec3(1.0), -Vec3(1.0));
  Hit h;
  REQUIRE(smooth.intersect(ray, h));
  SurfaceInfo s = smooth.surface(ray, h);
  Vec3 expect = glm::normalize(0.5 * Vec3(1, 0, 0) + 0.25 * Vec3(0, 1, 0) + 0.25 * Vec3(0, 0, 1));
  CHECK_THAT(s.ns.x, WithinAbs(expect.x, 1e-14));
  CHECK_THAT(s.ns.y, WithinAbs(expect.y, 1e-14));
  CHECK_THAT(s.ng.x, WithinAbs(1.0 / std::sqrt(3.0), 1e-14));
  CHECK(s.hasUV);
  CHECK_THAT(s.uv.x, WithinAbs(0.5, 1e-14));   // u = x
  CHECK_THAT(s.uv.y, WithinAbs(0.25, 1e-14));  // v = y
  REQUIRE(flat.intersect(ray, h));
  SurfaceInfo f = flat.surface(ray, h);
  CHECK_THAT(f.ns.x, WithinAbs(1.0 / std::sqrt(3.0), 1e-14));
}

TEST_CASE("mesh: computed vertex normals are area weighted", "[primitives][mesh]") {
  // Two triangles meeting at vertex 0: a large one in z = 0 and a small one in x = 0.
  MeshData m;
  m.positions = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 1}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 3, 4}};
  std::vector<Vec3> n = computeVertexNormals(m);
  // Areas 8 and 0.5 along +z and -x... (0,0,1)·16 + (−1,0,0)·1, normalised.
  Vec3 expect = glm::normalize(Vec3(-1, 0, 16));
  CHECK_THAT(n[0].x, WithinAbs(expect.x, 1e-15));
  CHECK_THAT(n[0].z, WithinAbs(expect.z, 1e-15));
  CHECK(n[1] == Vec3(0, 0, 1));
}

TEST_CASE("mesh: an open mesh lists every hit as entering", "[primitives][mesh]") {
  TriangleMesh square(squareMesh(), false);
  CrossingList cl;
  square.crossings(Ray(Vec3(0.5, 0.5, 1), Vec3(0, 0, -1)), cl);  // through the shared diagonal
  CHECK_FALSE(cl.startsInside);
  REQUIRE(cl.items.size() >= 1);
  for (const Crossing& c : cl.items) {
    CHECK(c.entering);
    CHECK(c.hit.t == 1.0);
  }
  Hit h;
  REQUIRE(square.intersect(Ray(Vec3(0.5, 0.5, 1), Vec3(0, 0, -1)), h));
  CHECK(h.t == 1.0);
}

TEST_CASE("mesh: zero-area triangles are never hit and never give NaN", "[primitives][mesh]") {
  // A closed box mesh plus slivers: a collinear triangle across the top face and one whose
  // corners coincide. They change nothing: same crossings as the plain box.
  auto data = boxMesh(Vec3(-1.0), Vec3(1.0));
  data->positions.push_back({0, 1, 0});  // 8: on the edge-free middle of the top face
  data->triangles.push_back({2, 8, 7});  // (-1,1,-1), (0,1,0), (1,1,1): collinear
  data->triangles.push_back({8, 8, 8});
  TriangleMesh mesh(data, false);
  Box box(Vec3(-1.0), Vec3(1.0));
  CHECK(mesh.triangleCount() == 14);
  Rng rng(24);
  for (int i = 0; i < 3000; ++i) {
    Ray ray = randomRayAt(rng, box.bounds());
    if (i % 3 == 0) ray = Ray(Vec3(uniform(rng, -1, 1), 3, uniform(rng, -1, 1)), Vec3(0, -1, 0));
    Hit h;
    bool hit = mesh.intersect(ray, h);
    REQUIRE(hit == box.occluded(ray));
    if (hit) {
      REQUIRE(h.part < 12);
      SurfaceInfo si = mesh.surface(ray, h);
      REQUIRE(isFinite(si.p));
      REQUIRE(isFinite(si.ng));
    }
  }
  // Straight down through the sliver's line.
  Hit h;
  REQUIRE(mesh.intersect(Ray(Vec3(0.5, 3, 0.5), Vec3(0, -1, 0)), h));
  CHECK(h.part < 12);
  CHECK(h.t == 2.0);
}
