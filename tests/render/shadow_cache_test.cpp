// The shadow cache (render/shadow_cache.h) and the shadow rays of one point computed
// together (ShadowRays): faster answers, never different ones.
#include "scene_builder.h"
#include "scenegraph/shape_registry.h"

#include "render/renderer.h"
#include "render/spawn.h"

#include <catch2/catch.hpp>

#include <random>

using namespace lucent;
using namespace lucent::test;

namespace {

Material diffuse(float kd) {
  Material m;
  m.diffuse = Color(kd);
  return m;
}

// A floor and floating blockers lit by an area light, a point light and a directional
// light: shadows of every kind of light, soft and hard, all opaque. With
// `unusedGlass` the scene also holds a transmissive material that no object uses: the
// tracer then takes the shadow path for transparent scenes (the opaque objects asked
// first, then a walk through the objects that may transmit, of which there are none),
// and neither the image nor the cache's answers may change.
void blockersScene(Scene& scene, bool unusedGlass) {
  scene.render.width = 64;
  scene.render.height = 48;
  scene.cameras.push_back(lookingFrom(Vec3(0, 6, 9), Vec3(0, 0.5, 0), 50.0));
  const uint32_t floor = addMaterial(scene, diffuse(0.8f));
  const uint32_t blocker = addMaterial(scene, diffuse(0.6f));
  addShape(scene, PlaneSpec{Vec3(0, 1, 0), 0.0}, floor);
  addShape(scene, SphereSpec{Vec3(-1.5, 1.2, 0), 0.7}, blocker);
  addShape(scene, BoxSpec{Vec3(0.5, 0.0, -1.0), Vec3(1.7, 1.4, 0.2)}, blocker);
  addShape(scene, CylinderSpec{Vec3(2.5, 0, 1.5), Vec3(2.5, 0.8, 1.5), 0.4, false}, blocker);
  addShape(scene, SphereSpec{Vec3(0.3, 2.6, 1.0), 0.4}, blocker);
  Light area;
  area.type = LightType::Area;
  area.position = Vec3(-1, 6, 1);
  area.u = Vec3(2, 0, 0);
  area.v = Vec3(0, 0, 2);
  area.samplesU = 5;
  area.samplesV = 4;
  area.color = Color(0.7f);
  scene.lights.push_back(area);
  scene.lights.push_back(pointLight(Vec3(4, 5, 3), Color(0.3f)));
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(Vec3(-1, -2, -0.5));
  sun.color = Color(0.2f);
  scene.lights.push_back(sun);
  if (unusedGlass) {
    Material glass;
    glass.transmissive = Color(0.9f);
    glass.ior = 1.5;
    addMaterial(scene, glass);
  }
}

RenderResult renderBlockers(bool unusedGlass, int threads = 0) {
  Scene scene;
  blockersScene(scene, unusedGlass);
  World world(scene);
  RenderControl control;
  control.threads = threads;
  return Renderer(world, scene.cameras[0]).render(control);
}

}  // namespace

TEST_CASE("the shadow cache changes no pixel of an opaque scene", "[render][shadow][cache]") {
  const RenderResult cached = renderBlockers(false);
  const RenderResult walked = renderBlockers(true);
  REQUIRE(cached.stats.shadow == walked.stats.shadow);
  CHECK(walked.stats.shadowCacheHits == cached.stats.shadowCacheHits);
  // Many blocked rays are answered by the cached blocker: far fewer than the shadow rays.
  CHECK(cached.stats.shadowCacheHits > cached.stats.shadow / 20);
  CHECK(cached.stats.shadowCacheHits < cached.stats.shadow);
  int shadowed = 0;
  for (int y = 0; y < cached.image.height; ++y)
    for (int x = 0; x < cached.image.width; ++x) {
      REQUIRE(cached.image.at(x, y) == walked.image.at(x, y));
      if (cached.image.at(x, y).r < 0.05f) ++shadowed;
    }
  CHECK(shadowed > 0);
}

TEST_CASE("the shadow cache starts empty in every tile: counts alike on 1 and 2 threads",
          "[render][shadow][cache]") {
  const RenderResult one = renderBlockers(false, 1), two = renderBlockers(false, 2);
  CHECK(one.stats.shadowCacheHits == two.stats.shadowCacheHits);
  CHECK(one.stats.tests.n == two.stats.tests.n);
}

TEST_CASE("every blocked shadow ray but the first hits the cache when one object blocks",
          "[render][shadow][cache]") {
  // One 16x16 tile seen from straight above: the floor, and a disc floating over it whose
  // shadow from a point light falls partly in view. Nothing is ambient or emissive, so a
  // pixel is black exactly where its one shadow ray is blocked, always by the disc.
  Scene scene;
  scene.render.width = 16;
  scene.render.height = 16;
  Camera camera = lookingFrom(Vec3(0, 20, 0), Vec3(0.0), 30.0);
  camera.up = Vec3(0, 0, -1);
  scene.cameras.push_back(camera);
  addShape(scene, PlaneSpec{Vec3(0, 1, 0), 0.0}, addMaterial(scene, diffuse(1.0f)));
  addShape(scene, DiscSpec{Vec3(0, 3, 0), Vec3(0, 1, 0), 1.5, 0.0},
           addMaterial(scene, diffuse(1.0f)));
  scene.lights.push_back(pointLight(Vec3(3, 10, 0)));
  World world(scene);
  const RenderResult r = Renderer(world, scene.cameras[0]).render();
  REQUIRE(r.stats.primary == 256);
  REQUIRE(r.stats.shadow == 256);  // every point seen faces the light
  uint64_t blocked = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      if (r.image.at(x, y) == Color(0.0f)) ++blocked;
  REQUIRE(blocked > 10);
  REQUIRE(blocked < 200);
  CHECK(r.stats.shadowCacheHits == blocked - 1);
  // The floor plane is tested by every primary ray and by every shadow ray the cached
  // disc does not answer; the disc (a lone bounded object, tested directly) by all.
  CHECK(r.stats.tests[slotOf<PlaneSpec>()] == 256 + (256 - r.stats.shadowCacheHits));
  CHECK(r.stats.tests[slotOf<DiscSpec>()] == 256 + 256);
}

