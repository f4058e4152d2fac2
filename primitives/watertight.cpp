#include "watertight.h"

#include <cmath>
#include <limits>
#include <utility>

namespace lucent {

namespace {

// The value of an edge function decided by the tie-break: far below any real one, so the
// barycentric weights and t stay what they were (the ray passes through the edge).
constexpr double kTieBreak = 1e-300;

// a·b − c·d with the correct sign (Kahan's algorithm with fma, see watertight.h).
double diffOfProducts(double a, double b, double c, double d) {
  double w = c * d;
  double e = std::fma(-c, d, w);  // exactly w − c·d
  double f = std::fma(a, b, -w);
  return f + e;
}

// The edge function p × q of the origin against the sheared edge from p to q, with its
// exact sign, and never 0. Its sign decides on which side of the edge the ray passes, so
// it must agree between the two triangles that share the edge (they compute q × p, the
// exact negation): the plain products are used when their rounding cannot flip the sign,
// Kahan's exactly signed form otherwise. An exact 0 (the ray meets the edge's line) is
// decided as if the ray were moved by an infinitesimal δ·(1, η), 0 < η ≪ 1, in the sheared
// plane (simulation of simplicity, Edelsbrunner & Mücke 1990; rasterisers' top-left rule
// is the same idea): p × q becomes p × q + δ·((p.y − q.y) + η·(q.x − p.x)). Every point is
// then covered exactly once by the triangles around a shared edge or vertex, so a closed
// mesh's crossings alternate and nothing is counted twice. 0 is returned only when p and
// q coincide in the sheared plane (the edge lies along the ray): no perturbation separates
// the ray from such an edge's line, and its triangle is seen edge-on and never hit.
double edgeFunction(double px, double py, double qx, double qy) {
  const double l = px * qy, r = py * qx;
  const double e = l - r;
  if (std::abs(e) > gamma(3) * (std::abs(l) + std::abs(r))) return e;
  const double exact = diffOfProducts(px, qy, py, qx);
  if (exact != 0.0) return exact;
  if (py != qy) return py > qy ? kTieBreak : -kTieBreak;
  if (qx != px) return qx > px ? kTieBreak : -kTieBreak;
  return 0.0;
}

// On which side of the plane of the triangle (a, b, c), given relative to the ray's
// origin, does the origin lie: +1 on the side its normal (b − a) × (c − a) points to,
// −1 on the other, 0 when rounding cannot tell (Shewchuk's static filter for orient3d,
// "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates",
// 1997: error bound (7 + 56ε)ε times the permanent).
int originSide(const Vec3& a, const Vec3& b, const Vec3& c) {
  // The origin's offset from the plane along the normal is −a·(b × c).
  const double bc = b.x * c.y - c.x * b.y, ca = c.x * a.y - a.x * c.y, ab = a.x * b.y - b.x * a.y;
  const double d = a.z * bc + b.z * ca + c.z * ab;
  const double permanent = (std::abs(b.x * c.y) + std::abs(c.x * b.y)) * std::abs(a.z) +
                           (std::abs(c.x * a.y) + std::abs(a.x * c.y)) * std::abs(b.z) +
                           (std::abs(a.x * b.y) + std::abs(b.x * a.y)) * std::abs(c.z);
  const double eps = 0.5 * std::numeric_limits<double>::epsilon();
  const double bound = (7.0 + 56.0 * eps) * eps * permanent;
  if (d > bound) return -1;
  if (d < -bound) return 1;
  return 0;
}

int maxDimension(const Vec3& v) { return v.x > v.y ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2); }

}  // namespace

ShearedRay::ShearedRay(const Ray& ray) : o(ray.o) {
  kz = maxDimension(glm::abs(ray.d));
  if (ray.d[kz] == 0.0) return;
  kx = (kz + 1) % 3;
  ky = (kx + 1) % 3;
  // Swapping keeps the winding, so the determinant's sign tells the side that was hit.
  if (ray.d[kz] < 0.0) std::swap(kx, ky);
  sx = ray.d[kx] / ray.d[kz];
  sy = ray.d[ky] / ray.d[kz];
  sz = 1.0 / ray.d[kz];
  valid = true;
}

