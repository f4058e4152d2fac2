// Deterministic sample positions: the Halton (2,3) sequence for sub-pixel offsets, a
// scrambled (0,2)-sequence for lens positions, and a hash of integer coordinates for the
// few places that need "random" numbers (area-light jitter). Nothing here has state, so
// an image never depends on threads or run order.
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

// Kensler's hash-based permutation of [0, count) ("Correlated Multi-Jittered Sampling",
// Pixar Technical Memo 13-01, 2013): element i of the permutation selected by `seed`.
inline uint32_t permuteIndex(uint32_t i, uint32_t count, uint32_t seed) {
  uint32_t w = count - 1;
  w |= w >> 1;
  w |= w >> 2;
  w |= w >> 4;
  w |= w >> 8;
  w |= w >> 16;
  do {  // cycle-walk until the hash lands inside [0, count)
    i ^= seed;
    i *= 0xe170893du;
    i ^= seed >> 16;
    i ^= (i & w) >> 4;
    i ^= seed >> 8;
    i *= 0x0929eb3fu;
    i ^= seed >> 23;
    i ^= (i & w) >> 1;
    i *= 1u | seed >> 27;
    i *= 0x6935fa69u;
    i ^= (i & w) >> 11;
    i *= 0x74dcb303u;
    i ^= (i & w) >> 2;
    i *= 0x9e501cc3u;
    i ^= (i & w) >> 2;
    i *= 0xc860a3dfu;
    i &= w;
    i ^= i >> 5;
  } while (i >= count);
  return (i + seed) % count;
}

// Owen's nested uniform scramble of a base-2 fraction (32 bits), hashed as in Burley,
// "Practical Hash-based Owen Scrambling" (JCGT 9(4), 2020): each digit is flipped or not
// depending on all the digits before it, which keeps a net a net but, unlike a plain XOR,
// also breaks up the lattice lines of the unscrambled points.
inline uint32_t reverseBits(uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}
inline uint32_t owenScramble(uint32_t x, uint32_t seed) {
  x = reverseBits(x);
  // Laine & Karras's permutation: each bit depends only on the bits below it.
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return reverseBits(x);
}

// Point i of the Sobol' (0,2)-sequence in base 2, Owen-scrambled with two seeds (Kollig &
// Keller, "Efficient Multidimensional Sampling", 2002, for the generator matrices): the
// first 2^m points put exactly one point in each of the 2^m elementary boxes of any shape
// (2^a x 2^(m-a) grids), scrambled or not.
inline Vec2 sobol02(uint32_t i, uint32_t seedX, uint32_t seedY) {
  uint32_t x = 0, y = 0;
  for (uint32_t v = 1u << 31, u = 1u << 31; i != 0; i >>= 1, v >>= 1, u ^= u >> 1)
    if (i & 1u) {
      x ^= v;  // first dimension: van der Corput (bit reversal)
      y ^= u;  // second: Sobol's generator matrix (Pascal's triangle mod 2)
    }
  return Vec2(owenScramble(x, seedX) * 0x1.0p-32, owenScramble(y, seedY) * 0x1.0p-32);
}

// The lens position of camera sample k of `count` in pixel (x, y), in [0,1)^2. One sample
// uses the lens centre (like the pixel centre). Otherwise each pixel gets the first `count`
// points of a (0,2)-sequence, Owen-scrambled per pixel and in an order shuffled per pixel:
// - the points are stratified on the lens (count = 4^m: one per cell of a 2^m x 2^m grid),
//   so depth of field converges with `samples`;
// - the shuffle pairs lens positions with the Halton sub-pixel offsets at random instead
//   of in lockstep, and the scramble gives neighbouring pixels different lens patterns,
//   so out-of-focus regions show fine noise instead of `count` ghost copies;
// - everything depends only on (x, y, k, count): images stay bit-identical across threads.
inline Vec2 lensSample(int x, int y, int k, int count) {
  if (count <= 1) return Vec2(0.5, 0.5);
  uint64_t h = mixBits((static_cast<uint64_t>(static_cast<uint32_t>(x)) << 32) ^
                       static_cast<uint32_t>(y) ^ 0x6c656e73ULL /* "lens" */);
  uint32_t index = permuteIndex(static_cast<uint32_t>(k), static_cast<uint32_t>(count),
                                static_cast<uint32_t>(h));
  uint64_t s = mixBits(h);
  return sobol02(index, static_cast<uint32_t>(s), static_cast<uint32_t>(s >> 32));
}

}  // namespace lucent
