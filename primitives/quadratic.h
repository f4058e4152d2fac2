// Cancellation-free roots of the quadratics behind the sphere, cylinder and cone.
#pragma once

#include "math.h"

#include <cmath>
#include <utility>

namespace lucent {

// Real roots t0 <= t1 of a·t² + 2·h·t + c = 0 (note the half coefficient h), given the
// reduced discriminant disc = h² − a·c, which the caller may compute in a better
// conditioned form. Returns false when disc < 0, or when a = h = 0 (no unique roots).
//
// Numerical Recipes §5.6 / Haines, Günther, Akenine-Möller, "Precision Improvements for
// Ray/Sphere Intersection" (Ray Tracing Gems, ch. 7): q = −(h + sign(h)·√disc) adds two
// numbers of the same sign, so the root q/a of larger magnitude is free of cancellation,
// and the other root comes from Vieta's product t0·t1 = c/a as c/q, also free of it.
// The textbook (−h ± √disc)/a loses every digit of the small root when h² ≫ |a·c|
// (a ray from far away, or one that starts near the surface).
inline bool solveQuadratic(double a, double h, double c, double disc, double& t0, double& t1) {
  if (disc < 0.0 || std::isnan(disc)) return false;
  double q = -(h + std::copysign(std::sqrt(disc), h));
  if (q == 0.0) {
    // h = 0 and disc = 0, so a·c = 0: a double root at 0 if a ≠ 0.
    if (a == 0.0) return false;
    t0 = t1 = 0.0;
    return true;
  }
  if (a == 0.0) {
    // Degenerates to the line 2·h·t + c = 0 (a cone's side parallel to the ray): one root,
    // reported twice so callers can treat it like a tangent pair.
    t0 = t1 = c / q;  // q = −2h here
    return std::isfinite(t0);
  }
  t0 = q / a;
  t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

// Roots of |f + t·d|² = r², the shape of every "distance from a point or an axis" test:
// f is the origin relative to the centre (or its part perpendicular to the axis) and d the
// direction (or its perpendicular part). Works for glm::dvec2 and dvec3.
//
// The discriminant comes from the perpendicular distance of the centre from the line
// (Ray Tracing Gems, ch. 7, eq. 7.5): h² − a·c = a·(r² − |f − (h/a)·d|²). The textbook
// h² − a·c subtracts two nearly equal large numbers when the ray comes from far away and
// loses the discriminant's digits; the distance form subtracts quantities of the size of
// the radius instead.
template <class V>
bool solveDistanceQuadratic(const V& f, const V& d, double r2, double& t0, double& t1) {
  double a = glm::dot(d, d);
  if (!(a > 0.0)) return false;
  double h = glm::dot(f, d);
  V perp = f - (h / a) * d;
  double disc = a * (r2 - glm::dot(perp, perp));
  double c = glm::dot(f, f) - r2;
  return solveQuadratic(a, h, c, disc, t0, t1);
}

}  // namespace lucent