bool isDegenerateTriangle(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  Vec3 e1 = p1 - p0, e2 = p2 - p0;
  double area2 = glm::length(glm::cross(e1, e2));
  return !(area2 > gamma(6) * glm::length(e1) * glm::length(e2));
}

bool intersectTriangle(const ShearedRay& r, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                       TriangleIntersection& out, double tmin) {
  if (!r.valid) return false;
  const Vec3 a = p0 - r.o, b = p1 - r.o, c = p2 - r.o;
  const double ax = a[r.kx] - r.sx * a[r.kz], ay = a[r.ky] - r.sy * a[r.kz];
  const double bx = b[r.kx] - r.sx * b[r.kz], by = b[r.ky] - r.sy * b[r.kz];
  const double cx = c[r.kx] - r.sx * c[r.kz], cy = c[r.ky] - r.sy * c[r.kz];

  // Edge functions: u for the edge opposite p0, v opposite p1, w opposite p2, each with
  // its exact sign and never 0 unless the edge lies along the ray.
  const double u = edgeFunction(cx, cy, bx, by);
  const double v = edgeFunction(ax, ay, cx, cy);
  const double w = edgeFunction(bx, by, ax, ay);
  if (u == 0.0 || v == 0.0 || w == 0.0) return false;
  if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;
  const double det = u + v + w;
  if (det == 0.0 || !std::isfinite(det)) return false;

  const double az = r.sz * a[r.kz], bz = r.sz * b[r.kz], cz = r.sz * c[r.kz];
  const double invDet = 1.0 / det;
  const double t = (u * az + v * bz + w * cz) * invDet;
  if (!std::isfinite(t)) return false;

  // pbrt-v3 §3.9.6: bound the error of t from those of the sheared coordinates, the edge
  // functions and the sum; a |t| below it cannot be told from 0.
  const double maxZ = maxComponent(glm::abs(Vec3(az, bz, cz)));
  const double maxX = maxComponent(glm::abs(Vec3(ax, bx, cx)));
  const double maxY = maxComponent(glm::abs(Vec3(ay, by, cy)));
  const double deltaZ = gamma(3) * maxZ;
  const double deltaX = gamma(5) * (maxX + maxZ);
  const double deltaY = gamma(5) * (maxY + maxZ);
  const double deltaE = 2.0 * (gamma(2) * maxX * maxY + deltaY * maxX + deltaX * maxY);
  const double maxE = maxComponent(glm::abs(Vec3(u, v, w)));
  const double deltaT =
      3.0 * (gamma(3) * maxE * maxZ + deltaE * maxZ + deltaZ * maxE) * std::abs(invDet);

  const int facing = det > 0.0 ? 1 : -1;
  out.t = t;
  if (std::abs(t) <= deltaT && deltaT > 0.0) {
    // Every t this branch can give is within deltaT of 0: at most tmin, so the caller
    // rejects it whatever its sign (the origin's side is not needed).
    if (deltaT <= tmin) return false;
    // t cannot be told from 0 by its own bound. The exact side of the ray's origin
    // against the triangle's plane still gives its sign: t > 0 exactly when the origin
    // is on the side the ray comes from.
    const int side = originSide(a, b, c);
    if (side != 0) {
      const double sign = side == facing ? 1.0 : -1.0;
      out.t = sign * std::max(std::abs(t), std::numeric_limits<double>::denorm_min());
    } else if (std::abs(t) <= 6.0 * deltaZ) {
      // The origin lies on the plane within rounding and the hit is where the origin
      // is: it is put just behind the origin, so a ray that starts on (or, offset,
      // just off) a triangle neither finds it again nor, for a closed mesh, lists it as
      // a crossing ahead; its side still counts for startsInside.
      out.t = -deltaT;
    }
    // Else the ray starts on the plane and runs along it (a ray along a mesh edge meets
    // the triangles beside the edge almost edge-on): the computed t stands, consistent
    // with the neighbours' because the edge functions are.
  }
  out.b0 = u * invDet;
  out.b1 = v * invDet;
  out.b2 = w * invDet;
  out.facing = facing;
  return true;
}

}  // namespace lucent
