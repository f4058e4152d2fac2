#include "cone.h"

#include "quadratic.h"

#include <algorithm>
#include <stdexcept>

namespace lucent {

Cone::Cone(const Vec3& base, double baseRadius, const Vec3& cap, double capRadius, bool open)
    : base_(base),
      cap_(cap),
      rBase_(baseRadius),
      rCap_(capRadius),
      height_(glm::length(cap - base)),
      slope_(0.0),
      open_(open),
      frame_(base, cap != base ? glm::normalize(cap - base) : Vec3(0, 0, 1)) {
  if (!isFinite(base) || !isFinite(cap) || !(height_ > 0.0) || !std::isfinite(height_))
    throw std::invalid_argument("cone: base and cap must be distinct finite points");
  if (!(baseRadius >= 0.0 && capRadius >= 0.0) || !std::isfinite(baseRadius) ||
      !std::isfinite(capRadius) || (baseRadius == 0.0 && capRadius == 0.0))
    throw std::invalid_argument("cone: the radii must be finite, >= 0 and not both 0");
  slope_ = (capRadius - baseRadius) / height_;
}

AABB Cone::bounds() const {
  const Vec3& a = frame_.a;
  Vec3 s = glm::sqrt(glm::max(Vec3(0.0), Vec3(1.0) - a * a));
  AABB box(base_ - rBase_ * s, base_ + rBase_ * s);
  box.expand(AABB(cap_ - rCap_ * s, cap_ + rCap_ * s));
  return box;
}

bool Cone::sideQuadratic(const Ray& l, Quadratic& q) const {
  // Move the origin to the line's closest approach to a centre point before forming the
  // coefficients: they are then of the size of the cone, not of the distance the ray
  // comes from, and h² − a·c no longer cancels catastrophically for far rays (the same
  // idea as the distance form for spheres, Ray Tracing Gems ch. 7). A pointed cone is
  // centred on its apex, where the side's implicit function has a zero gradient: relative
  // to the apex its terms are of the size of the line's distance δ from it and keep their
  // relative precision, where the radius r(z) formed from the axis's middle carries an
  // absolute error of ε·size and decides lines within √ε of the apex by rounding.
  double dd = glm::dot(l.d, l.d);
  if (!(dd > 0.0)) return false;
  const Vec3 mid(0.0, 0.0, 0.5 * height_);
  const bool pointed = rBase_ == 0.0 || rCap_ == 0.0;
  const Vec3 centre = !pointed ? mid : rBase_ == 0.0 ? Vec3(0.0) : Vec3(0.0, 0.0, height_);
  const Vec3 f = l.o - centre;
  q.tShift = -glm::dot(f, l.d) / dd;
  const Vec3 g = f + q.tShift * l.d;  // the closest approach, relative to the centre
  q.o = centre + g;
  q.d = l.d;
  // Outside the bounding sphere (with a margin for rounding): the line misses. The test
  // needs the closest approach to the sphere's centre, the axis's middle.
  const double rMax = std::max(rBase_, rCap_);
  const Vec3 fm = l.o - mid;
  const Vec3 m = fm - (glm::dot(fm, l.d) / dd) * l.d;
  if (glm::dot(m, m) > (rMax * rMax + 0.25 * height_ * height_) * (1.0 + gamma(8))) return false;
  // x² + y² − r(z)² along o + s·d, with r(z) = r0 + k·z, which for a pointed cone is
  // k·(z − z_apex) = k·g.z.
  const double k = slope_;
  const double r = pointed ? k * g.z : radiusAt(q.o.z);
  q.a = q.d.x * q.d.x + q.d.y * q.d.y - k * k * q.d.z * q.d.z;
  q.h = g.x * q.d.x + g.y * q.d.y - k * q.d.z * r;
  q.c = g.x * g.x + g.y * g.y - r * r;
  return true;
}

bool Cone::solidSpan(const Ray& l, Span& s) const {
  s = Span();
  Quadratic q;
  if (!sideQuadratic(l, q)) return false;
  // Where the side's quadratic is <= 0 (inside the double cone): one or two pieces.
  double pieces[2][2];
  int n = 0;
  if (q.a == 0.0) {
    if (q.h == 0.0) {
      if (q.c > 0.0) return false;
      pieces[n][0] = -kInf, pieces[n][1] = kInf, ++n;
    } else {
      double s0 = -q.c / (2.0 * q.h);
      if (q.h > 0.0) pieces[n][0] = -kInf, pieces[n][1] = s0, ++n;
      else pieces[n][0] = s0, pieces[n][1] = kInf, ++n;
    }
  } else {
    double s0, s1;
    bool real = solveQuadratic(q.a, q.h, q.c, q.h * q.h - q.a * q.c, s0, s1);
    if (q.a > 0.0) {
      if (!real) return false;
      pieces[n][0] = s0, pieces[n][1] = s1, ++n;
    } else if (!real) {
      pieces[n][0] = -kInf, pieces[n][1] = kInf, ++n;
    } else {
      pieces[n][0] = -kInf, pieces[n][1] = s0, ++n;
      pieces[n][0] = s1, pieces[n][1] = kInf, ++n;
    }
  }
  // The slab 0 <= z <= height between the end discs. Its crossings come from the ray as
  // given, not from the shifted line: shifting the origin by tShift (the apex may be the
  // cone's length away) rounds its z by ε·tShift, more than the offset that lifts a
  // secondary ray off a disc near the origin, which could then find the disc it leaves.
  // t0, t1 are ray parameters; z0, z1 the same in the shifted parameter, to clip with.
  double t0 = -kInf, t1 = kInf;
  uint32_t p0 = 1, p1 = 2;
  if (l.d.z == 0.0) {
    if (l.o.z < 0.0 || l.o.z > height_) return false;
  } else {
    t0 = -l.o.z / l.d.z;
    t1 = (height_ - l.o.z) / l.d.z;
    if (t0 > t1) {
      std::swap(t0, t1);
      std::swap(p0, p1);
    }
  }
  const double z0 = t0 - q.tShift, z1 = t1 - q.tShift;
  // Within the slab only the real nappe lies (the mirrored one is beyond the apex), and
  // the truncated cone is convex, so at most one piece survives the clipping (two only
  // when both merely touch the apex; keep the longer).
  bool found = false;
  double bestLen = -1.0;
  for (int i = 0; i < n; ++i) {
    double lo = pieces[i][0], hi = pieces[i][1];
    uint32_t partLo = 0, partHi = 0;
    if (z0 > lo) {
      lo = z0;
      partLo = p0;
    }
    if (z1 < hi) {
      hi = z1;
      partHi = p1;
    }
    if (!(lo <= hi) || hi - lo <= bestLen) continue;
    bestLen = hi - lo;
    s.tIn = partLo != 0 ? t0 : q.tShift + lo;
    s.tOut = partHi != 0 ? t1 : q.tShift + hi;
    s.partIn = partLo;
    s.partOut = partHi;
    found = true;
  }
  return found;
}

int Cone::sideRoots(const Ray& l, SurfaceRoot roots[2]) const {
  Quadratic q;
  if (!sideQuadratic(l, q)) return 0;
  double s0, s1;
  if (!solveQuadratic(q.a, q.h, q.c, q.h * q.h - q.a * q.c, s0, s1)) return 0;
  int n = 0;
  const double ss[2] = {s0, s1};
  for (int i = 0; i < (s0 == s1 ? 1 : 2); ++i) {
    double z = q.o.z + ss[i] * q.d.z;
    if (0.0 <= z && z <= height_) roots[n++] = {q.tShift + ss[i], 0, 0.0, 0.0};
  }
  return n;
}

bool Cone::inside(const Vec3& p) const {
  if (open_) return false;
  Vec3 q = frame_.pointToLocal(p);
  if (!(0.0 < q.z && q.z < height_)) return false;
  double r = radiusAt(q.z);
  return q.x * q.x + q.y * q.y < r * r;
}

SurfaceInfo Cone::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo s;
  Ray l = frame_.rayToLocal(ray);
  Vec3 q = l.at(hit.t);
  Vec3 nLocal;
  double rho = std::sqrt(q.x * q.x + q.y * q.y);
  if (hit.part == 0) {
    // Reproject onto the side at the hit's height; the normal is the gradient of
    // x² + y² − r(z)², i.e. (cos φ, sin φ, −dr/dz) normalised.
    q.z = glm::clamp(q.z, 0.0, height_);
    double r = radiusAt(q.z);
    Vec2 dir = rho > 0.0 ? Vec2(q.x, q.y) / rho : Vec2(1.0, 0.0);
    q.x = r * dir.x;
    q.y = r * dir.y;
    nLocal = glm::normalize(Vec3(dir.x, dir.y, -slope_));
  } else {
    double r = hit.part == 1 ? rBase_ : rCap_;
    if (rho > r) {
      q.x *= r / rho;
      q.y *= r / rho;
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
