// A colour map written out of order (woods.inc's T_Wood32) becomes the ascending map that
// gives every value POV-Ray's colour: checked against a transcription of POV-Ray 3.7's
// blend map search (its BlendMap::Search, as facts) at many values, through Lucent's own
// map lookup.
#include "render/patterns/color_map.h"
#include "sdl/pov_finish.h"

#include <catch2/catch.hpp>

#include <random>

using namespace lucent;
using namespace lucent::sdl;

namespace {

// POV-Ray's search over the entries in their written order: the last entry from its value
// up; else the first entry at or above v, blended with the one before it in the list.
Color povColour(const std::vector<PovColorMapEntry>& map, double v) {
  if (v >= map.back().at) return map.back().color;
  size_t n = 0, p = 0;
  while (v > map[n].at) p = n++;
  if (v == map[n].at || p == n) return map[n].color;
  const double prevWeight = (map[n].at - v) / (map[n].at - map[p].at);
  return map[p].color * static_cast<float>(prevWeight) +
         map[n].color * static_cast<float>(1.0 - prevWeight);
}

Color lucentColour(const std::vector<PovColorMapEntry>& written, double v) {
  ColorMap map;
  for (const PovColorMapEntry& e : ascendingMap(written)) map.entries.push_back({e.at, e.color});
  return lookupColorMap(map, v);
}

PovColorMapEntry entry(double at, float r, float g, float b) {
  PovColorMapEntry e;
  e.at = at;
  e.color = Color(r, g, b);
  return e;
}

void compareAt(const std::vector<PovColorMapEntry>& map, double v) {
  INFO("v = " << v);
  const Color want = povColour(map, v), got = lucentColour(map, v);
  for (int c = 0; c < 3; ++c) CHECK(got[c] == Approx(want[c]).margin(1e-5));
}

}  // namespace

TEST_CASE("a colour map out of order gives POV-Ray's colour at every value",
          "[sdl][pattern][colour-map]") {
  // T_Wood32's map ends 0.85, 0.95, 0.90, 1.00.
  const std::vector<PovColorMapEntry> wood{
      entry(0.75, 0.38f, 0.15f, 0.0f), entry(0.85, 0.24f, 0.0f, 0.0f),
      entry(0.95, 0.38f, 0.149f, 0.0f), entry(0.90, 0.235f, 0.0f, 0.0f),
      entry(1.00, 0.38f, 0.1493f, 0.0f)};
  CHECK(ascendingMap(wood).size() > wood.size());
  for (int i = 0; i <= 1000; ++i) {
    const double v = i / 1000.0;
    // The sharp edge at 0.95 (POV-Ray takes the lower stretch's end there) is left out.
    if (v != 0.95) compareAt(wood, v + 1e-7);
  }
  // The last entry below the others: it covers everything from its value up.
  const std::vector<PovColorMapEntry> lastLow{entry(0.2, 1, 0, 0), entry(0.9, 0, 1, 0),
                                              entry(0.5, 0, 0, 1)};
  for (double v : {0.0, 0.1, 0.3, 0.45, 0.5, 0.7, 0.95}) compareAt(lastLow, v + 1e-7);

  // Random orders.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<PovColorMapEntry> map;
    for (int k = 0; k < 6; ++k)
      map.push_back(entry(unit(random), static_cast<float>(unit(random)),
                          static_cast<float>(unit(random)), static_cast<float>(unit(random))));
    for (int i = 0; i < 200; ++i) {
      const double v = unit(random);
      bool atEntry = false;  // a value exactly at an entry may fall on a sharp edge
      for (const PovColorMapEntry& e : map) atEntry = atEntry || e.at == v;
      if (!atEntry) compareAt(map, v);
    }
  }
  // An ascending map is kept as it is.
  const std::vector<PovColorMapEntry> ascending{entry(0, 0, 0, 0), entry(1, 1, 1, 1)};
  CHECK(ascendingMap(ascending).size() == 2);
}

TEST_CASE("a colour map with entries beyond 0 and 1 keeps POV-Ray's colour at every value",
          "[sdl][pattern][colour-map]") {
  // stones.inc ends its maps at 1.001; maps may also start below 0 or lie wholly outside.
  const std::vector<std::vector<PovColorMapEntry>> maps{
      {entry(0, 0.2f, 0.3f, 0.4f), entry(0.729, 0.7f, 0.5f, 0.4f), entry(1.001, 0.1f, 0.9f, 0.3f)},
      {entry(-0.5, 1, 0, 0), entry(0.25, 0, 1, 0), entry(1.5, 0, 0, 1)},
      {entry(-2, 1, 0, 0), entry(-1, 0, 1, 0), entry(0.5, 0, 0, 1), entry(1, 1, 1, 1)},
      {entry(1.2, 1, 0, 0), entry(1.5, 0, 1, 0)},
      {entry(-1.5, 1, 0, 0), entry(-0.5, 0, 1, 0)}};
  for (const std::vector<PovColorMapEntry>& map : maps) {
    const std::vector<PovColorMapEntry> unit = unitMap(map);
    for (const PovColorMapEntry& e : unit) {
      CHECK(e.at >= 0.0);
      CHECK(e.at <= 1.0);
    }
    ColorMap lucent;
    for (const PovColorMapEntry& e : unit) lucent.entries.push_back({e.at, e.color});
    for (int i = 0; i <= 100; ++i) {
      const double v = i / 100.0;
      INFO("v = " << v);
      const Color want = povColour(map, v), got = lookupColorMap(lucent, v);
      for (int c = 0; c < 3; ++c) CHECK(got[c] == Approx(want[c]).margin(1e-5));
    }
  }
}
