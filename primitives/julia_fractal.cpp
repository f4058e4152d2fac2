#include "julia_fractal.h"

#include <cmath>

namespace lucent {

namespace {

// POV-Ray's fractal.cpp tolerance: the nearest start, the bisection's end, the restart.
constexpr double kTolerance = 1e-7;
// POV-Ray's EPSILON in its sphere test.
constexpr double kPovEpsilon = 1e-10;

// The orbit of the last test, one per thread, grown to the largest max-iteration seen.
JuliaMap::Orbit& orbitFor(const JuliaMap& m) {
  thread_local JuliaMap::Orbit orbit;
  const size_t n = static_cast<size_t>(m.maxIteration()) + 1;
  if (orbit.size() < n) orbit.resize(n);
  return orbit;
}

// A unit vector in two numbers (the hit's payload), by the octahedral map: exact to a few
// ulps (Cigolle et al., "A Survey of Efficient Representations for Independent Unit
// Vectors", JCGT 2014).
Vec2 packUnit(const Vec3& n) {
  const Vec3 a = n / (std::abs(n.x) + std::abs(n.y) + std::abs(n.z));
  if (a.z >= 0.0) return {a.x, a.y};
  return {(1.0 - std::abs(a.y)) * (a.x >= 0.0 ? 1.0 : -1.0),
          (1.0 - std::abs(a.x)) * (a.y >= 0.0 ? 1.0 : -1.0)};
}
Vec3 unpackUnit(const Vec2& p) {
  Vec3 n(p.x, p.y, 1.0 - std::abs(p.x) - std::abs(p.y));
  if (n.z < 0.0) {
    n.x = (1.0 - std::abs(p.y)) * (p.x >= 0.0 ? 1.0 : -1.0);
    n.y = (1.0 - std::abs(p.x)) * (p.y >= 0.0 ? 1.0 : -1.0);
  }
  return glm::normalize(n);
}

// The hit's payload: the side in part, POV-Ray's normal (made unit) in b1, b2; a normal of
// no length or not finite is stored as the reverse of the ray.
void fillHit(Hit& h, const JuliaFractal* shape, double t, bool entering, Vec3 n, const Vec3& d) {
  h.t = t;
  h.shape = shape;
  h.part = entering ? 1 : 0;
  const double m = glm::length(n);
  n = m > 0.0 && std::isfinite(m) ? n / m : -glm::normalize(d);
  const Vec2 p = packUnit(n);
  h.b1 = p.x;
  h.b2 = p.y;
}

}  // namespace

JuliaFractal::JuliaFractal(const JuliaParams& p) : map_(p) {}

AABB JuliaFractal::bounds() const {
  const double r = map_.radius();
  return AABB(Vec3(-r), Vec3(r));
}

template <class OnHit>
bool JuliaFractal::march(const Ray& ray, double tmax, OnHit&& onHit) const {
  const double len = glm::length(ray.d);
  if (!(len > 0.0)) return false;
  const Vec3 dir = ray.d / len;
  // The bounding sphere, as POV-Ray's sphere test: none when the origin is outside and
  // the centre not ahead.
  const double r2 = map_.radius() * map_.radius();
  const double oc2 = glm::dot(ray.o, ray.o);
  const double closest = -glm::dot(ray.o, dir);
  if (oc2 >= r2 && closest < kPovEpsilon) return false;
  const double half2 = r2 - oc2 + closest * closest;
  if (!(half2 > kPovEpsilon)) return false;
  const double half = std::sqrt(half2);
  double depth = closest - half;
  const double depthMax = std::min(closest + half, tmax * len);
  if (depthMax < kTolerance) return false;
  depth = std::max(depth, kTolerance);

  JuliaMap::Orbit& orbit = orbitFor(map_);
  Vec3 next = ray.o + dir * depth;
  double dist = 0.0, distNext = 0.0;
  bool current = map_.insideWithStep(next, dir, dist, orbit);
  if (current) {
    next += 2.0 * kTolerance * dir;
    depth += 2.0 * kTolerance;
    if (depth > depthMax) return false;
    current = map_.insideWithStep(next, dir, dist, orbit);
  }
  const bool startedInside = current;
  bool last = false;  // the last bisection test (POV-Ray keeps it from crossing to crossing)
  Vec3 point = next;
  while (depth < depthMax) {
    // Step until the membership changes; `point` keeps the last point of the old one.
    bool nextIn = current;
    for (;;) {
      dist = std::max(dist, map_.minStep());
      depth += dist;
      if (depth > depthMax) return startedInside;
      point = next;
      next += dist * dir;
      nextIn = map_.insideWithStep(next, dir, distNext, orbit);
      if (nextIn != current) break;
      dist = distNext;
    }
    const double depthOfNext = depth;
    depth -= dist;
    // Bisect with the inside test, keeping `point` on the old side.
    while (dist > kTolerance) {
      dist *= 0.5;
      const Vec3 mid = point + dist * dir;
      last = map_.inside(mid, orbit);
      if (last == current) {
        point = mid;
        depth += dist;
        if (depth > depthMax) return startedInside;
      }
    }
    // The hit is the point on the inside side; its orbit gives the normal, which POV-Ray
    // computes here from the orbit buffer as the tests left it.
    if (!current) {
      point += dist * dir;
      depth += dist;
      map_.inside(point, orbit);
    } else if (last != current) {
      map_.inside(point, orbit);
    }
    if (!onHit(depth / len, !current, map_.normal(orbit))) return startedInside;
    point = next;
    depth = depthOfNext;
    dist = distNext;
    current = nextIn;
  }
  return startedInside;
}

bool JuliaFractal::intersect(const Ray& ray, Hit& hit) const {
  bool found = false;
  march(ray, ray.tmax, [&](double t, bool entering, const Vec3& n) {
    if (t <= ray.tmin) return true;
    if (t >= ray.tmax) return false;
    fillHit(hit, this, t, entering, n, ray.d);
    found = true;
    return false;
  });
  return found;
}

void JuliaFractal::crossings(const Ray& ray, CrossingList& out) const {
  int sideBefore = -1;  // the side after the last crossing before tmin (-1: none)
  const bool startedInside = march(ray, ray.tmax, [&](double t, bool entering, const Vec3& n) {
    if (t > ray.tmax) return false;
    if (t < ray.tmin) {
      sideBefore = entering ? 1 : 0;
      return true;
    }
    Crossing c;
    fillHit(c.hit, this, t, entering, n, ray.d);
    c.entering = entering;
    out.items.push_back(c);
    return true;
  });
  out.startsInside = sideBefore < 0 ? startedInside : sideBefore == 1;
}

bool JuliaFractal::inside(const Vec3& p) const { return map_.inside(p, orbitFor(map_)); }

SurfaceInfo JuliaFractal::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo s;
  s.p = ray.at(hit.t);
  // The hit lies within the bisection's 1e-7 of the crossing (object units along the unit
  // ray), on its inside side, besides the point's rounding.
  s.pError = Vec3(2.0 * kTolerance) + 1e-15 * (glm::abs(ray.o) + glm::abs(hit.t * ray.d));
  Vec3 n = unpackUnit(Vec2(hit.b1, hit.b2));
  // POV-Ray shades with its normal as computed; Lucent's ng faces out of the solid, so it
  // is turned to the side the crossing says (entering: against the ray).
  const bool entering = hit.part == 1;
  if ((glm::dot(n, ray.d) > 0.0) == entering) n = -n;
  s.ng = n;
  s.ns = n;
  return s;
}

}  // namespace lucent
