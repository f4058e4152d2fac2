#include "rainbow.h"

#include "patterns/color_map.h"
#include "sampling.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace lucent {

namespace {

// The top of the map's range POV-Ray draws: the value stays below 1 − 10⁻¹⁰ (its EPSILON).
constexpr double kTopOfMap = 1.0 - 1e-10;

// A number in [0, 1) from the direction's bits: the jitter, the same for the same ray.
double jitterUnit(const Vec3& d, size_t which) {
  uint64_t bits[3];
  std::memcpy(bits, &d, sizeof bits);
  return hashToUnit(bits[0], bits[1], bits[2], which);
}

}  // namespace

RainbowEffect rainbowsAlong(const std::vector<Rainbow>& rainbows, const Vec3& dir, double length) {
  RainbowEffect sum{Color(0.0f), Color(0.0f)};
  int n = 0;
  for (size_t i = 0; i < rainbows.size(); ++i) {
    const Rainbow& r = rainbows[i];
    // The angle around the ring, from up.
    const double x = glm::dot(dir, r.rightAxis);
    double y = glm::dot(dir, r.upAxis);
    const double l = x * x + y * y;
    if (l > 0.0) y /= std::sqrt(l);
    const double around = std::acos(std::clamp(y, -1.0, 1.0));
    const double arc = r.arcAngle * kPi / 360.0, falloff = r.falloffAngle * kPi / 360.0;
    if (around > arc) continue;
    const double toCentre = glm::dot(dir, r.axis);
    if (toCentre < 0.0) continue;
    const double width = r.width * kPi / 180.0;
    const double inner = (r.angle - 0.5 * r.width) * kPi / 180.0;
    double value = (std::acos(std::min(toCentre, 1.0)) - inner) / width;
    if (r.jitter > 0.0) value += (2.0 * jitterUnit(dir, i) - 1.0) * r.jitter;
    if (!(value >= 0.0 && value <= kTopOfMap)) continue;
    const PigmentColor c = lookupColorMapFT(r.map, value);
    // Faded out towards the arc's ends, from falloff on.
    double fade = 0.0;
    if (arc - falloff > 0.0 && around > falloff) {
      const double s = (around - falloff) / (arc - falloff);
      fade = (3.0 - 2.0 * s) * s * s;
    }
    const double transmit = c.ft.transmit;
    double k = std::exp(-length / r.distance);
    k = std::max(k, fade * (1.0 - transmit) + transmit);
    const double ki = 1.0 - k;
    const auto f = static_cast<float>(c.ft.filter * ki);
    sum.keep += static_cast<float>(k) * ((1.0f - f) + f * c.rgb);
    sum.add += static_cast<float>(ki) * c.rgb;
    ++n;
  }
  if (n == 0) return RainbowEffect{};
  const float share = 1.0f / static_cast<float>(n);
  return RainbowEffect{sum.keep * share, sum.add * share};
}

}  // namespace lucent
