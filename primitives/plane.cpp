#include "plane.h"

#include <stdexcept>

namespace lucent {

void planeTangents(const Vec3& n, Vec3& t1, Vec3& t2) {
  Vec3 h = std::abs(n.y) > std::sqrt(0.5) ? Vec3(0.0, 0.0, -1.0) : Vec3(0.0, 1.0, 0.0);
  t1 = glm::normalize(glm::cross(h, n));
  t2 = glm::cross(n, t1);
}

Plane::Plane(const Vec3& unitNormal, double offset) : n_(unitNormal), offset_(offset) {
  double len = glm::length(unitNormal);
  if (!(len > 0.0) || !std::isfinite(len) || !std::isfinite(offset))
    throw std::invalid_argument("plane: the normal must be a non-zero finite vector");
  n_ = unitNormal / len;  // the spec's normal is unit already; this only removes rounding
  planeTangents(n_, t1_, t2_);
  // Inside is n·p < offset: along an axis (n = ±e_k) that is p_k < offset or p_k > −offset.
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    if (n_[i] != 0.0 || n_[j] != 0.0) continue;
    if (n_[k] > 0.0) bounds_.hi[k] = offset_ / n_[k];
    else bounds_.lo[k] = offset_ / n_[k];
  }
}

bool Plane::intersect(const Ray& ray, Hit& hit) const {
  double denom = glm::dot(n_, ray.d);
  if (denom == 0.0) return false;
  double t = (offset_ - glm::dot(n_, ray.o)) / denom;
  if (!(ray.tmin < t && t < ray.tmax)) return false;
  hit.t = t;
  hit.shape = this;
  hit.part = 0;
  return true;
}

void Plane::crossings(const Ray& ray, CrossingList& out) const {
  double denom = glm::dot(n_, ray.d);
  double dist = glm::dot(n_, ray.o) - offset_;
  if (denom == 0.0) {
    // Parallel: the whole line is on one side (a line in the plane counts as outside).
    out.startsInside = dist < 0.0;
    return;
  }
  double t = -dist / denom;
  bool entering = denom < 0.0;  // moving towards smaller normal·x
  out.startsInside = entering ? t < ray.tmin : t >= ray.tmin;
  if (ray.tmin <= t && t <= ray.tmax) {
    Crossing c;
    c.hit.t = t;
    c.hit.shape = this;
    c.entering = entering;
    out.items.push_back(c);
  }
}

bool Plane::inside(const Vec3& p) const { return glm::dot(n_, p) < offset_; }

SurfaceInfo Plane::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo s;
  // Reproject along the normal, so the error depends on |p| and the offset (the size of
  // the numbers at the hit) and not on how far the ray travelled: the residual of
  // normal·p − offset is then a few roundings of those.
  Vec3 p = ray.at(hit.t);
  p -= (glm::dot(n_, p) - offset_) * n_;
  s.p = p;
  s.pError = gamma(6) * (glm::abs(p) + Vec3(std::abs(offset_)));
  s.ng = n_;
  s.ns = n_;
  s.uv = Vec2(glm::dot(p, t1_), glm::dot(p, t2_));
  s.hasUV = true;
  return s;
}

}  // namespace lucent
