// Deterministic sample positions: the Halton (2,3) sequence for sub-pixel offsets, and a
// hash of integer coordinates for the few places that need "random" numbers (area-light
// jitter). Nothing here has state, so an image never depends on threads or run order.
#pragma once

#include "primitives/math.h"

#include <cstdint>

namespace lucent {

// The radical inverse of `index` in `base` (van der Corput): the digits mirrored about
// the radix point. Halton point k in bases (2, 3) is (radicalInverse(2,k), radicalInverse(3,k)).
inline double radicalInverse(uint32_t base, uint64_t index) {
  double inverse = 1.0 / base, factor = inverse, result = 0.0;
  while (index > 0) {
    result += static_cast<double>(index % base) * factor;
    index /= base;
    factor *= inverse;
  }
  return result;
}

// Offset inside the pixel of sample `k` of `count`: the pixel centre for a single sample,
// otherwise Halton (2,3) points 1..count (point 0 is the pixel's corner (0,0), which
// would sample the same edge in every pixel). Every pixel uses the same offsets.
inline Vec2 pixelSampleOffset(int k, int count) {
  if (count <= 1) return Vec2(0.5, 0.5);
  uint64_t index = static_cast<uint64_t>(k) + 1;
  return Vec2(radicalInverse(2, index), radicalInverse(3, index));
}

// A lens position for sample k (bases 5 and 7, independent of the pixel offset's 2 and 3).
inline Vec2 lensSample(int k, int count) {
  if (count <= 1) return Vec2(0.5, 0.5);
  uint64_t index = static_cast<uint64_t>(k) + 1;
  return Vec2(radicalInverse(5, index), radicalInverse(7, index));
}

// SplitMix64's finaliser (Steele, Lea, Flood 2014): a bijective 64-bit mix.
inline uint64_t mixBits(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// A number in [0, 1) that depends only on the integers given.
inline double hashToUnit(uint64_t a, uint64_t b, uint64_t c, uint64_t d) {
  uint64_t h = mixBits(a + 0x9e3779b97f4a7c15ULL);
  h = mixBits(h ^ (b + 0x9e3779b97f4a7c15ULL));
  h = mixBits(h ^ (c + 0x9e3779b97f4a7c15ULL));
  h = mixBits(h ^ (d + 0x9e3779b97f4a7c15ULL));
  return static_cast<double>(h >> 11) * 0x1.0p-53;
}

}  // namespace lucent
