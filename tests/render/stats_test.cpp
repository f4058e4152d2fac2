// --stats' intersection-test counts: one test per object a ray is tested
// against, by kind, and the triangles tested inside meshes; the same counts whatever the
// thread count.
#include "scene_builder.h"

#include "../primitives/test_meshes.h"
#include "render/renderer.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

TEST_CASE("stats: a plane seen from above is tested once by every primary and shadow ray",
          "[render][stats]") {
  Scene scene;
  scene.render.width = 24;
  scene.render.height = 16;
  scene.cameras.push_back(lookingFrom(Vec3(0, 5, 0.01), Vec3(0), 40.0));
  Material m;
  m.diffuse = Color(0.8f);
  addShape(scene, PlaneSpec{Vec3(0, 1, 0), 0.0}, addMaterial(scene, m));
  scene.lights.push_back(pointLight(Vec3(0, 10, 0)));
  World world(scene);
  RenderResult r = Renderer(world, scene.cameras[0]).render();
  const uint64_t pixels = 24 * 16;
  REQUIRE(r.stats.primary == pixels);
  REQUIRE(r.stats.shadow == pixels);  // every hit is lit from above
  CHECK(r.stats.tests[TestKind::Plane] == 2 * pixels);
  for (int k = 0; k < kTestKinds; ++k)
    if (static_cast<TestKind>(k) != TestKind::Plane) CHECK(r.stats.tests.n[size_t(k)] == 0);
}

TEST_CASE("stats: spheres and meshes are counted by kind, alike with 1 and 2 threads",
          "[render][stats]") {
  Scene scene;
  scene.render.width = 40;
  scene.render.height = 30;
  scene.cameras.push_back(lookingFrom(Vec3(0, 1, 6), Vec3(0), 50.0));
  Material m;
  m.diffuse = Color(0.7f);
  const uint32_t mat = addMaterial(scene, m);
  addShape(scene, SphereSpec{Vec3(-1.2, 0, 0), 1.0}, mat);
  MeshSpec mesh;
  mesh.data = boxMesh(Vec3(0.3, -1, -1), Vec3(2.3, 1, 1));
  addShape(scene, mesh, mat);
  scene.lights.push_back(pointLight(Vec3(3, 6, 5)));
  World world(scene);
  Renderer renderer(world, scene.cameras[0]);
  RenderControl one, two;
  one.threads = 1;
  two.threads = 2;
  RenderResult a = renderer.render(one), b = renderer.render(two);
  CHECK(a.stats.tests.n == b.stats.tests.n);
  const TestCounts& t = a.stats.tests;
  // Each object is tested at most once per search of the world, and the box's 12
  // triangles are searched through its BVH: fewer than 12 a mesh test on average.
  CHECK(t[TestKind::Sphere] > 0);
  CHECK(t[TestKind::Sphere] <= a.stats.queries);
  CHECK(t[TestKind::Mesh] > 0);
  CHECK(t[TestKind::Mesh] <= a.stats.queries);
  CHECK(t[TestKind::MeshTriangle] >= t[TestKind::Mesh] / 2);
  CHECK(t[TestKind::MeshTriangle] < 12 * t[TestKind::Mesh]);
  CHECK(t[TestKind::Plane] == 0);
  CHECK(t[TestKind::Box] == 0);
}
