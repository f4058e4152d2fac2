#include "color_map.h"

#include "pattern_value.h"

namespace lucent {

namespace {

const ColorMapEntry kGrey[2] = {{0.0, Color(0.0f)}, {1.0, Color(1.0f)}};

double position(const ColorMapEntry& e) { return static_cast<float>(e.at); }

}  // namespace

Color lookupColorMap(const ColorMap& map, double v) {
  const ColorMapEntry* e = map.entries.empty() ? kGrey : map.entries.data();
  const size_t n = map.entries.empty() ? 2 : map.entries.size();

  // POV-Ray's search: the first entry at or above v (the last if v is past it) and the
  // one before it; at an entry's own position both are that entry.
  size_t prev, cur;
  if (v >= position(e[n - 1])) {
    prev = cur = n - 1;
  } else {
    prev = cur = 0;
    while (v > position(e[cur])) prev = cur++;
  }
  if (v == position(e[cur])) prev = cur;
  if (prev == cur) return e[cur].color;

  // The span is a difference of two floats, so POV-Ray computes it in float.
  const float span = static_cast<float>(e[cur].at) - static_cast<float>(e[prev].at);
  const double fraction = (v - position(e[prev])) / static_cast<double>(span);
  const Color& a = e[prev].color;
  const Color& b = e[cur].color;
  Color c;
  for (int i = 0; i < 3; ++i) {
    // float difference, scaled in double and rounded back to float, as POV-Ray's colours.
    const float d = b[i] - a[i];
    c[i] = a[i] + static_cast<float>(static_cast<double>(d) * fraction);
  }
  return c;
}

Color patternColor(const PatternSpec& spec, const ColorMap& map, const Vec3& objectPoint) {
  return lookupColorMap(map, patternValue(spec, objectPoint));
}

}  // namespace lucent
