// The maps of POV-Ray 3.7's julia_fractal (its quatern.cpp and hcmplx.cpp, taken as facts):
// the iteration q → f(q) + c over 4-D points, the escape test, the step the ray march
// takes from a point, and the normal from an orbit. primitives/julia_fractal.h traces them.
//
// A point p of the 3-D slice is the 4-D point (x, y, z, w) with w = (distance − s·p) / s_t,
// s the unit slice vector. Quaternion: f(q) = q² or q³, escaping when |q|² exceeds
// R² + 1e-7, R = min(2, 1 + |c| + 1e-7). Hypercomplex (the commutative algebra of duplex
// pairs a = (x − w) + i(y + z), b = (x + w) + i(y − z), each mapped by a complex function):
// q², q³ (which POV-Ray iterates as q², with another step), 1/q, or a complex function;
// escaping when |q|² exceeds 16. A point is in the set when it does not escape within
// max_iteration steps.
#pragma once

#include "math.h"

#include <vector>

namespace lucent {

enum class JuliaAlgebra { Quaternion, Hypercomplex };
// POV-Ray's functions; quaternions take Sqr and Cube only.
enum class JuliaFunction {
  Sqr,
  Cube,
  Reciprocal,
  Exp,
  Ln,
  Sin,
  Asin,
  Cos,
  Acos,
  Tan,
  Atan,
  Sinh,
  Asinh,
  Cosh,
  Acosh,
  Tanh,
  Atanh,
  Pwr
};

struct JuliaParams {
  Vec4 c{1.0, 0.0, 0.0, 0.0};  // POV-Ray's Julia parameter (x, y, z, t)
  JuliaAlgebra algebra = JuliaAlgebra::Quaternion;
  JuliaFunction function = JuliaFunction::Sqr;
  Vec2 exponent{0.0};  // pwr's complex exponent
  int maxIteration = 20;
  double precision = 20.0;         // the smallest step of the march is 1 / precision
  Vec4 slice{0.0, 0.0, 0.0, 1.0};  // any length, t not 0 (made unit)
  double distance = 0.0;           // of the slice from the origin (not scaled with it)
};

class JuliaMap {
 public:
  // Throws std::invalid_argument for a quaternion function other than Sqr and Cube, a
  // slice whose length or t is below 1e-10 (POV-Ray's errors), max_iteration below 1 or
  // precision below 1.
  explicit JuliaMap(const JuliaParams& p);

  // The orbit q0 .. qN of the last test (N = maxIteration); sized by the caller.
  using Orbit = std::vector<Vec4>;

  // POV-Ray's inside test (Iteration): true when the point does not escape. For the
  // hypercomplex functions POV-Ray 3.7 starts this test from (x, y, y) (its z read from y;
  // fixed after 3.7), and so does this.
  bool inside(const Vec3& p, Orbit& orbit) const;
  // POV-Ray's test with a step (D_Iteration), from the true (x, y, z): whether the point is
  // in the set, and in `step` how far the march may go from it along the unit `dir`
  // (a distance estimate outside, 1 / precision inside).
  bool insideWithStep(const Vec3& p, const Vec3& dir, double& step, Orbit& orbit) const;
  // POV-Ray's normal (not unit) from the orbit of a point in the set (all N steps).
  Vec3 normal(const Orbit& orbit) const { return normalUpTo(orbit, maxIteration_); }

  double radius() const { return radius_; }  // of the bounding sphere about the origin
  double minStep() const { return minStep_; }
  int maxIteration() const { return maxIteration_; }

 private:
  Vec4 start(const Vec3& p) const;
  Vec4 step(const Vec4& q) const;  // f(q) + c
  Vec3 normalUpTo(const Orbit& orbit, int n) const;
  double stepOutside(const Orbit& orbit, int escapedAt, double norm, const Vec3& dir) const;

  JuliaParams p_;
  Vec4 slice_;  // unit
  int maxIteration_;
  double minStep_, radius_, exitValue_;
};

}  // namespace lucent
