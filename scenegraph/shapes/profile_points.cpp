#include "profile_points.h"

#include <fmt/format.h>

#include <cmath>

namespace lucent {

std::optional<std::vector<Vec2>> readProfilePairs(AttributeInput& in, std::string_view element) {
  if (!in.has("points")) {
    in.error(fmt::format("<{}> needs the attribute 'points' (x y pairs)", element));
    return std::nullopt;
  }
  auto v = in.numbers("points");
  if (!v) return std::nullopt;
  if (v->size() % 2 != 0) {
    in.attrError("points", fmt::format("needs x y pairs, but has {} numbers", v->size()));
    return std::nullopt;
  }
  std::vector<Vec2> pairs(v->size() / 2);
  for (size_t i = 0; i < pairs.size(); ++i) pairs[i] = Vec2((*v)[2 * i], (*v)[2 * i + 1]);
  return pairs;
}

bool profilePointValid(AttributeInput& in, const Vec2& p, size_t i) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
    in.attrError("points", "must be finite numbers");
    return false;
  }
  if (p.x < 0.0) {
    in.attrError("points", fmt::format("point {} has x = {}: x must be >= 0", i + 1, p.x));
    return false;
  }
  return true;
}

}  // namespace lucent
