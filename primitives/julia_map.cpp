#include "julia_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucent {

namespace {

// POV-Ray's tolerances: fractal.cpp's bound and exit slack, hcmplx.cpp's step test.
constexpr double kBoundSlack = 1e-7;
constexpr double kStepSlopeMin = 1e-8;
constexpr double kPovEpsilon = 1e-10;

struct Cx {
  double x = 0.0, y = 0.0;
};
Cx mul(Cx a, Cx b) { return {a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x}; }
// POV-Ray leaves the result unset when dividing by 0; 0 here.
Cx div(Cx a, Cx b) {
  const double m = b.x * b.x + b.y * b.y;
  if (m == 0.0) return {};
  return mul(a, {b.x / m, -b.y / m});
}
Cx cxLn(Cx a) { return {std::log(std::sqrt(a.x * a.x + a.y * a.y)), std::atan2(a.y, a.x)}; }
Cx cxSqrt(Cx a) {
  if (a.x == 0.0 && a.y == 0.0) return {};
  const double mag = std::sqrt(std::sqrt(a.x * a.x + a.y * a.y));
  const double th = std::atan2(a.y, a.x) / 2.0;
  return {mag * std::cos(th), mag * std::sin(th)};
}
// arctanh z = ln((1 + z) / (1 − z)) / 2, with POV-Ray's special cases on the axes.
Cx cxAtanh(Cx a) {
  if (a.x == 0.0) return {0.0, std::atan(a.y)};
  if (a.y == 0.0 && std::fabs(a.x) == 1.0) return {};
  if (a.y == 0.0 && std::fabs(a.x) < 1.0) return {std::log((1.0 + a.x) / (1.0 - a.x)) / 2.0, 0.0};
  const Cx l = cxLn(div({1.0 + a.x, a.y}, {1.0 - a.x, -a.y}));
  return {0.5 * l.x, 0.5 * l.y};
}
// arctan z = (i/2) ln((1 − iz) / (1 + iz)), with POV-Ray's special cases on the axes.
Cx cxAtan(Cx a) {
  if (a.x == 0.0 && a.y == 0.0) return {};
  if (a.y == 0.0) return {std::atan(a.x), 0.0};
  if (a.x == 0.0) {
    // POV-Ray works in place: where arctanh leaves its result unset, the input remains.
    const Cx h = std::fabs(a.y) == 1.0 ? Cx{a.y, 0.0} : cxAtanh({a.y, 0.0});
    return {-h.y, h.x};
  }
  const Cx iz{-a.y, a.x};
  const Cx l = cxLn(div({1.0 - iz.x, -iz.y}, {1.0 + iz.x, iz.y}));
  return {-0.5 * l.y, 0.5 * l.x};
}

Cx complexFunction(JuliaFunction f, Cx a, Vec2 e) {
  switch (f) {
    case JuliaFunction::Exp: {
      const double r = std::exp(a.x);
      return {r * std::cos(a.y), r * std::sin(a.y)};
    }
    case JuliaFunction::Ln:
      return cxLn(a);
    case JuliaFunction::Sin:
      return {std::sin(a.x) * std::cosh(a.y), std::cos(a.x) * std::sinh(a.y)};
    case JuliaFunction::Cos:
      return {std::cos(a.x) * std::cosh(a.y), -std::sin(a.x) * std::sinh(a.y)};
    case JuliaFunction::Sinh:
      return {std::sinh(a.x) * std::cos(a.y), std::cosh(a.x) * std::sin(a.y)};
    case JuliaFunction::Cosh:
      return {std::cosh(a.x) * std::cos(a.y), std::sinh(a.x) * std::sin(a.y)};
    case JuliaFunction::Asin: {  // −i ln(iz + √(1 − z²))
      const Cx z2 = mul(a, a);
      const Cx s = cxSqrt({1.0 - z2.x, -z2.y});
      const Cx l = cxLn({s.x - a.y, s.y + a.x});
      return {l.y, -l.x};
    }
    case JuliaFunction::Acos: {  // −i ln(z + √(z² − 1))
      const Cx z2 = mul(a, a);
      const Cx s = cxSqrt({z2.x - 1.0, z2.y});
      const Cx l = cxLn({s.x + a.x, s.y + a.y});
      return {l.y, -l.x};
    }
    case JuliaFunction::Asinh: {  // ln(z + √(z² + 1))
      const Cx z2 = mul(a, a);
      const Cx s = cxSqrt({z2.x + 1.0, z2.y});
      return cxLn({s.x + a.x, s.y + a.y});
    }
    case JuliaFunction::Acosh: {  // ln(z + √(z² − 1))
      const Cx z2 = mul(a, a);
      const Cx s = cxSqrt({z2.x - 1.0, z2.y});
      return cxLn({s.x + a.x, s.y + a.y});
    }
    case JuliaFunction::Tan: {  // (sin 2x, sinh 2y) / (cos 2x + cosh 2y)
      const double den = std::cos(2.0 * a.x) + std::cosh(2.0 * a.y);
      if (den == 0.0) return {};
      return {std::sin(2.0 * a.x) / den, std::sinh(2.0 * a.y) / den};
    }
    case JuliaFunction::Tanh: {  // (sinh 2x, sin 2y) / (cosh 2x + cos 2y)
      const double den = std::cosh(2.0 * a.x) + std::cos(2.0 * a.y);
      if (den == 0.0) return {};
      return {std::sinh(2.0 * a.x) / den, std::sin(2.0 * a.y) / den};
    }
    case JuliaFunction::Atan:
      return cxAtan(a);
    case JuliaFunction::Atanh:
      return cxAtanh(a);
    case JuliaFunction::Pwr: {  // exp(e · ln z), 0 at z = 0, POV-Ray's underflow cut at −690
      if (a.x == 0.0 && a.y == 0.0) return {};
      const Cx t = mul(cxLn(a), {e.x, e.y});
      const double r = t.x < -690.0 ? 0.0 : std::exp(t.x);
      return {r * std::cos(t.y), r * std::sin(t.y)};
    }
    default:
      return a;
  }
}

// The hypercomplex product (commutative).
Vec4 hMul(const Vec4& a, const Vec4& b) {
  return {
      a.x * b.x - a.y * b.y - a.z * b.z + a.w * b.w, a.y * b.x + a.x * b.y - a.w * b.z - a.z * b.w,
      a.z * b.x - a.w * b.y + a.x * b.z - a.y * b.w, a.w * b.x + a.z * b.y + a.y * b.z + a.x * b.w};
}
Vec4 hSqr(const Vec4& q) {
  return {q.x * q.x - q.y * q.y - q.z * q.z + q.w * q.w, 2.0 * (q.x * q.y - q.z * q.w),
          2.0 * (q.z * q.x - q.w * q.y), 2.0 * (q.w * q.x + q.z * q.y)};
}
// 1/q; POV-Ray leaves it unset where the duplex parts vanish; 0 here.
Vec4 hReciprocal(const Vec4& q) {
  const double det = ((q.x - q.w) * (q.x - q.w) + (q.y + q.z) * (q.y + q.z)) *
                     ((q.x + q.w) * (q.x + q.w) + (q.y - q.z) * (q.y - q.z));
  if (det == 0.0) return Vec4(0.0);
  const double mod = glm::dot(q, q);
  const double k = q.x * q.w - q.y * q.z;
  return {(q.x * mod - 2.0 * q.w * k) / det, (-q.y * mod - 2.0 * q.z * k) / det,
          (-q.z * mod - 2.0 * q.y * k) / det, (q.w * mod - 2.0 * q.x * k) / det};
}
// f applied to each duplex part.
Vec4 hFunction(JuliaFunction f, const Vec4& q, Vec2 e) {
  const Cx a = complexFunction(f, {q.x - q.w, q.y + q.z}, e);
  const Cx b = complexFunction(f, {q.x + q.w, q.y - q.z}, e);
  return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y), 0.5 * (a.y - b.y), 0.5 * (b.x - a.x)};
}

