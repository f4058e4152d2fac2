#include "color_map.h"

#include "pattern_value.h"

namespace lucent {

namespace {

const ColorMapEntry kGrey[2] = {{0.0, Color(0.0f)}, {1.0, Color(1.0f)}};

double position(const ColorMapEntry& e) { return static_cast<float>(e.at); }

// POV-Ray's search: the first entry at or above v (the last if v is past it) and the one
// before it; at an entry's own position both are that entry. `fraction` is how far v lies
// from the first towards the second.
struct Span {
  const ColorMapEntry* a;
  const ColorMapEntry* b;
  double fraction = 0.0;
};
Span spanAt(const ColorMapEntry* e, size_t n, double v) {
  size_t prev, cur;
  if (v >= position(e[n - 1])) {
    prev = cur = n - 1;
  } else {
    prev = cur = 0;
    while (v > position(e[cur])) prev = cur++;
  }
  if (v == position(e[cur])) prev = cur;
  if (prev == cur) return {&e[cur], &e[cur]};
  // The span is a difference of two floats, so POV-Ray computes it in float.
  const float span = static_cast<float>(e[cur].at) - static_cast<float>(e[prev].at);
  return {&e[prev], &e[cur], (v - position(e[prev])) / static_cast<double>(span)};
}

// float difference, scaled in double and rounded back to float, as POV-Ray's colours.
float blend(float a, float b, double fraction) {
  const float d = b - a;
  return a + static_cast<float>(static_cast<double>(d) * fraction);
}

}  // namespace

Color lookupColorMap(const ColorMap& map, double v) {
  const ColorMapEntry* e = map.entries.empty() ? kGrey : map.entries.data();
  const size_t n = map.entries.empty() ? 2 : map.entries.size();
  const Span s = spanAt(e, n, v);
  if (s.a == s.b) return s.a->color;
  Color c;
  for (int i = 0; i < 3; ++i) c[i] = blend(s.a->color[i], s.b->color[i], s.fraction);
  return c;
}

PigmentColor lookupColorMapFT(const ColorMap& map, double v) {
  const ColorMapEntry* e = map.entries.empty() ? kGrey : map.entries.data();
  const size_t n = map.entries.empty() ? 2 : map.entries.size();
  const Span s = spanAt(e, n, v);
  if (s.a == s.b) return {s.a->color, s.a->ft};
  PigmentColor c;
  for (int i = 0; i < 3; ++i) c.rgb[i] = blend(s.a->color[i], s.b->color[i], s.fraction);
  c.ft.filter = blend(s.a->ft.filter, s.b->ft.filter, s.fraction);
  c.ft.transmit = blend(s.a->ft.transmit, s.b->ft.transmit, s.fraction);
  return c;
}

Color patternColor(const PatternSpec& spec, const ColorMap& map, const Vec3& objectPoint) {
  return lookupColorMap(map, patternValue(spec, objectPoint));
}

}  // namespace lucent
