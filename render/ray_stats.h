// Ray counts by kind, for `lucent render --stats`. Each tile counts into its own copy (in
// its thread's TraceContext, trace_context.h) and the copies are summed, so counting never
// makes threads wait for each other.
#pragma once

#include "primitives/test_counts.h"

#include <cstdint>

namespace lucent {

struct RayStats {
  uint64_t primary = 0;
  uint64_t shadow = 0;           // one per light sample tested (a shadow ray that crosses
                                 // transparent surfaces is still one ray)
  uint64_t reflected = 0;        // mirror rays, including total internal reflection
  uint64_t refracted = 0;        // transmitted rays, bent or straight through
  uint64_t queries = 0;          // searches of the world (closest hit or any hit)
  uint64_t shadowCacheHits = 0;  // shadow rays blocked by their light's cached last blocker
  TestCounts tests;              // intersection tests by kind of shape

  uint64_t rays() const { return primary + shadow + reflected + refracted; }

  RayStats& operator+=(const RayStats& o) {
    primary += o.primary;
    shadow += o.shadow;
    reflected += o.reflected;
    refracted += o.refracted;
    queries += o.queries;
    shadowCacheHits += o.shadowCacheHits;
    tests += o.tests;
    return *this;
  }
};

}  // namespace lucent
