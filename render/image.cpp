#include "image.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace lucent {

float srgbEncode(float x) {
  if (!(x > 0.0f)) return 0.0f;  // also NaN
  x = std::min(x, 1.0f);
  return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

namespace {

int srgbByteByFormula(float linear) {
  return static_cast<int>(std::floor(srgbEncode(linear) * 255.0f + 0.5f));
}

// The formula's byte above the linear segment, by table: the floats of [2^-9, 1) fall in
// buckets of equal exponent and top kBits mantissa bits, and within a bucket the byte
// rises at most once (a bucket spans well under a byte's step), so it is the byte at the
// bucket's first float, plus one from the float where it steps up, if it does. Both are
// found with the formula itself, so the answer is the formula's for every float (the
// formula never decreases as the float grows: checked for every float of [0, 1], and
// around every step by tests/render/srgb_byte_test.cpp). No pow per channel.
class SrgbTable {
 public:
  static constexpr int kBits = 8;
  static constexpr int kLowExponent = 127 - 9;  // 2^-9 < 0.0031308, the segments' joint
  static constexpr int kBuckets = 9 << kBits;   // exponents 2^-9 .. 2^-1

  SrgbTable() {
    for (uint32_t k = 0; k < kBuckets; ++k) {
      const uint32_t first = (uint32_t(kLowExponent) << 23) + (k << (23 - kBits));
      const uint32_t last = first + (1u << (23 - kBits)) - 1;
      base_[k] = static_cast<uint8_t>(srgbByteByFormula(floatOf(first)));
      step_[k] = ~0u;  // no step: no float's bits reach it
      if (srgbByteByFormula(floatOf(last)) != base_[k]) {
        uint32_t lo = first, hi = last;  // byte(lo) = base < byte(hi)
        while (hi - lo > 1) {
          const uint32_t mid = lo + (hi - lo) / 2;
          (srgbByteByFormula(floatOf(mid)) > base_[k] ? hi : lo) = mid;
        }
        step_[k] = hi;
      }
    }
  }
  // For 2^-9 <= x < 1.
  int byteOf(float x) const {
    uint32_t bits;
    std::memcpy(&bits, &x, 4);
    const uint32_t k = (bits >> (23 - kBits)) - (uint32_t(kLowExponent) << kBits);
    return base_[k] + int(bits >= step_[k]);
  }

 private:
  static float floatOf(uint32_t bits) {
    float f;
    std::memcpy(&f, &bits, 4);
    return f;
  }
  uint8_t base_[kBuckets];
  uint32_t step_[kBuckets];
};

}  // namespace

int srgbByte(float linear) {
  static const SrgbTable table;
  if (!(linear > 0.0f)) return 0;  // also NaN
  if (linear >= 1.0f) return 255;
  if (linear < 0.001953125f) return srgbByteByFormula(linear);  // 2^-9: the linear segment, no pow
  return table.byteOf(linear);
}

int srgbByteFormula(float linear) { return srgbByteByFormula(linear); }

}  // namespace lucent
