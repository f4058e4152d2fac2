// POV-Ray's space and transforms, and how the importer carries them into Lucent's.
//
// POV-Ray's space is left-handed (x right, y up, z into the screen); Lucent's is
// right-handed. The importer negates z of everything (docs/povray-import.md, "Space"):
// points and vectors become S·p with S = diag(1, 1, -1), and a transform M of POV-Ray's
// space becomes S·M·S. A scene's numbers then map one to one and the image is POV-Ray's,
// not its mirror. Everything in sdl/ computes in POV-Ray's own coordinates until this last
// step, so `vrotate`, `vcross` and `trace()` answer as POV-Ray's do.
#pragma once

#include "primitives/math.h"

#include <array>

namespace lucent::sdl {

// S·p: a point or a direction of POV-Ray's space in Lucent's.
inline Vec3 lucentFromPov(const Vec3& v) { return Vec3(v.x, v.y, -v.z); }

// A transform of POV-Ray's space, as its `translate`, `rotate`, `scale`, `matrix`,
// `transform { ... }` and `inverse` build it: each one written after the others applies
// after them. Held as a 4x4 matrix acting on column vectors (p' = M·p).
class PovTransform {
 public:
  PovTransform() = default;
  explicit PovTransform(const Mat4& m) : m_(m) {}

  // The single transforms, as POV-Ray computes them.
  static PovTransform translation(const Vec3& v);
  // `rotate <a, b, c>`: degrees about x, then about y, then about z, each by the
  // right-hand rule of the numbers (rotate z*90 takes +x to +y, rotate y*90 takes +x to -z).
  static PovTransform rotation(const Vec3& degrees);
  static PovTransform scaling(const Vec3& v);
  // `matrix <m00, m01, m02, m10, m11, m12, m20, m21, m22, tx, ty, tz>`: POV-Ray multiplies
  // row vectors, x'_k = sum_i x_i m_ik + t_k.
  static PovTransform matrix(const std::array<double, 12>& m);

  // `then` applied after this one (what writing it next in a block does).
  PovTransform then(const PovTransform& next) const { return PovTransform(next.m_ * m_); }
  PovTransform& translate(const Vec3& v) { return *this = then(translation(v)); }
  PovTransform& rotate(const Vec3& degrees) { return *this = then(rotation(degrees)); }
  PovTransform& scale(const Vec3& v) { return *this = then(scaling(v)); }
  // `transform { ... inverse }`
  PovTransform inverse() const { return PovTransform(glm::inverse(m_)); }

  const Mat4& povMatrix() const { return m_; }
  bool isIdentity() const { return m_ == Mat4(1.0); }
  Vec3 point(const Vec3& p) const { return Vec3(m_ * Vec4(p, 1.0)); }
  Vec3 vector(const Vec3& v) const { return Vec3(m_ * Vec4(v, 0.0)); }

  // The same transform in Lucent's space: S·M·S.
  Mat4 lucentMatrix() const;

 private:
  Mat4 m_{1.0};
};

}  // namespace lucent::sdl
