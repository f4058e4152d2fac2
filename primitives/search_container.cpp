#include "search_container.h"

#include "quadratic.h"

#include <stdexcept>
#include <string>

namespace lucent {

AABB containerBounds(const IsosurfaceContainer& c, const char* shape) {
  if (c.kind == IsosurfaceContainer::Box) {
    if (!(isFinite(c.min) && isFinite(c.max) && c.min.x < c.max.x && c.min.y < c.max.y &&
          c.min.z < c.max.z))
      throw std::invalid_argument(std::string(shape) + ": the container box must have min < max");
    return AABB(c.min, c.max);
  }
  if (!(c.radius > 0.0 && std::isfinite(c.radius)) || !isFinite(c.center))
    throw std::invalid_argument(std::string(shape) + ": the container sphere needs a radius > 0");
  return AABB(c.center - Vec3(c.radius), c.center + Vec3(c.radius));
}

bool containerSpan(const IsosurfaceContainer& c, const Ray& ray, double& t0, double& t1) {
  if (c.kind == IsosurfaceContainer::Sphere)
    return solveDistanceQuadratic(ray.o - c.center, ray.d, c.radius * c.radius, t0, t1) && t0 < t1;
  t0 = -kInf;
  t1 = kInf;
  for (int i = 0; i < 3; ++i) {
    if (ray.d[i] == 0.0) {
      if (ray.o[i] < c.min[i] || ray.o[i] > c.max[i]) return false;
      continue;
    }
    const double inv = 1.0 / ray.d[i];
    double a = (c.min[i] - ray.o[i]) * inv, b = (c.max[i] - ray.o[i]) * inv;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t0 < t1;
}

}  // namespace lucent
