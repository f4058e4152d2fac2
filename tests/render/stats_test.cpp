// --stats' intersection-test counts: one test per object a ray is tested
// against, by kind, and the triangles tested inside meshes; the same counts whatever the
// thread count.
#include "scene_builder.h"
#include "scenegraph/shape_registry.h"

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
  CHECK(r.stats.tests[slotOf<PlaneSpec>()] == 2 * pixels);
  for (size_t k = 0; k < kTestSlots; ++k)
    if (k != slotOf<PlaneSpec>()) CHECK(r.stats.tests[k] == 0);
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
  CHECK(t[slotOf<SphereSpec>()] > 0);
  CHECK(t[slotOf<SphereSpec>()] <= a.stats.queries);
  CHECK(t[slotOf<MeshSpec>()] > 0);
  CHECK(t[slotOf<MeshSpec>()] <= a.stats.queries);
  CHECK(t[kMeshTriangleSlot] >= t[slotOf<MeshSpec>()] / 2);
  CHECK(t[kMeshTriangleSlot] < 12 * t[slotOf<MeshSpec>()]);
  CHECK(t[slotOf<PlaneSpec>()] == 0);
  CHECK(t[slotOf<BoxSpec>()] == 0);
}
