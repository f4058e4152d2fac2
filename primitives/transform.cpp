#include "transform.h"

namespace lucent {

std::optional<Transform> Transform::fromMatrix(const Mat4& m) {
  // glm is column-major: m[col][row]. The bottom row must be (0 0 0 1) for an affine map.
  if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0) return std::nullopt;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return std::nullopt;
  Mat3 linear(m);
  double det = glm::determinant(linear);
  // Singular relative to the matrix's own axes: |det| is at most the product of the column
  // lengths (Hadamard), equal for orthogonal axes, so their ratio says how flat the map is
  // whatever its scales. A scale of 0.01 on two axes and 1e5 on the third (POV-Ray's way of
  // making a pattern constant along an axis) is no flatter than the identity.
  const double axes = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
  if (!(axes > 0.0) || !(std::abs(det) > 1e-12 * axes)) return std::nullopt;

  Transform t;
  t.worldFromObject_ = m;
  t.objectFromWorld_ = glm::inverse(m);
  t.normalToWorld_ = glm::transpose(glm::inverse(linear));
  t.identity_ = (m == Mat4(1.0));
  t.flips_ = det < 0.0;
  return t;
}

Vec3 Transform::errorToWorld(const Vec3& p, const Vec3& pErr) const {
  const Mat4& m = worldFromObject_;
  Vec3 err(0.0);
  for (int r = 0; r < 3; ++r) {
    double fromP = 0.0, fromErr = 0.0;
    for (int c = 0; c < 3; ++c) {
      fromP += std::abs(m[c][r] * p[c]);
      fromErr += std::abs(m[c][r]) * pErr[c];
    }
    fromP += std::abs(m[3][r]);
    err[r] = (gamma(3) + 1.0) * fromErr + gamma(3) * fromP;
  }
  return err;
}

Transform Transform::followedBy(const Transform& then) const {
  // Composition of two invertible affine maps is invertible; keep the tested inverses.
  Transform t;
  t.worldFromObject_ = then.worldFromObject_ * worldFromObject_;
  t.objectFromWorld_ = objectFromWorld_ * then.objectFromWorld_;
  t.normalToWorld_ = then.normalToWorld_ * normalToWorld_;
  t.identity_ = identity_ && then.identity_;
  t.flips_ = flips_ != then.flips_;
  return t;
}

}  // namespace lucent
