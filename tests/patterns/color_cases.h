// The colour cases of tests/data/patterns/make_references.sh (colors.csv) as Lucent specs.
#pragma once

#include "pattern_cases.h"

#include "render/patterns/block_pattern.h"
#include "render/patterns/color_map.h"
#include "render/patterns/pattern_point.h"

#include <functional>
#include <map>
#include <string>

namespace lucent::test {

using ColorAt = std::function<Color(const Vec3& objectPoint)>;

inline ColorAt mapped(const PatternSpec& s, const ColorMap& map) {
  return [s, map](const Vec3& p) { return patternColor(s, map, p); };
}

inline ColorAt hexagon(const HexagonSpec& h, const PatternPlacement& placement) {
  return [h, placement](const Vec3& p) { return hexagonColor(h, warpPoint(placement, p)); };
}

inline ColorAt brick(const BrickSpec& b, const PatternPlacement& placement) {
  return [b, placement](const Vec3& p) { return brickColor(b, warpPoint(placement, p)); };
}

inline std::map<std::string, ColorAt> colorCases() {
  using T = PatternType;
  const Color red(1, 0, 0), green(0, 1, 0), blue(0, 0, 1);
  PatternPlacement none;
  PatternPlacement hexPlaced;
  hexPlaced.patternFromObject = then(inverseScale(Vec3(0.3)), inverseTranslate(Vec3(0.1, 0, -0.2)));
  PatternPlacement hexTurbulent;
  hexTurbulent.turbulence = Vec3(0.3);
  PatternPlacement brickTurbulent;
  brickTurbulent.turbulence = Vec3(0.4);
  brickTurbulent.octaves = 3;

  BrickSpec plainBrick;
  plainBrick.color1 = Color(0.1f, 0.2f, 0.3f);
  plainBrick.color2 = Color(0.9f, 0.8f, 0.7f);
  BrickSpec sizedBrick = plainBrick;
  sizedBrick.mortar = 0.2;
  sizedBrick.size = Vec3(1, 0.5, 0.7);
  BrickSpec whiteBrick;
  whiteBrick.color1 = Color(1.0f);
  whiteBrick.color2 = Color(0.0f);

  return {
      {"map_bozo",
       mapped(spec(T::bozo),
              {{{0.2, red}, {0.5, Color(0, 1, 0.5f)}, {0.9, Color(0.1f, 0.2f, 0.9f)}}})},
      {"map_single", mapped(spec(T::onion), {{{0.5, Color(0.3f, 0.6f, 0.9f)}}})},
      {"map_step", mapped(axis(spec(T::gradient), Vec3(1, 0, 0)),
                          {{{0, Color(0)}, {0.5, red}, {0.5, blue}, {1, Color(1)}}})},
      {"map_single_precision", mapped(spec(T::leopard), {{{0.1, Color(0.25f, 0.5f, 0.75f)},
                                                          {0.3, Color(1, 0.5f, 0)},
                                                          {0.7, Color(0, 0.3f, 0.1f)}}})},
      {"map_none", mapped(spec(T::granite), ColorMap{})},
      {"map_wide",
       mapped(turbulent(spec(T::marble), Vec3(0.6)), {{{-0.5, Color(0.2f, 0.4f, 0.6f)},
                                                       {0.3, Color(0.9f, 0.1f, 0.3f)},
                                                       {1.5, Color(0.05f, 0.95f, 0.5f)}}})},
      {"hexagon", hexagon(HexagonSpec{{red, green, blue}}, none)},
      {"hexagon_scaled", hexagon(HexagonSpec{{Color(0.2f, 0.3f, 0.4f), Color(0.9f, 0.8f, 0.1f),
                                              Color(0.5f, 0.5f, 0)}},
                                 hexPlaced)},
      {"hexagon_turbulence", hexagon(HexagonSpec{{red, green, blue}}, hexTurbulent)},
      {"brick", brick(plainBrick, none)},
      {"brick_sized", brick(sizedBrick, none)},
      {"brick_turbulence", brick(whiteBrick, brickTurbulent)},
      {"mandel_exterior7", mapped(fractal(T::mandel, 15, 7, {7, 3}, {3, 0.5}),
                                  {{{0, Color(0)}, {1, Color(1, 0.5f, 0.25f)}}})},
      {"julia_exterior8",
       mapped(julia(-0.5, 0.5, 20, 3, {8, 4}), {{{0, Color(0)}, {1, Color(1, 0.5f, 0.25f)}}})},
  };
}

}  // namespace lucent::test
