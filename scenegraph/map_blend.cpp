#include "map_blend.h"

namespace lucent {

MapBlend mapBlend(const std::vector<MaterialMapEntry>& entries, double v) {
  const auto last = static_cast<uint32_t>(entries.size() - 1);
  if (!(v < entries[last].at)) return {last, last, 1.0f, 0.0f};  // NaN too
  uint32_t next = 0;
  while (v > entries[next].at) ++next;
  if (next == 0 || v == entries[next].at) return {next, next, 1.0f, 0.0f};
  const uint32_t prev = next - 1;
  const double wPrev = (entries[next].at - v) / (entries[next].at - entries[prev].at);
  return {prev, next, static_cast<float>(wPrev), static_cast<float>(1.0 - wPrev)};
}

}  // namespace lucent
