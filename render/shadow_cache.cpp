#include "shadow_cache.h"

#include <atomic>

namespace lucent {

uint64_t newShadowCacheOwner() {
  static std::atomic<uint64_t> next{1};
  return next.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace lucent
