#include "wave_shape.h"

#include <cmath>

namespace lucent {

namespace {
constexpr double kTwoPi = 6.283185307179586476925286766560;  // POV-Ray's TWO_M_PI
}

double cycloidal(double v) {
  // POV-Ray scales the fraction by 50000 and back before taking the sine: kept, since it
  // changes the last bits.
  if (v >= 0.0) return std::sin((v - std::floor(v)) * 50000.0 / 50000.0 * kTwoPi);
  return 0.0 - std::sin((0.0 - (v + std::floor(0.0 - v))) * 50000.0 / 50000.0 * kTwoPi);
}

double triangleWave(double v) {
  const double offset = v >= 0.0 ? v - std::floor(v) : v + 1.0 + std::floor(std::fabs(v));
  return offset >= 0.5 ? 2.0 * (1.0 - offset) : 2.0 * offset;
}

double shapeValue(double raw, const PatternSpec& spec) {
  double value = raw;
  const double frequency = static_cast<float>(spec.frequency);
  if (frequency != 0.0)
    value = std::fmod(value * frequency + static_cast<float>(spec.phase), 1.00001);
  if (value < 0.0) value -= std::floor(value);

  switch (spec.waveShape()) {
    case WaveShape::ramp:
      return value;
    case WaveShape::sine:
      return (1.0 + cycloidal(value)) * 0.5;
    case WaveShape::triangle:
      return triangleWave(value);
    case WaveShape::scallop:
      return std::fabs(cycloidal(value * 0.5));
    case WaveShape::cubic:
      return value * value * ((-2.0 * value) + 3.0);
    case WaveShape::poly:
      return std::pow(value, static_cast<double>(static_cast<float>(spec.exponent)));
  }
  return value;
}

}  // namespace lucent
