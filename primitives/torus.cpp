#include "torus.h"
#include "pov_uv.h"

#include "polynomial.h"

#include <algorithm>
#include <stdexcept>

namespace lucent {

Torus::Torus(double major, double minor) : R_(major), r_(minor) {
  if (!(major > 0.0 && minor > 0.0) || !std::isfinite(major) || !std::isfinite(minor))
    throw std::invalid_argument("torus: major and minor must be positive finite numbers");
}

AABB Torus::bounds() const {
  double e = R_ + r_;
  return {Vec3(-e, -r_, -e), Vec3(e, r_, e)};
}

namespace {

// The quartic along o + t·d in its factored form, and its first two derivatives in t from
// the expanded form (smooth on the axis, where ρ is not).
struct TorusEval {
  double f, df, d2f;
};

TorusEval evalTorus(double R, double r, const Vec3& o, const Vec3& d, double t) {
  Vec3 p = o + t * d;
  double rho2 = p.x * p.x + p.z * p.z;
  double rho = std::sqrt(rho2);
  double y2r2 = p.y * p.y - r * r;
  double g1 = (rho - R) * (rho - R) + y2r2;
  double g2 = (rho + R) * (rho + R) + y2r2;
  double S = glm::dot(p, p) + R * R - r * r;
  double pd = glm::dot(p, d);
  double rd = p.x * d.x + p.z * d.z;
  double dxz = d.x * d.x + d.z * d.z;
  TorusEval e;
  e.f = g1 * g2;
  e.df = 4.0 * S * pd - 8.0 * R * R * rd;
  e.d2f = 8.0 * pd * pd + 4.0 * S * glm::dot(d, d) - 8.0 * R * R * dxz;
  return e;
}

// Newton on g(t) (g = f for a simple root, g = f' for a tangent one), keeping the iterate
// where |g| is smallest: polishing can only improve on the quartic's root.
double polish(double R, double r, const Vec3& o, const Vec3& d, double t, bool tangent) {
  auto g = [&](double x, double& dg) {
    TorusEval e = evalTorus(R, r, o, d, x);
    dg = tangent ? e.d2f : e.df;
    return tangent ? e.df : e.f;
  };
  double dg;
  double x = t, gx = g(x, dg);
  double best = x, bestAbs = std::abs(gx);
  for (int it = 0; it < 4 && bestAbs > 0.0; ++it) {
    if (dg == 0.0 || !std::isfinite(dg)) break;
    double next = x - gx / dg;
    if (next == x) break;
    double dn;
    double gn = g(next, dn);
    if (!(std::abs(gn) < bestAbs)) break;
    x = best = next;
    gx = gn;
    dg = dn;
    bestAbs = std::abs(gn);
  }
  return best;
}

}  // namespace

bool Torus::missesHull(const Vec3& o, const Vec3& dn, double a2, double a1, double a0,
                       double L) const {
  // Every point of the solid torus has |y| <= r and R - r <= ρ <= R + r (ρ: the distance
  // from the axis). The line's stretch inside the slab |y| <= r, within the chord (-L, L),
  // has ρ² = a2·s² + 2·a1·s + a0, convex in s: if it stays beyond R + r, or within R - r,
  // the line meets no point of the torus. The hull is widened by a millionth, far beyond
  // the rounding of these few operations and of the quartic's coefficients, so every line
  // the quartic could find a root for (near the surface, or touching it) is still solved.
  constexpr double kMargin = 1e-6;
  const double ySlab = r_ * (1.0 + kMargin);
  double s0 = -L, s1 = L;
  if (dn.y != 0.0) {
    double a = (-ySlab - o.y) / dn.y, b = (ySlab - o.y) / dn.y;
    if (a > b) std::swap(a, b);
    s0 = std::max(s0, a);
    s1 = std::min(s1, b);
    if (!(s0 <= s1)) return true;
  } else if (!(std::abs(o.y) <= ySlab)) {
    return true;
  }
  auto rho2 = [&](double s) { return (a2 * s + 2.0 * a1) * s + a0; };
  // The nearest approach to the axis on [s0, s1] (a2 = 0: the line is parallel to the axis
  // and a1 = 0, ρ² constant).
  const double sNear = a2 > 0.0 ? std::clamp(-a1 / a2, s0, s1) : s0;
  const double outer = (R_ + r_) * (1.0 + kMargin);
  if (rho2(sNear) > outer * outer) return true;
  const double inner = (R_ - r_) * (1.0 - kMargin);
  return inner > 0.0 && std::max(rho2(s0), rho2(s1)) < inner * inner;
}

int Torus::lineRoots(const Ray& ray, double t[4]) const {
  const double dd = glm::dot(ray.d, ray.d);
  if (!(dd > 0.0)) return 0;
  const double speed = std::sqrt(dd);
  const Vec3 dn = ray.d / speed;
  // Shift to the closest approach to the centre; leave if the bounding sphere is missed.
  const double tShift = -glm::dot(ray.o, ray.d) / dd;
  const Vec3 o = ray.o + tShift * ray.d;
  const double bound = R_ + r_;
  const double o2 = glm::dot(o, o);
  if (o2 > bound * bound * (1.0 + gamma(4))) return 0;
  // The chord of a slightly larger sphere: its ends are safely outside the torus.
  const double L = std::sqrt(std::max(0.0, 1.0625 * bound * bound - o2)) + 0.25 * bound;

  // (e·s² + 2β·s + α)² − 4R²(a2·s² + 2·a1·s + a0), with p = o + s·dn.
  const double e = glm::dot(dn, dn);
  const double beta = glm::dot(o, dn);
  const double R2 = R_ * R_, r2 = r_ * r_;
  const double alpha = o2 + R2 - r2;
  const double a2 = dn.x * dn.x + dn.z * dn.z;
  const double a1 = o.x * dn.x + o.z * dn.z;
  const double a0 = o.x * o.x + o.z * o.z;
  if (missesHull(o, dn, a2, a1, a0, L)) return 0;
  // The quartic is solved on the line's stretch through the slab |y| <= 1.25·r only: a
  // shorter bracket takes the root finder fewer steps, and at its ends, a quarter of r
  // beyond the tube, the quartic is still clearly positive.
  double s0 = -L, s1 = L;
  if (dn.y != 0.0) {
    const double a = (-1.25 * r_ - o.y) / dn.y, b = (1.25 * r_ - o.y) / dn.y;
    s0 = std::max(s0, std::min(a, b));
    s1 = std::min(s1, std::max(a, b));
  }
  const double c[5] = {alpha * alpha - 4.0 * R2 * a0, 4.0 * alpha * beta - 8.0 * R2 * a1,
                       4.0 * beta * beta + 2.0 * e * alpha - 4.0 * R2 * a2, 4.0 * e * beta, e * e};
  // Magnitudes of the terms behind each coefficient, for the rounding bound.
  const double alphaAbs = o2 + R2 + r2, betaAbs = std::abs(beta);
  const double cAbs[5] = {
      alphaAbs * alphaAbs + 4.0 * R2 * a0, 4.0 * alphaAbs * betaAbs + 8.0 * R2 * std::abs(a1),
      4.0 * beta * beta + 2.0 * e * alphaAbs + 4.0 * R2 * a2, 4.0 * e * betaAbs, e * e};
  PolynomialRoot roots[4];
  int n = polynomialRoots(c, cAbs, 4, s0, s1, roots);
  int count = 0;
  for (int i = 0; i < n; ++i) {
    double ti = polish(R_, r_, ray.o, ray.d, tShift + roots[i].x / speed, roots[i].touching);
    t[count++] = ti;
    if (roots[i].touching && count < 4) t[count++] = ti;
  }
  std::sort(t, t + count);
  // A degenerate case could leave an odd count (a sign change at a touching point): the
  // line starts and ends outside, so drop the last root rather than end "inside".
  if (count % 2 == 1) --count;
  return count;
}

bool Torus::intersect(const Ray& ray, Hit& hit) const {
  double t[4];
  int n = lineRoots(ray, t);
  for (int i = 0; i < n; ++i) {
    if (ray.tmin < t[i] && t[i] < ray.tmax) {
      hit.t = t[i];
      hit.shape = this;
      hit.part = 0;
      return true;
    }
  }
  return false;
}

void Torus::crossings(const Ray& ray, CrossingList& out) const {
  double t[4];
  int n = lineRoots(ray, t);
  int before = 0;
  for (int i = 0; i < n; ++i) {
    if (t[i] < ray.tmin) {
      ++before;
    } else if (t[i] <= ray.tmax) {
      Crossing c;
      c.hit.t = t[i];
      c.hit.shape = this;
      c.entering = (i % 2 == 0);
      out.items.push_back(c);
    }
  }
  out.startsInside = before % 2 == 1;
}

bool Torus::inside(const Vec3& p) const {
  // The quartic's sign from its factors: negative inside the outer surface (g1 < 0) and
  // outside the inner one (g2 > 0, which only a spindle torus can violate).
  double rho = std::sqrt(p.x * p.x + p.z * p.z);
  double y2r2 = p.y * p.y - r_ * r_;
  double g1 = (rho - R_) * (rho - R_) + y2r2;
  double g2 = (rho + R_) * (rho + R_) + y2r2;
  return g1 < 0.0 && g2 > 0.0;
}

SurfaceInfo Torus::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo s;
  Vec3 p = ray.at(hit.t);
  double rho = std::sqrt(p.x * p.x + p.z * p.z);
  double y2r2 = p.y * p.y - r_ * r_;
  double g1 = (rho - R_) * (rho - R_) + y2r2;
  double g2 = (rho + R_) * (rho + R_) + y2r2;
  if (rho > 0.0) {
    // Reproject like a sphere around the nearest point of the tube's centre circle
    // (c = ±R·ρ̂, the sign picking the factor that vanishes): p = c + r·m, m unit.
    double side = std::abs(g1) <= std::abs(g2) ? 1.0 : -1.0;
    Vec3 c = side * R_ * Vec3(p.x / rho, 0.0, p.z / rho);
    Vec3 m = p - c;
    double len = glm::length(m);
    m = len > 0.0 ? m / len : Vec3(0.0, 1.0, 0.0);
    s.p = c + r_ * m;
    s.pError = gamma(8) * (glm::abs(c) + r_ * glm::abs(m)) + gamma(2) * glm::abs(s.p);
    // On the inner (lemon) sheet of a spindle torus the solid lies outside that sphere.
    s.ng = side * m;
  } else {
    // On the axis (spindle tori only): the gradient of the quartic there is along ±y.
    s.p = p;
    s.pError = gamma(16) * (glm::abs(ray.o) + glm::abs(hit.t * ray.d));
    s.ng = Vec3(0.0, p.y >= 0.0 ? 1.0 : -1.0, 0.0);
  }
  s.ns = s.ng;
  return s;
}

// POV-Ray's torus: u = 1 - (atan2(z, x) + pi)/2pi about +y, v = the angle round the tube
// from its inner equator, (atan2(y, rho - R) + pi)/2pi, in POV-Ray's space (z negated).
bool Torus::povUV(const SurfaceInfo& s, const Hit& /*hit*/, Vec2& uv) const {
  const double x = s.p.x, y = s.p.y, z = -s.p.z;
  const double u = 1.0 - (std::atan2(z, x) + kPi) / (2.0 * kPi);
  const double rho = std::sqrt(x * x + z * z);
  uv = Vec2(u, (std::atan2(y, rho - R_) + kPi) / (2.0 * kPi));
  return true;
}

}  // namespace lucent
