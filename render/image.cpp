#include "image.h"

#include <algorithm>
#include <cmath>

namespace lucent {

float srgbEncode(float x) {
  if (!(x > 0.0f)) return 0.0f;  // also NaN
  x = std::min(x, 1.0f);
  return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

int srgbByte(float linear) { return static_cast<int>(std::floor(srgbEncode(linear) * 255.0f + 0.5f)); }

}  // namespace lucent
