#include "pov_space.h"

#include <cmath>

namespace lucent::sdl {

PovTransform PovTransform::translation(const Vec3& v) {
  Mat4 m(1.0);
  m[3] = Vec4(v, 1.0);
  return PovTransform(m);
}

PovTransform PovTransform::rotation(const Vec3& degrees) {
  // The matrices of the right-hand rule about each axis, applied x first.
  auto about = [](int axis, double deg) {
    const double a = radians(deg), c = std::cos(a), s = std::sin(a);
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;  // the plane turned: i towards j
    Mat4 m(1.0);
    m[i][i] = c;
    m[i][j] = s;
    m[j][i] = -s;
    m[j][j] = c;
    return m;
  };
  return PovTransform(about(2, degrees.z) * about(1, degrees.y) * about(0, degrees.x));
}

PovTransform PovTransform::scaling(const Vec3& v) {
  Mat4 m(1.0);
  m[0][0] = v.x;
  m[1][1] = v.y;
  m[2][2] = v.z;
  return PovTransform(m);
}

PovTransform PovTransform::matrix(const std::array<double, 12>& v) {
  // Row i of POV-Ray's 3x3 part is what input axis i becomes: column i of ours.
  Mat4 m(1.0);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) m[i][k] = v[3 * i + k];
  m[3] = Vec4(v[9], v[10], v[11], 1.0);
  return PovTransform(m);
}

Mat4 PovTransform::lucentMatrix() const {
  Mat4 s(1.0);
  s[2][2] = -1.0;
  return s * m_ * s;
}

}  // namespace lucent::sdl
