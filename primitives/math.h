// Math vocabulary shared by every Lucent library: double-precision geometry, float colours.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <limits>

namespace lucent {

// Geometry is double precision: POV-Ray's scenes span 1e-4 to 1e5 units and we promise
// to be more accurate than POV-Ray there (docs/accuracy.md). Colours are float, as in POV-Ray.
using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;
using Vec4 = glm::dvec4;
using Mat3 = glm::dmat3;
using Mat4 = glm::dmat4;
using Color = glm::vec3;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
constexpr double kMachineEps = std::numeric_limits<double>::epsilon() * 0.5;

// pbrt's gamma(n): a bound on the relative rounding error of n chained floating-point
// operations (Pharr, Jakob, Humphreys, "Physically Based Rendering", 3rd ed., 3.9.1).
constexpr double gamma(int n) { return (n * kMachineEps) / (1 - n * kMachineEps); }

inline double radians(double degrees) { return degrees * (kPi / 180.0); }

inline double maxComponent(const Vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }
inline float maxComponent(const Color& c) { return std::max(c.r, std::max(c.g, c.b)); }
// Not black: a negative component counts (POV-Ray's transmit -1 subtracts what is behind).
inline bool anyNonZero(const Color& c) { return c.r != 0.0f || c.g != 0.0f || c.b != 0.0f; }

inline bool isFinite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace lucent
