// Helpers shared by the camera tests: cameras of each type, rays at film positions, angles.
#pragma once

#include "render/projection.h"

#include <catch2/catch.hpp>

#include <memory>

namespace lucent::camtest {

// The angle between two directions, accurate near 0 and pi (atan2 of |a x b| and a . b).
inline double angleBetween(const Vec3& a, const Vec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

inline Ray rayAt(const Projection& p, const Vec2& film, const Vec2& lens = Vec2(0.5)) {
  Ray r;
  REQUIRE(p.generateRay(film, lens, r));
  return r;
}

inline bool hasRay(const Projection& p, const Vec2& film) {
  Ray r;
  return p.generateRay(film, Vec2(0.5), r);
}

// A camera that does not sit at the origin nor look along an axis, so a mix-up of frame
// axes cannot pass unnoticed.
inline Camera tiltedCamera(CameraType type) {
  Camera c;
  c.type = type;
  c.position = Vec3(1.0, 2.0, 3.0);
  c.lookAt = Vec3(-2.0, 0.5, -4.0);
  c.up = Vec3(0.1, 1.0, 0.2);
  return c;
}

template <class P>
const P& as(const std::unique_ptr<Projection>& p) {
  const P* q = dynamic_cast<const P*>(p.get());
  REQUIRE(q != nullptr);
  return *q;
}

}  // namespace lucent::camtest
