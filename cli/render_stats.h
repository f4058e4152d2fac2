// The figures `lucent render --stats` prints after a render (rays by kind, world searches,
// shadow cache hits, intersection tests by kind, time and speed), as text: printed by
// `render`, shown in the page by `preview`.
#pragma once

#include "render/ray_stats.h"

#include <string>

namespace lucent::cli {

// The lines, each ending in a line break.
std::string renderStatsText(const RayStats& stats, double seconds, int threads);

}  // namespace lucent::cli
