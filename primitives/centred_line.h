// A ray's line restarted at its point nearest a shape's centre, with a unit direction:
// coefficients of a shape's equations along it keep the shape's size however far the ray
// starts (used by the sor and the sphere sweep, whose polynomials would otherwise lose
// their digits to a far origin).
#pragma once

#include "aabb.h"
#include "ray.h"

#include <cmath>

namespace lucent {

struct CentredLine {
  Vec3 o{0.0};       // the line's point nearest the box's centre
  Vec3 d{0.0};       // the ray's direction, of unit length
  double s0 = 0.0;   // o's distance along d from the ray's origin
  double len = 1.0;  // the ray direction's length: the ray's t is (s + s0) / len
};

// False when the ray has no finite direction or its line misses `box`.
inline bool centredLine(const Ray& ray, const AABB& box, CentredLine& out) {
  out.len = glm::length(ray.d);
  if (!(out.len > 0.0) || !std::isfinite(out.len)) return false;
  out.d = ray.d / out.len;
  out.s0 = glm::dot(box.center() - ray.o, out.d);
  out.o = ray.o + out.s0 * out.d;
  return box.hit(Ray(out.o, out.d, -kInf, kInf), 1.0 / out.d);
}

}  // namespace lucent