// The quaternion product q·a as POV-Ray's distance estimate chains it.
Vec4 qMulLeft(const Vec4& q, const Vec4& a) {
  return {
      a.x * q.x - a.y * q.y - a.z * q.z - a.w * q.w, a.x * q.y + a.y * q.x + a.w * q.z - a.z * q.w,
      a.x * q.z + a.z * q.x + a.y * q.w - a.w * q.y, a.x * q.w + a.w * q.x + a.z * q.y - a.y * q.z};
}

bool isComplexFunction(JuliaFunction f) {
  return f != JuliaFunction::Sqr && f != JuliaFunction::Cube && f != JuliaFunction::Reciprocal;
}

}  // namespace

JuliaMap::JuliaMap(const JuliaParams& p) : p_(p) {
  if (p.algebra == JuliaAlgebra::Quaternion && p.function != JuliaFunction::Sqr &&
      p.function != JuliaFunction::Cube)
    throw std::invalid_argument("a quaternion julia fractal takes sqr and cube only");
  const double len2 = glm::dot(p.slice, p.slice);
  if (!(std::fabs(len2) >= kPovEpsilon)) throw std::invalid_argument("the slice vector is zero");
  if (!(std::fabs(p.slice.w) >= kPovEpsilon))
    throw std::invalid_argument("the slice's t component is zero");
  if (p.maxIteration < 1) throw std::invalid_argument("max-iteration must be 1 or more");
  if (!(p.precision >= 1.0)) throw std::invalid_argument("precision must be 1 or more");
  slice_ = p.slice / std::sqrt(len2);
  maxIteration_ = p.maxIteration;
  minStep_ = 1.0 / p.precision;
  if (p.algebra == JuliaAlgebra::Quaternion) {
    radius_ = std::min(2.0, 1.0 + std::sqrt(glm::dot(p.c, p.c)) + kBoundSlack);
    exitValue_ = radius_ * radius_ + kBoundSlack;
  } else {
    radius_ = 4.0;
    exitValue_ = 16.0;
  }
}

