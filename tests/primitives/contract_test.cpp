// Every shape against the contract of shape.h on seeded random rays: crossings sorted,
// inside [tmin, tmax] and alternating from startsInside; intersect() and occluded() agree
// with the first crossing; startsInside agrees with inside() away from the surface.
#include "scenegraph/shape_registry.h"
#include "shape_checks.h"

#include <catch2/catch.hpp>

#include <memory>
#include <vector>

using namespace lucent;
using namespace lucent::test;

namespace {

struct Named {
  std::string name;
  std::shared_ptr<const Shape> shape;
  AABB aim;  // where random rays are aimed (the bounds, or a box around the origin)
};

// Every sample of every row of the shape registry: a new shape is checked here as soon as
// its entry exists.
std::vector<Named> allShapes() {
  std::vector<Named> v;
  for (const ShapeType& type : shapeTypes()) {
    for (const auto& [name, spec] : type.samples()) {
      std::shared_ptr<const Shape> s = type.build(spec);
      AABB b = s->bounds();
      if (!b.isBounded()) b = AABB(Vec3(-2.0), Vec3(2.0));
      v.push_back({name, std::move(s), b});
    }
  }
  return v;
}

}  // namespace

TEST_CASE("every registered shape has samples for the contract tests", "[primitives]") {
  for (const ShapeType& type : shapeTypes()) {
    INFO(type.element);
    CHECK_FALSE(type.samples().empty());
  }
  CHECK(allShapes().size() >= shapeTypes().size());
}

TEST_CASE("every shape keeps the crossings contract on random rays", "[primitives]") {
  Rng rng(20240601);
  for (const Named& s : allShapes()) {
    INFO(s.name);
    int checked = 0;
    std::string failure;
    for (int i = 0; i < 3000 && failure.empty(); ++i) {
      Ray ray = randomRayAt(rng, s.aim);
      // Some directions lose one or two components (the slab and shear code's 0 and ±inf
      // paths); the origin moves so the ray still passes through the aimed-at point.
      if (i % 5 == 2 || i % 5 == 3) {
        Vec3 target = ray.at(1.0);
        ray.d[i % 3] = 0.0;
        if (i % 5 == 3) ray.d[(i + 1) % 3] = 0.0;
        if (ray.d == Vec3(0.0)) ray.d[(i + 2) % 3] = 1.0;
        ray.o = target - ray.d;
      }
      // Half the rays get a random window, sometimes starting inside the shape.
      if (i % 2 == 1) {
        ray.tmin = uniform(rng, 0.0, 1.2);
        ray.tmax = ray.tmin + uniform(rng, 0.0, 1.0);
      }
      failure = intersectAgreesWithCrossings(*s.shape, ray);
      ++checked;
    }
    INFO("after " << checked << " rays");
    CHECK(failure == "");
  }
}

TEST_CASE("startsInside agrees with inside() away from the surface", "[primitives]") {
  Rng rng(77);
  for (const Named& s : allShapes()) {
    INFO(s.name);
    int compared = 0, wrong = 0;
    for (int i = 0; i < 3000; ++i) {
      Ray ray = randomRayAt(rng, s.aim);
      ray.tmin = uniform(rng, 0.0, 1.5);
      // Skip points within 1e-7 (relative) of a crossing: surface points may go either way.
      CrossingList whole;
      s.shape->crossings(Ray(ray.o, ray.d, -kInf, kInf), whole);
      double size = glm::length(s.aim.extent());
      bool near = false;
      for (const Crossing& c : whole.items)
        near |= std::abs(c.hit.t - ray.tmin) * glm::length(ray.d) < 1e-7 * size;
      if (near) continue;
      CrossingList cl;
      s.shape->crossings(ray, cl);
      ++compared;
      if (cl.startsInside != s.shape->inside(ray.at(ray.tmin))) ++wrong;
    }
    CHECK(compared > 2900);
    CHECK(wrong == 0);
  }
}

TEST_CASE("surfaces are never inside and all their crossings enter", "[primitives]") {
  for (const Named& s : allShapes()) {
    if (s.shape->isSolid()) continue;
    INFO(s.name);
    CHECK_FALSE(s.shape->inside(s.aim.center()));
  }
}

TEST_CASE("surface() gives unit normals, finite points and pError >= 0 at random hits",
          "[primitives]") {
  Rng rng(5150);
  for (const Named& s : allShapes()) {
    INFO(s.name);
    int hits = 0, bad = 0;
    for (int i = 0; i < 2000; ++i) {
      Ray ray = randomRayAt(rng, s.aim);
      Hit h;
      if (!s.shape->intersect(ray, h)) continue;
      ++hits;
      SurfaceInfo si = s.shape->surface(ray, h);
      bool ok = isFinite(si.p) && isFinite(si.pError) && si.pError.x >= 0 && si.pError.y >= 0 &&
                si.pError.z >= 0 && std::abs(glm::length(si.ng) - 1.0) < 1e-12 &&
                std::abs(glm::length(si.ns) - 1.0) < 1e-12 && glm::dot(si.ng, si.ns) >= 0.0 &&
                // the point is where the ray says, up to rounding of the ray equation
                glm::length(si.p - ray.at(h.t)) <= 1e-9 * (1.0 + glm::length(ray.at(h.t)));
      if (!ok) ++bad;
    }
    CHECK(hits > 50);
    CHECK(bad == 0);
  }
}
