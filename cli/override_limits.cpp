#include "commands.h"

#include "scenegraph/render_limits.h"

#include <fmt/format.h>

namespace lucent::cli {

std::optional<std::string> overrideProblem(const std::string& name,
                                           const std::optional<int>& value) {
  if (!value) return std::nullopt;
  if (*value < 1) return fmt::format("{} must be at least 1 (got {})", name, *value);
  int limit = 0;
  if (name == "--width" || name == "--height") limit = kMaxImageSide;
  else if (name == "--samples") limit = kMaxSamples;
  else if (name == "--max-depth") limit = kMaxRecursionDepth;
  else if (name == "--threads") limit = 4096;  // far above any machine's cores; TBB's own cap
  if (limit > 0 && *value > limit)
    return fmt::format("{} must be at most {} (got {})", name, limit, *value);
  return std::nullopt;
}

}  // namespace lucent::cli
