// POV-Ray 3.7's random numbers (rand() and seed()): each stream is a 32-bit linear
// congruential generator, next = next * 1812433253 + 12345 (mod 2^32), giving
// next / (2^32 - 1). Matching it puts randomly scattered objects where POV-Ray puts them.
#pragma once

#include <cstdint>

namespace lucent::sdl {

inline double povRand(std::uint32_t& state) {
  state = state * 1812433253u + 12345u;
  return static_cast<double>(state) / 4294967295.0;
}

}  // namespace lucent::sdl