Vec4 JuliaMap::start(const Vec3& p) const {
  const double w = (p_.distance - slice_.x * p.x - slice_.y * p.y - slice_.z * p.z) / slice_.w;
  return {p.x, p.y, p.z, w};
}

Vec4 JuliaMap::step(const Vec4& q) const {
  if (p_.algebra == JuliaAlgebra::Quaternion) {
    const double d = q.y * q.y + q.z * q.z + q.w * q.w, x2 = q.x * q.x;
    if (p_.function == JuliaFunction::Cube) {
      const double k = 3.0 * x2 - d;
      return Vec4(q.x * (x2 - 3.0 * d), q.y * k, q.z * k, q.w * k) + p_.c;
    }
    const double x = 2.0 * q.x;
    return Vec4(x2 - d, x * q.y, x * q.z, x * q.w) + p_.c;
  }
  switch (p_.function) {
    case JuliaFunction::Sqr:
    case JuliaFunction::Cube:
      return hSqr(q) + p_.c;  // POV-Ray's cube iterates q² too
    case JuliaFunction::Reciprocal:
      return hReciprocal(q) + p_.c;
    default:
      return hFunction(p_.function, q, p_.exponent) + p_.c;
  }
}

bool JuliaMap::inside(const Vec3& p, Orbit& orbit) const {
  Vec3 from = p;
  if (p_.algebra == JuliaAlgebra::Hypercomplex && isComplexFunction(p_.function)) from.z = p.y;
  Vec4 q = start(from);
  orbit[0] = q;
  for (int i = 1; i <= maxIteration_; ++i) {
    if (glm::dot(q, q) > exitValue_) return false;
    q = step(q);
    orbit[i] = q;
  }
  return true;
}

