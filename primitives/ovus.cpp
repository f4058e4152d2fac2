#include "ovus.h"
#include "pov_uv.h"

#include "sphere.h"

#include <algorithm>
#include <stdexcept>

namespace lucent {

Ovus::Geometry Ovus::geometryOf(double rb, double rt) {
  Geometry g;
  g.bottomRadius = rb;
  g.topRadius = rt;
  if (!(rt < 2.0 * rb)) {
    g.sphereOnly = true;
    return g;
  }
  // The arc's circle holds each sphere and touches it: its centre lies at C − rb from the
  // bottom centre (0, 0) and at C − rt from the top one (0, rb). The two
  // distances give V; H follows. The seams lie on the lines from (−H, V) through each
  // centre, a radius beyond it.
  const double C = 2.0 * std::max(rb, rt);
  const double db = C - rb, dt = C - rt;
  g.connecting = C;
  g.vertical = (rb * rb + db * db - dt * dt) / (2.0 * rb);
  g.horizontal = std::sqrt(std::max(0.0, db * db - g.vertical * g.vertical));
  g.bottomSeam = -g.vertical * rb / db;
  g.topSeam = rb + rt * (rb - g.vertical) / dt;
  g.lemon = rt > 0.0 && g.horizontal > 0.0 && g.bottomSeam < g.topSeam;
  return g;
}

Ovus::Ovus(double bottomRadius, double topRadius) {
  if (!(bottomRadius >= 0.0 && topRadius >= 0.0) || !std::isfinite(bottomRadius) ||
      !std::isfinite(topRadius) || (bottomRadius == 0.0 && topRadius == 0.0))
    throw std::invalid_argument("ovus: the radii must be finite numbers >= 0, not both 0");
  g_ = geometryOf(bottomRadius, topRadius);
}

AABB Ovus::bounds() const {
  const double rb = g_.bottomRadius, rt = g_.topRadius;
  if (g_.sphereOnly) return {Vec3(-rt, rb - rt, -rt), Vec3(rt, rb + rt, rt)};
  // The arc is widest at y = V when V lies between the seams; elsewhere its widest point
  // is a seam, no wider than that sphere.
  double wide = std::max(rb, rt);
  if (g_.lemon && g_.bottomSeam < g_.vertical && g_.vertical < g_.topSeam)
    wide = std::max(wide, g_.connecting - g_.horizontal);
  return {Vec3(-wide, -rb, -wide), Vec3(wide, rb + rt, wide)};
}

namespace {

// h and its derivative along d at p (relative to the arc's centre line y = V): the
// greatest distance from p to the ring of the arc's centres, less C (convex in p).
void lemonGauge(const Vec3& p, const Vec3& d, double H, double C, double& h, double& dh) {
  const double rho = std::sqrt(p.x * p.x + p.z * p.z);
  const double a = rho + H;
  const double D = std::sqrt(a * a + p.y * p.y);
  h = D - C;
  // On the axis ρ has no derivative; h < 0 there between the seams, so no root is near.
  const double drho = rho > 0.0 ? (p.x * d.x + p.z * d.z) / rho : 0.0;
  dh = D > 0.0 ? (a * drho + p.y * d.y) / D : 0.0;
}

// The root of the convex h along f0 + s·d nearest `from`, walking towards `to`: Newton's
// iterates from outside stay outside and increase monotonically to the root (the tangent
// of a convex function lies below it). False when h turns upwards first or the step
// passes `to` (no root between), or when a near-double root does not settle.
bool lemonRoot(const Vec3& f0, const Vec3& d, double H, double C, double from, double to,
               double& root) {
  const double dir = to > from ? 1.0 : -1.0;
  double s = from;
  for (int it = 0; it < 200; ++it) {
    double h, dh;
    lemonGauge(f0 + s * d, d, H, C, h, dh);
    if (h <= 0.0) {
      root = s;
      return true;
    }
    if (!(dir * dh < 0.0)) return false;
    const double next = s - h / dh;
    if (dir * (next - to) > 0.0) return false;
    if (next == s) {
      root = s;
      return true;
    }
    s = next;
  }
  return false;
}

}  // namespace

bool Ovus::lemonSpan(const Ray& ray, double& tIn, double& tOut) const {
  const double a = glm::dot(ray.d, ray.d);
  if (!(a > 0.0)) return false;
  const double V = g_.vertical, H = g_.horizontal, C = g_.connecting;
  // From the line's point nearest the arc's centre (0, V, 0), so that the coordinates the
  // iteration works on are of the lemon's size however far the ray starts.
  const Vec3 f = ray.o - Vec3(0.0, V, 0.0);
  const double tShift = -glm::dot(f, ray.d) / a;
  const Vec3 f0 = f + tShift * ray.d;
  // The lemon lies within the ball of radius √(C² − H²) about (0, V, 0) (its tips).
  const double q = (C * C - H * H) - glm::dot(f0, f0);
  if (!(q > 0.0)) return false;
  double s0 = -std::sqrt(q / a), s1 = -s0;
  const double lo = g_.bottomSeam - V, hi = g_.topSeam - V;
  if (ray.d.y != 0.0) {
    double sa = (lo - f0.y) / ray.d.y, sb = (hi - f0.y) / ray.d.y;
    if (sa > sb) std::swap(sa, sb);
    s0 = std::max(s0, sa);
    s1 = std::min(s1, sb);
  } else if (!(lo < f0.y && f0.y < hi)) {
    return false;
  }
  if (!(s0 < s1)) return false;
  double l, r;
  if (!lemonRoot(f0, ray.d, H, C, s0, s1, l) || !lemonRoot(f0, ray.d, H, C, s1, s0, r) || !(l <= r))
    return false;
  tIn = tShift + l;
  tOut = tShift + r;
  return true;
}

bool Ovus::span(const Ray& ray, Span& out) const {
  out = Span();
  bool any = false;
  auto take = [&](double t0, double t1, Part part) {
    if (t0 < out.tIn) {
      out.tIn = t0;
      out.partIn = part;
    }
    if (t1 > out.tOut) {
      out.tOut = t1;
      out.partOut = part;
    }
    any = true;
  };
  const double rb = g_.bottomRadius, rt = g_.topRadius;
  double t0, t1;
  if (!g_.sphereOnly && rb > 0.0 && sphereRoots(Vec3(0.0), rb * rb, ray, t0, t1))
    take(t0, t1, kBottom);
  if (rt > 0.0 && sphereRoots(Vec3(0.0, rb, 0.0), rt * rt, ray, t0, t1)) take(t0, t1, kTop);
  if (g_.lemon && lemonSpan(ray, t0, t1)) take(t0, t1, kLemon);
  return any;
}

bool Ovus::intersect(const Ray& ray, Hit& hit) const {
  Span s;
  if (!span(ray, s)) return false;
  return intersectSpan(s, ray, this, hit);
}

void Ovus::crossings(const Ray& ray, CrossingList& out) const {
  Span s;
  if (!span(ray, s)) s = Span();
  crossingsOfSpan(s, ray, this, out);
}

bool Ovus::inside(const Vec3& p) const {
  const double rb = g_.bottomRadius, rt = g_.topRadius;
  const Vec3 top = p - Vec3(0.0, rb, 0.0);
  if (glm::dot(top, top) < rt * rt) return true;
  if (g_.sphereOnly) return false;
  if (glm::dot(p, p) < rb * rb) return true;
  if (!(g_.lemon && g_.bottomSeam < p.y && p.y < g_.topSeam)) return false;
  const double a = std::sqrt(p.x * p.x + p.z * p.z) + g_.horizontal;
  const double y = p.y - g_.vertical;
  return a * a + y * y < g_.connecting * g_.connecting;
}

SurfaceInfo Ovus::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo s;
  // Each piece's point reprojected onto it (as a sphere's, about its centre): the bottom
  // and top spheres about theirs, the arc about the nearest point of the ring of its
  // centres, on the far side of the axis.
  Vec3 centre(0.0);
  double radius = g_.bottomRadius;
  if (hit.part == kTop) {
    centre = Vec3(0.0, g_.bottomRadius, 0.0);
    radius = g_.topRadius;
  } else if (hit.part == kLemon) {
    const Vec3 p = ray.at(hit.t);
    const double rho = std::sqrt(p.x * p.x + p.z * p.z);
    const Vec3 out = rho > 0.0 ? Vec3(p.x / rho, 0.0, p.z / rho) : Vec3(1.0, 0.0, 0.0);
    centre = Vec3(0.0, g_.vertical, 0.0) - g_.horizontal * out;
    radius = g_.connecting;
  }
  Vec3 local = (ray.o - centre) + hit.t * ray.d;
  const double len = glm::length(local);
  const Vec3 m = len > 0.0 ? local / len : Vec3(0.0, 1.0, 0.0);
  s.p = centre + radius * m;
  s.pError = gamma(8) * (glm::abs(centre) + radius * glm::abs(m)) + gamma(2) * glm::abs(s.p);
  s.ng = m;
  s.ns = m;
  return s;
}

// POV-Ray's ovus maps (u, v) as a sphere about (0, top-radius/2, 0); the sphere it
// substitutes maps about its own centre (0, bottom-radius, 0). In POV-Ray's space (z
// negated).
bool Ovus::povUV(const SurfaceInfo& s, const Hit& /*hit*/, Vec2& uv) const {
  const double cy = g_.sphereOnly ? g_.bottomRadius : 0.5 * g_.topRadius;
  uv = povSphereUV(s.p - Vec3(0.0, cy, 0.0));
  return true;
}

}  // namespace lucent
