// srgbByte looks the byte up in a table of the floats where it steps up; it must be the
// formula's answer for every float. Checked around every step (where a wrong table
// would differ) and on many floats between them.
#include "render/image.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

using namespace lucent;

namespace {

float fromBits(uint32_t b) {
  float f;
  std::memcpy(&f, &b, 4);
  return f;
}
uint32_t bitsOf(float f) {
  uint32_t b;
  std::memcpy(&b, &f, 4);
  return b;
}

}  // namespace

TEST_CASE("srgbByte equals the formula around every step and between them",
          "[render][image][srgb]") {
  // Walk up from 0 float by float near each step: find the step by the formula, then
  // compare a window of floats on both sides.
  int steps = 0;
  uint32_t b = 0;
  const uint32_t one = bitsOf(1.0f);
  for (int value = 1; value < 256; ++value) {
    // Bisect for the first float whose formula byte reaches `value`.
    uint32_t lo = b, hi = one;
    while (hi - lo > 1) {
      uint32_t mid = lo + (hi - lo) / 2;
      (srgbByteFormula(fromBits(mid)) >= value ? hi : lo) = mid;
    }
    for (uint32_t k = hi > 3000 ? hi - 3000 : 0; k <= std::min(hi + 3000, one); ++k)
      REQUIRE(srgbByte(fromBits(k)) == srgbByteFormula(fromBits(k)));
    REQUIRE(srgbByte(fromBits(hi)) == value);
    REQUIRE(srgbByte(fromBits(hi - 1)) == value - 1);
    ++steps;
    b = hi;
  }
  CHECK(steps == 255);
  std::mt19937 rng(3);
  std::uniform_int_distribution<uint32_t> anyBits(0, bitsOf(1.5f));
  for (int i = 0; i < 2000000; ++i) {
    const float x = fromBits(anyBits(rng));
    REQUIRE(srgbByte(x) == srgbByteFormula(x));
  }
  CHECK(srgbByte(0.0f) == 0);
  CHECK(srgbByte(-1.0f) == 0);
  CHECK(srgbByte(std::numeric_limits<float>::quiet_NaN()) == 0);
  CHECK(srgbByte(1.0f) == 255);
  CHECK(srgbByte(std::numeric_limits<float>::infinity()) == 255);
  CHECK(srgbByte(0.5f) == 188);  // POV-Ray's value for rgb 0.5 (povray-notes, gamma)
}
