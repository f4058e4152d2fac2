#include "watertight.h"

#include <cmath>
#include <utility>

namespace lucent {

namespace {

// a·b − c·d with the correct sign (Kahan's algorithm with fma, see watertight.h).
double diffOfProducts(double a, double b, double c, double d) {
  double w = c * d;
  double e = std::fma(-c, d, w);  // exactly w − c·d
  double f = std::fma(a, b, -w);
  return f + e;
}

int maxDimension(const Vec3& v) {
  return v.x > v.y ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2);
}

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
                       TriangleIntersection& out) {
  if (!r.valid) return false;
  const Vec3 a = p0 - r.o, b = p1 - r.o, c = p2 - r.o;
  const double ax = a[r.kx] - r.sx * a[r.kz], ay = a[r.ky] - r.sy * a[r.kz];
  const double bx = b[r.kx] - r.sx * b[r.kz], by = b[r.ky] - r.sy * b[r.kz];
  const double cx = c[r.kx] - r.sx * c[r.kz], cy = c[r.ky] - r.sy * c[r.kz];

  // Edge functions: u for the edge opposite p0, v opposite p1, w opposite p2.
  double u = cx * by - cy * bx;
  double v = ax * cy - ay * cx;
  double w = bx * ay - by * ax;
  if (u == 0.0 || v == 0.0 || w == 0.0) {
    u = diffOfProducts(cx, by, cy, bx);
    v = diffOfProducts(ax, cy, ay, cx);
    w = diffOfProducts(bx, ay, by, ax);
  }
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

  // A hit that cannot be told from t = 0 is put just behind the origin: a ray that starts
  // on (or, offset, just off) a triangle neither finds it again nor, for a closed mesh,
  // lists it as a crossing ahead; its side still counts for startsInside.
  out.t = (std::abs(t) <= deltaT && deltaT > 0.0) ? -deltaT : t;
  out.b0 = u * invDet;
  out.b1 = v * invDet;
  out.b2 = w * invDet;
  out.facing = det > 0.0 ? 1 : -1;
  return true;
}

}  // namespace lucent
