#include "gradient_report.h"

#include <fmt/format.h>

#include <set>

namespace lucent {

namespace {

void collect(const Node& n, std::set<const GradientRecord*>& seen, std::vector<std::string>& out) {
  if (n.shape)
    if (const auto* iso = std::get_if<IsosurfaceSpec>(&*n.shape);
        iso && iso->record && seen.insert(iso->record.get()).second) {
      const double found = iso->record->largest();
      if (found > iso->maxGradient)
        out.push_back(fmt::format(
            "{}: warning: <isosurface> max-gradient is {} but the function's gradient reached "
            "{:.4g} along the rays: parts of the surface may be missing; set max-gradient to "
            "at least {:.4g}",
            n.loc.str(), iso->maxGradient, found, found));
    }
  for (const auto& c : n.children) collect(*c, seen, out);
}

}  // namespace

std::vector<std::string> gradientWarnings(const Scene& scene) {
  std::set<const GradientRecord*> seen;
  std::vector<std::string> out;
  collect(*scene.root, seen, out);
  for (const auto& d : scene.defs) collect(*d, seen, out);
  return out;
}

}  // namespace lucent
