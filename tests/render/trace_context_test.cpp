// TraceContext, what a thread carries through the tracer: a tile counts from zero with an
// empty shadow cache, and the context's total sums its tiles.
#include "scene_builder.h"

#include "render/trace_context.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

TEST_CASE("TraceContext: tiles count from zero with an empty shadow cache, the total sums them",
          "[render][shadow][cache]") {
  // A floor and a disc over it that shades the floor's origin from a point light.
  Scene scene;
  Material white;
  white.diffuse = Color(1.0f);
  addShape(scene, PlaneSpec{Vec3(0, 1, 0), 0.0}, addMaterial(scene, white));
  addShape(scene, DiscSpec{Vec3(0, 3, 0), Vec3(0, 1, 0), 1.5, 0.0}, addMaterial(scene, white));
  scene.lights.push_back(pointLight(Vec3(0, 10, 0)));
  World world(scene);
  Tracer tracer(world);
  // Down onto the floor beside the disc's rim: the disc blocks the light there.
  const Ray down(Vec3(2.0, 5, 0), Vec3(-0.1, -1, 0));  // meets the floor at x = 1.5
  auto trace = [&](TraceContext& context) {
    PathSeed seed;
    return tracer.traceCamera(down, MediaStack(), seed, context);
  };

  TraceContext context;
  context.startTile();
  CHECK(trace(context) == Color(0.0f));  // the disc's shadow
  CHECK(trace(context) == Color(0.0f));
  const RayStats first = context.finishTile();
  CHECK(first.primary == 2);
  CHECK(first.shadow == 2);
  CHECK(first.shadowCacheHits == 1);  // the second shadow ray asks the disc first
  // Each primary ray tests the floor and the disc; the first shadow ray both, the second
  // the cached disc alone.
  CHECK(first.tests[slotOf<PlaneSpec>()] == 3);
  CHECK(first.tests[slotOf<DiscSpec>()] == 4);

  context.startTile();
  CHECK(context.stats.primary == 0);
  CHECK(trace(context) == Color(0.0f));
  const RayStats second = context.finishTile();
  CHECK(second.primary == 1);
  CHECK(second.shadowCacheHits == 0);  // a new tile: the cache was emptied
  CHECK(second.tests[slotOf<PlaneSpec>()] == 2);

  CHECK(context.total().primary == 3);
  CHECK(context.total().shadow == 3);
  CHECK(context.total().shadowCacheHits == 1);
  TestCounts both = first.tests;
  both += second.tests;
  CHECK(context.total().tests.n == both.n);
}
