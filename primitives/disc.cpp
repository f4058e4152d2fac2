#include "disc.h"

#include "plane.h"
#include "span.h"

#include <stdexcept>

namespace lucent {

Disc::Disc(const Vec3& center, const Vec3& unitNormal, double radius, double innerRadius)
    : center_(center), n_(unitNormal), radius_(radius), inner_(innerRadius) {
  double len = glm::length(unitNormal);
  if (!(len > 0.0) || !std::isfinite(len) || !isFinite(center))
    throw std::invalid_argument("disc: the normal must be a non-zero finite vector");
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw std::invalid_argument("disc: the radius must be a positive finite number");
  if (!(innerRadius >= 0.0 && innerRadius < radius))
    throw std::invalid_argument("disc: inner-radius must be at least 0 and less than radius");
  n_ = unitNormal / len;
  planeTangents(n_, t1_, t2_);
}

AABB Disc::bounds() const {
  // Extent of a circle of radius r with unit normal n along axis i: r·sqrt(1 − n_i²).
  Vec3 e = radius_ * glm::sqrt(glm::max(Vec3(0.0), Vec3(1.0) - n_ * n_));
  return {center_ - e, center_ + e};
}

bool Disc::root(const Ray& ray, double& t) const {
  double denom = glm::dot(n_, ray.d);
  if (denom == 0.0) return false;
  t = glm::dot(n_, center_ - ray.o) / denom;
  if (!std::isfinite(t)) return false;
  Vec3 r = ray.at(t) - center_;
  r -= glm::dot(r, n_) * n_;  // remove the ray equation's error across the plane
  double d2 = glm::dot(r, r);
  return d2 <= radius_ * radius_ && d2 >= inner_ * inner_;
}

bool Disc::intersect(const Ray& ray, Hit& hit) const {
  SurfaceRoot r;
  return root(ray, r.t) && intersectRoots(&r, 1, ray, this, hit);
}

void Disc::crossings(const Ray& ray, CrossingList& out) const {
  SurfaceRoot r;
  int n = root(ray, r.t) ? 1 : 0;
  crossingsOfRoots(&r, n, ray, this, out);
}

SurfaceInfo Disc::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo s;
  // Reproject onto the plane (as Plane does): error of the size of |p| and |center|.
  Vec3 r = ray.at(hit.t) - center_;
  r -= glm::dot(r, n_) * n_;
  s.p = center_ + r;
  s.pError = gamma(6) * (glm::abs(r) + glm::abs(center_)) + gamma(1) * glm::abs(s.p);
  s.ng = n_;
  s.ns = n_;
  s.uv = Vec2(glm::dot(r, t1_), glm::dot(r, t2_));
  s.hasUV = true;
  return s;
}

}  // namespace lucent
