#include "cylinder.h"

#include "quadratic.h"

#include <stdexcept>

namespace lucent {

Cylinder::Cylinder(const Vec3& base, const Vec3& cap, double radius, bool open)
    : base_(base),
      cap_(cap),
      radius_(radius),
      height_(glm::length(cap - base)),
      open_(open),
      frame_(base, cap != base ? glm::normalize(cap - base) : Vec3(0, 0, 1)) {
  if (!isFinite(base) || !isFinite(cap) || !(height_ > 0.0) || !std::isfinite(height_))
    throw std::invalid_argument("cylinder: base and cap must be distinct finite points");
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw std::invalid_argument("cylinder: the radius must be a positive finite number");
}

AABB Cylinder::bounds() const {
  // The end discs' extents (see Disc::bounds) around both centres.
  const Vec3& a = frame_.a;
  Vec3 e = radius_ * glm::sqrt(glm::max(Vec3(0.0), Vec3(1.0) - a * a));
  AABB box(base_ - e, base_ + e);
  box.expand(AABB(cap_ - e, cap_ + e));
  return box;
}

// The side x² + y² = r² in the frame; the line's perpendicular part gives the quadratic in
// the distance form of quadratic.h (Ray Tracing Gems ch. 7), as for the sphere.
static bool sideInterval(const Ray& l, double r2, double& t0, double& t1) {
  Vec2 f(l.o.x, l.o.y), d(l.d.x, l.d.y);
  if (d == Vec2(0.0)) {  // parallel to the axis: all in or all out
    if (glm::dot(f, f) > r2) return false;
    t0 = -kInf;
    t1 = kInf;
    return true;
  }
  return solveDistanceQuadratic(f, d, r2, t0, t1);
}

bool Cylinder::solidSpan(const Ray& l, Span& s) const {
  s = Span();
  if (!sideInterval(l, radius_ * radius_, s.tIn, s.tOut)) return false;
  s.partIn = s.partOut = 0;
  if (l.d.z == 0.0) {
    if (l.o.z < 0.0 || l.o.z > height_) return false;
  } else {
    double tBase = -l.o.z / l.d.z, tCap = (height_ - l.o.z) / l.d.z;
    uint32_t pBase = 1, pCap = 2;
    if (tBase > tCap) {
      std::swap(tBase, tCap);
      std::swap(pBase, pCap);
    }
    if (tBase > s.tIn) {
      s.tIn = tBase;
      s.partIn = pBase;
    }
    if (tCap < s.tOut) {
      s.tOut = tCap;
      s.partOut = pCap;
    }
  }
  return s.tIn <= s.tOut;
}

int Cylinder::sideRoots(const Ray& l, SurfaceRoot roots[2]) const {
  double t0, t1;
  Vec2 f(l.o.x, l.o.y), d(l.d.x, l.d.y);
  if (!solveDistanceQuadratic(f, d, radius_ * radius_, t0, t1)) return 0;
  int n = 0;
  for (double t : {t0, t1}) {
    double z = l.o.z + t * l.d.z;
    if (0.0 <= z && z <= height_) roots[n++] = {t, 0, 0.0, 0.0};
  }
  return n;
}

bool Cylinder::inside(const Vec3& p) const {
  if (open_) return false;
  Vec3 q = frame_.pointToLocal(p);
  return q.x * q.x + q.y * q.y < radius_ * radius_ && 0.0 < q.z && q.z < height_;
}

SurfaceInfo Cylinder::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo s;
  Ray l = frame_.rayToLocal(ray);
  Vec3 q = l.at(hit.t);
  Vec3 nLocal;
  // Reproject in the frame: onto the side (scale x, y to the radius) or onto a disc (z
  // exact, x, y pulled inside the rim).
  double rho = std::sqrt(q.x * q.x + q.y * q.y);
  if (hit.part == 0) {
    if (rho > 0.0) {
      q.x *= radius_ / rho;
      q.y *= radius_ / rho;
    } else {
      q.x = radius_;
    }
    q.z = glm::clamp(q.z, 0.0, height_);
    nLocal = Vec3(q.x / radius_, q.y / radius_, 0.0);
  } else {
    if (rho > radius_) {
      q.x *= radius_ / rho;
      q.y *= radius_ / rho;
    }
    q.z = hit.part == 1 ? 0.0 : height_;
    nLocal = Vec3(0.0, 0.0, hit.part == 1 ? -1.0 : 1.0);
  }
  s.p = frame_.pointToObject(q);
  s.pError = frame_.roundTripError(q, s.p);
  s.ng = glm::normalize(frame_.vectorToObject(nLocal));
  s.ns = s.ng;
  return s;
}

}  // namespace lucent
