// An orthonormal frame whose third axis is a shape's axis: cylinders and cones are
// intersected in it, where their side is x² + y² = r(z)² and their caps are z = const.
#pragma once

#include "math.h"
#include "ray.h"

#include <cmath>

namespace lucent {

struct AxisFrame {
  Vec3 origin{0.0};
  Vec3 u{1.0, 0.0, 0.0}, v{0.0, 1.0, 0.0}, a{0.0, 0.0, 1.0};

  AxisFrame() = default;
  // unitAxis must be unit length. The completion is Duff et al., "Building an Orthonormal
  // Basis, Revisited" (JCGT 6(1), 2017): branch-free except for the sign, and accurate for
  // every axis, unlike cross products with a fixed helper vector.
  AxisFrame(const Vec3& origin_, const Vec3& unitAxis) : origin(origin_), a(unitAxis) {
    double sign = std::copysign(1.0, a.z);
    double p = -1.0 / (sign + a.z);
    double q = a.x * a.y * p;
    u = Vec3(1.0 + sign * a.x * a.x * p, sign * q, -sign * a.x);
    v = Vec3(q, sign + a.y * a.y * p, -a.y);
  }

  Vec3 pointToLocal(const Vec3& p) const {
    Vec3 r = p - origin;
    return {glm::dot(r, u), glm::dot(r, v), glm::dot(r, a)};
  }
  Vec3 vectorToLocal(const Vec3& d) const {
    return {glm::dot(d, u), glm::dot(d, v), glm::dot(d, a)};
  }
  Ray rayToLocal(const Ray& r) const {
    return Ray(pointToLocal(r.o), vectorToLocal(r.d), r.tmin, r.tmax);
  }
  Vec3 vectorToObject(const Vec3& l) const { return l.x * u + l.y * v + l.z * a; }
  Vec3 pointToObject(const Vec3& l) const { return origin + vectorToObject(l); }

  // Error bound of a point carried to the object space and back again (two rotations and
  // a translation each way, a few roundings of the magnitudes involved): what a local
  // reprojection must add so that an offset ray origin, once carried into this frame
  // again, is still on the side it was pushed to.
  Vec3 roundTripError(const Vec3& local, const Vec3& object) const {
    double l1 = std::abs(local.x) + std::abs(local.y) + std::abs(local.z);
    return Vec3(gamma(10) * l1) + gamma(4) * (glm::abs(origin) + glm::abs(object));
  }
};

}  // namespace lucent
