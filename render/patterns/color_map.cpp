#include "color_map.h"

#include "pattern_value.h"

namespace lucent {

namespace {

const ColorMapEntry kGrey[2] = {{0.0, Color(0.0f)}, {1.0, Color(1.0f)}};

// float difference, scaled in double and rounded back to float, as POV-Ray's colours.
float blend(float a, float b, double fraction) {
  const float d = b - a;
  return a + static_cast<float>(static_cast<double>(d) * fraction);
}

}  // namespace

Color lookupColorMap(const ColorMap& map, double v) {
  const ColorMapEntry* e = map.entries.empty() ? kGrey : map.entries.data();
  const size_t n = map.entries.empty() ? 2 : map.entries.size();
  const MapSpan s = mapSpanAt(e, n, v);
  if (s.a == s.b) return e[s.a].color;
  Color c;
  for (int i = 0; i < 3; ++i) c[i] = blend(e[s.a].color[i], e[s.b].color[i], s.fraction);
  return c;
}

PigmentColor blendPigments(const PigmentColor& a, const PigmentColor& b, double fraction) {
  PigmentColor c;
  for (int i = 0; i < 3; ++i) c.rgb[i] = blend(a.rgb[i], b.rgb[i], fraction);
  c.ft.filter = blend(a.ft.filter, b.ft.filter, fraction);
  c.ft.transmit = blend(a.ft.transmit, b.ft.transmit, fraction);
  return c;
}

PigmentColor lookupColorMapFT(const ColorMap& map, double v) {
  const ColorMapEntry* e = map.entries.empty() ? kGrey : map.entries.data();
  const size_t n = map.entries.empty() ? 2 : map.entries.size();
  const MapSpan s = mapSpanAt(e, n, v);
  if (s.a == s.b) return {e[s.a].color, e[s.a].ft};
  return blendPigments({e[s.a].color, e[s.a].ft}, {e[s.b].color, e[s.b].ft}, s.fraction);
}

Color patternColor(const PatternSpec& spec, const ColorMap& map, const Vec3& objectPoint) {
  return lookupColorMap(map, patternValue(spec, objectPoint));
}

}  // namespace lucent
