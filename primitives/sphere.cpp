#include "sphere.h"
#include "pov_uv.h"

#include "span.h"

#include <stdexcept>

namespace lucent {

Sphere::Sphere(const Vec3& center, double radius) : center_(center), radius_(radius) {
  if (!(radius > 0.0) || !std::isfinite(radius) || !isFinite(center))
    throw std::invalid_argument("sphere: the radius must be a positive finite number");
}

AABB Sphere::bounds() const { return {center_ - Vec3(radius_), center_ + Vec3(radius_)}; }

bool Sphere::span(const Ray& ray, Span& out) const {
  return sphereRoots(center_, radius_ * radius_, ray, out.tIn, out.tOut);
}

bool Sphere::intersect(const Ray& ray, Hit& hit) const {
  double t;
  if (!sphereHitDistance(center_, radius_ * radius_, ray, t)) return false;
  hit = Hit();
  hit.t = t;
  hit.shape = this;
  return true;
}

void Sphere::crossings(const Ray& ray, CrossingList& out) const {
  Span s;
  if (!span(ray, s)) s = Span();
  crossingsOfSpan(s, ray, this, out);
}

bool Sphere::inside(const Vec3& p) const {
  Vec3 f = p - center_;
  return glm::dot(f, f) < radius_ * radius_;
}

SurfaceInfo Sphere::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo s;
  // Reproject onto the sphere (pbrt-v3 §3.9.4): the point at distance r along the computed
  // direction is on the surface up to gamma(5)·|local|, whatever the error of t was.
  // Relative to the centre before adding t·d: for a sphere far from the origin,
  // ray.at(t) − center would round the hit point at the origin's distance first.
  Vec3 local = (ray.o - center_) + hit.t * ray.d;
  double len = glm::length(local);
  if (len > 0.0) local *= radius_ / len;
  else local = Vec3(0.0, radius_, 0.0);
  s.p = center_ + local;
  s.pError = gamma(5) * glm::abs(local) + gamma(1) * glm::abs(s.p);
  s.ng = glm::normalize(local);
  s.ns = s.ng;
  double phi = std::atan2(local.x, local.z) + kPi;
  double cosTheta = glm::clamp(local.y / radius_, -1.0, 1.0);
  s.uv = Vec2(phi / (2.0 * kPi), 1.0 - std::acos(cosTheta) / kPi);
  s.hasUV = true;
  return s;
}

// POV-Ray's sphere: the longitude of the direction from the centre about +y from +x, and
// 0.5 + its latitude over pi, in POV-Ray's space (z negated).
bool Sphere::povUV(const SurfaceInfo& s, const Hit& /*hit*/, Vec2& uv) const {
  uv = povSphereUV(s.p - center_);
  return true;
}

}  // namespace lucent
