// An affine transform kept with its inverse and its normal matrix, computed once.
#pragma once

#include "aabb.h"
#include "math.h"
#include "ray.h"

#include <optional>

namespace lucent {

// Named destination-from-source, so products read right-to-left (pbrt):
// worldFromObject * p carries an object-space point into the world.
class Transform {
 public:
  Transform() = default;  // identity

  // Nullopt when m is singular (or not affine, or not finite): such a transform would
  // flatten the shape and has no inverse for rays.
  static std::optional<Transform> fromMatrix(const Mat4& worldFromObject);

  const Mat4& worldFromObject() const { return worldFromObject_; }
  const Mat4& objectFromWorld() const { return objectFromWorld_; }
  // Inverse-transpose of the linear part: carries object-space normals into the world.
  const Mat3& normalToWorld() const { return normalToWorld_; }
  bool isIdentity() const { return identity_; }
  // Does the transform mirror space (negative determinant)?
  bool flipsHandedness() const { return flips_; }

  Vec3 pointToWorld(const Vec3& p) const { return Vec3(worldFromObject_ * Vec4(p, 1.0)); }
  Vec3 vectorToWorld(const Vec3& v) const { return Mat3(worldFromObject_) * v; }
  Vec3 pointToObject(const Vec3& p) const { return Vec3(objectFromWorld_ * Vec4(p, 1.0)); }
  Vec3 vectorToObject(const Vec3& v) const { return Mat3(objectFromWorld_) * v; }
  // Unit normal in the world.
  Vec3 normalToWorld(const Vec3& n) const { return glm::normalize(normalToWorld_ * n); }

  // The same ray in object space: the direction is not renormalised, so t is unchanged.
  Ray rayToObject(const Ray& r) const {
    return Ray(pointToObject(r.o), vectorToObject(r.d), r.tmin, r.tmax);
  }

  // Absolute error bound of a world point computed from object point p whose own error
  // bound is pErr (pbrt 3.9.4, "Transforming points").
  Vec3 errorToWorld(const Vec3& p, const Vec3& pErr) const;

  // A then B: the transform that applies *this first, then `then`.
  Transform followedBy(const Transform& then) const;

 private:
  Mat4 worldFromObject_{1.0};
  Mat4 objectFromWorld_{1.0};
  Mat3 normalToWorld_{1.0};
  bool identity_ = true;
  bool flips_ = false;
};

}  // namespace lucent
