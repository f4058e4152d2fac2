#include "render_stats.h"

#include "app/progress_bar.h"
#include "primitives/test_counts.h"
#include "scenegraph/shape_registry.h"

#include <fmt/core.h>

namespace lucent::cli {

std::string renderStatsText(const RayStats& s, double seconds, int threads) {
  std::string out;
  out += fmt::format("rays:      {:>14}  (primary {}, shadow {}, reflected {}, refracted {})\n",
                     s.rays(), s.primary, s.shadow, s.reflected, s.refracted);
  out +=
      fmt::format("searches:  {:>14}  (closest-hit and any-hit queries of the world)\n", s.queries);
  out += fmt::format(
      "cache hits:{:>14}  (shadow rays blocked by the object that blocked the light's "
      "previous one, tested first)\n",
      s.shadowCacheHits);
  // Intersection tests by kind, the kinds the scene has only.
  uint64_t tests = 0;
  std::string byKind;
  for (size_t k = 0; k < kTestSlots; ++k) {
    const uint64_t n = s.tests[k];
    if (n == 0) continue;
    tests += n;
    byKind += fmt::format("{}{} {}", byKind.empty() ? "" : ", ", testSlotName(k), n);
  }
  out += fmt::format("tests:     {:>14}  ({})\n", tests, byKind.empty() ? "none" : byKind);
  out += fmt::format("time:      {:>14.3f}  s ({})\n", seconds, formatDuration(seconds));
  out += fmt::format("speed:     {:>14.3f}  Mrays/s on {} threads\n",
                     seconds > 0.0 ? s.rays() / seconds * 1e-6 : 0.0, threads);
  return out;
}

}  // namespace lucent::cli