bool JuliaMap::insideWithStep(const Vec3& p, const Vec3& dir, double& stepOut, Orbit& orbit) const {
  Vec4 q = start(p);
  orbit[0] = q;
  for (int i = 1; i <= maxIteration_; ++i) {
    const double norm = glm::dot(q, q);
    if (norm > exitValue_) {
      stepOut = stepOutside(orbit, i, norm, dir);
      return false;
    }
    q = step(q);
    orbit[i] = q;
  }
  stepOut = minStep_;
  return true;
}

// Quaternions: the distance estimate (1/k^i)·√(|q|² / |q0·q1···|²)·ln |q|² (k = 2 or 3);
// hypercomplex: |q|² over twice the slope along the ray of the normal of the steps so far,
// when that falls between 1 and 30 smallest steps, else the smallest step.
double JuliaMap::stepOutside(const Orbit& orbit, int escapedAt, double norm,
                             const Vec3& dir) const {
  if (p_.algebra == JuliaAlgebra::Quaternion) {
    const double k = p_.function == JuliaFunction::Cube ? 3.0 : 2.0;
    Vec4 a = orbit[0];
    double scale = 1.0 / k;
    for (int j = 1; j < escapedAt; ++j) {
      a = qMulLeft(orbit[j], a);
      scale /= k;
    }
    return scale * std::sqrt(norm / glm::dot(a, a)) * std::log(norm);
  }
  double slope = glm::dot(normalUpTo(orbit, escapedAt - 1), dir);
  if (slope < -kStepSlopeMin) {
    slope *= -2.0;
    if (norm > minStep_ * slope && norm < 30.0 * minStep_ * slope) return norm / slope;
  }
  return minStep_;
}

Vec3 JuliaMap::normalUpTo(const Orbit& orbit, int n) const {
  if (p_.algebra == JuliaAlgebra::Quaternion) {
    // The rows of the Jacobian of q → qN over (x, y, z), chained step by step (w held),
    // applied to qN; without the constant factors.
    Vec4 rows[3] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    const bool cube = p_.function == JuliaFunction::Cube;
    for (int i = 1; i <= n; ++i) {
      const Vec4& q = orbit[i - 1];
      const double d = q.y * q.y + q.z * q.z + q.w * q.w, x2 = q.x * q.x;
      for (Vec4& r : rows) {
        if (cube) {
          const double t = 2.0 * (r.y * q.y + r.z * q.z + r.w * q.w);
          const double t2 = 6.0 * q.x * r.x - t;
          const double k = 3.0 * x2 - d;
          r = {3.0 * (r.x * (x2 - d) - q.x * t), r.y * k + q.y * t2, r.z * k + q.z * t2,
               r.w * k + q.w * t2};
        } else {
          r = {r.x * q.x - r.y * q.y - r.z * q.z - r.w * q.w, r.x * q.y + q.x * r.y,
               r.x * q.z + q.x * r.z, r.x * q.w + q.x * r.w};
        }
      }
    }
    const Vec4& qn = orbit[n];
    return {glm::dot(rows[0], qn), glm::dot(rows[1], qn), glm::dot(rows[2], qn)};
  }
  // Hypercomplex: the chain of the map's factors over the steps 1 .. n−1, times qn.
  Vec4 a = orbit[0];
  double scale = 1.0;
  for (int i = 1; i < n; ++i) {
    switch (p_.function) {
      case JuliaFunction::Sqr:
        a = hMul(orbit[i], a);
        scale *= 2.0;
        break;
      case JuliaFunction::Cube:
        a = hMul(orbit[i], a);
        break;
      case JuliaFunction::Reciprocal:
        a = hMul(a, -hSqr(hReciprocal(orbit[i])));
        break;
      default:
        a = hMul(hFunction(p_.function, orbit[i], p_.exponent), a);
        break;
    }
  }
  const Vec4 m = orbit[n] * (p_.function == JuliaFunction::Sqr ? 2.0 * scale : 1.0);
  return {a.x * m.x + a.y * m.y + a.z * m.z + a.w * m.w,
          -a.y * m.x + a.x * m.y - a.w * m.z + a.z * m.w,
          -a.z * m.x - a.w * m.y + a.x * m.z + a.y * m.w};
}

}  // namespace lucent