TEST_CASE("ShadowRays gives spawnRayTo's rays to the last bit", "[render][shadow][spawn]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-10.0, 10.0), e(0.0, 1e-6);
  for (int i = 0; i < 20000; ++i) {
    SurfaceInfo s;
    s.p = Vec3(u(rng), u(rng), u(rng));
    s.pError = Vec3(e(rng), e(rng), e(rng)) * (i % 3 == 0 ? 0.0 : 1.0);
    s.ng = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
    const std::optional<double> eps = i % 4 == 0 ? std::optional<double>(1e-4) : std::nullopt;
    const ShadowRays rays(s, eps);
    for (int k = 0; k < 4; ++k) {
      // Targets on both sides of the surface, and one exactly in its tangent plane.
      Vec3 target = k == 3 ? s.p : s.p + Vec3(u(rng), u(rng), u(rng));
      const Ray want = spawnRayTo(s, target, eps), got = rays.to(target);
      REQUIRE(got.o == want.o);
      REQUIRE(got.d == want.d);
      REQUIRE(got.tmin == want.tmin);
      REQUIRE(got.tmax == want.tmax);
    }
  }
}

namespace {

// The shadow walk as it was before the opaque objects were asked first: every surface
// along the ray in order, through the whole world; 0 at the first opaque one.
Color walkEverySurface(const World& world, Ray ray) {
  Color t(1.0f);
  for (;;) {
    Hit hit;
    if (!world.intersect(ray, hit)) return t;
    const Material& m = world.material(hit);
    if (!m.isTransmissive()) return Color(0.0f);
    t *= m.transmissive;
    ray.tmin = hit.t;
  }
}

}  // namespace

TEST_CASE("shadow rays through glass: asking the opaque objects first changes no answer",
          "[render][shadow][cache][glass]") {
  // Glass spheres (kept in world space), a glass box and glass CSG among opaque blockers;
  // shadow rays from random points of the floor towards random points above.
  Scene scene;
  Material glass, tinted;
  glass.transmissive = Color(0.9f);
  glass.ior = 1.5;
  tinted.transmissive = Color(0.5f, 0.8f, 0.3f);
  const uint32_t g = addMaterial(scene, glass), t = addMaterial(scene, tinted);
  const uint32_t opaque = addMaterial(scene, diffuse(0.7f));
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-4.0, 4.0), h(0.5, 3.0), r(0.2, 0.7);
  for (int i = 0; i < 60; ++i) {
    const Vec3 c(u(rng), h(rng), u(rng));
    const uint32_t m = i % 3 == 0 ? opaque : (i % 3 == 1 ? g : t);
    if (i % 4 == 3) addShape(scene, BoxSpec{c - Vec3(0.3), c + Vec3(0.3)}, m);
    else addShape(scene, SphereSpec{c, r(rng)}, m);
  }
  auto lens = std::make_unique<Node>();
  lens->kind = NodeKind::Intersection;
  lens->material = g;
  lens->children.push_back(shapeNode(SphereSpec{Vec3(0.4, 2, 0), 1.0}, std::nullopt));
  lens->children.push_back(shapeNode(SphereSpec{Vec3(-0.4, 2, 0), 1.0}, std::nullopt));
  scene.root->children.push_back(std::move(lens));
  addShape(scene, PlaneSpec{Vec3(0, 1, 0), 0.0}, opaque);
  World world(scene);
  REQUIRE(world.transmissiveObjectCount() > 30);
  Tracer tracer(world);
  RayStats stats;
  World::ObjectId slot = World::kNoObject;
  size_t dark = 0, tinted_ = 0, clear = 0, cacheHits = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 from(u(rng), 1e-3, u(rng)), to(u(rng), 6.0, u(rng));
    Ray ray(from, to - from);
    ray.tmin = 1e-6;
    ray.tmax = 1.0;
    const Color want = walkEverySurface(world, ray);
    const uint64_t hitsBefore = stats.shadowCacheHits;
    const Color got = tracer.transmittance(ray, MediaStack(), slot, stats);
    REQUIRE(got == want);
    const Color uncached = tracer.transmittance(ray, MediaStack(), stats);
    REQUIRE(uncached == want);
    cacheHits += stats.shadowCacheHits - hitsBefore;
    if (want == Color(0.0f)) ++dark;
    else if (want == Color(1.0f)) ++clear;
    else ++tinted_;
  }
  // All three answers occur often, and the cache answers some of the blocked rays.
  CHECK(dark > 2000);
  CHECK(tinted_ > 2000);
  CHECK(clear > 2000);
  CHECK(cacheHits > 100);
}
