// How much of a long randomized test to run. All of it in the Release build; an eighth under
// the sanitizers (scripts/test's second pass), which look for memory errors and undefined
// behaviour: the same code paths on fewer random rays, where the Release pass has already
// held every one of the full count to its bound.
#pragma once

#include "images/address_sanitizer.h"

namespace lucent::test {
#ifdef LUCENT_ASAN
inline constexpr double kRandomEffort = 0.125;
inline constexpr bool kSanitizerPass = true;
#else
inline constexpr double kRandomEffort = 1.0;
inline constexpr bool kSanitizerPass = false;
#endif

// n scaled by kRandomEffort, at least 1.
inline constexpr int effortCount(int n) {
  return n * kRandomEffort < 1.0 ? 1 : static_cast<int>(n * kRandomEffort);
}
}  // namespace lucent::test
