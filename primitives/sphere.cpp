#include "sphere.h"

#include "quadratic.h"

namespace lucent {

Sphere::Sphere(const Vec3& center, double radius) : center_(center), radius_(radius) {}

AABB Sphere::bounds() const { return {center_ - Vec3(radius_), center_ + Vec3(radius_)}; }

bool Sphere::roots(const Ray& ray, double& t0, double& t1) const {
  // Precision-improved quadratic (Ray Tracing Gems ch. 7), see quadratic.h.
  return solveDistanceQuadratic(ray.o - center_, ray.d, radius_ * radius_, t0, t1);
}

bool Sphere::intersect(const Ray& ray, Hit& hit) const {
  double t0, t1;
  if (!roots(ray, t0, t1)) return false;
  double t;
  if (ray.tmin < t0 && t0 < ray.tmax)
    t = t0;
  else if (ray.tmin < t1 && t1 < ray.tmax)
    t = t1;
  else
    return false;
  hit.t = t;
  hit.shape = this;
  hit.part = 0;
  return true;
}

void Sphere::crossings(const Ray& ray, CrossingList& out) const {
  double t0, t1;
  out.startsInside = false;
  if (!roots(ray, t0, t1)) return;
  // The line is inside on [t0, t1]; a root exactly at tmin is listed, not counted as behind.
  out.startsInside = t0 < ray.tmin && ray.tmin <= t1;
  const double ts[2] = {t0, t1};
  for (int i = 0; i < 2; ++i) {
    if (ts[i] < ray.tmin || ts[i] > ray.tmax) continue;
    Crossing c;
    c.hit.t = ts[i];
    c.hit.shape = this;
    c.entering = (i == 0);
    out.items.push_back(c);
  }
}

bool Sphere::inside(const Vec3& p) const {
  Vec3 f = p - center_;
  return glm::dot(f, f) < radius_ * radius_;
}

SurfaceInfo Sphere::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo s;
  // Reproject onto the sphere (pbrt-v3 §3.9.4): the point at distance r along the computed
  // direction is on the surface up to gamma(5)·|local|, whatever the error of t was.
  Vec3 local = ray.at(hit.t) - center_;
  double len = glm::length(local);
  if (len > 0.0)
    local *= radius_ / len;
  else
    local = Vec3(0.0, radius_, 0.0);
  s.p = center_ + local;
  s.pError = gamma(5) * glm::abs(local) + gamma(1) * glm::abs(s.p);
  s.ng = glm::normalize(local);
  s.ns = s.ng;
  double phi = std::atan2(local.x, local.z) + kPi;
  double cosTheta = glm::clamp(local.y / radius_, -1.0, 1.0);
  s.uv = Vec2(phi / (2.0 * kPi), std::acos(cosTheta) / kPi);
  s.hasUV = true;
  return s;
}

}  // namespace lucent
