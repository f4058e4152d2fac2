// The normal cases of tests/data/patterns/make_references.sh (normals.csv) as Lucent specs.
#pragma once

#include "pattern_cases.h"

#include <map>
#include <string>

namespace lucent::test {

inline NormalSpec bumpy(PatternSpec s, double depth) {
  NormalSpec n;
  n.pattern = s;
  n.depth = depth;
  return n;
}

// A normal map (entries at `at`) or a block pattern's list (entries at 0, 1, 2) over `s`.
inline NormalSpec mapped(PatternSpec s, std::vector<std::pair<double, NormalSpec>> entries,
                         NormalBlock block = NormalBlock::none) {
  NormalSpec n;
  n.pattern = s;
  n.block = block;
  for (auto& [at, normal] : entries) n.map.push_back({at, false, normal});
  return n;
}

// A normal spec with its depth (a map's or a list's, for a block pattern's slope).
inline NormalSpec bumpy(NormalSpec n, double depth) {
  n.depth = depth;
  return n;
}

inline NormalSpec sloped(NormalSpec n, std::vector<SlopeMapEntry> map) {
  n.slopeMap = std::move(map);
  return n;
}

inline NormalSpec bricked(NormalSpec n, Vec3 size, double mortar) {
  n.brick.size = size;
  n.brick.mortar = mortar;
  return n;
}

inline std::map<std::string, NormalSpec> normalCases() {
  using T = PatternType;
  return {
      {"bumps", bumpy(spec(T::bumps), 0.5)},
      {"bumps_scaled", bumpy(placed(spec(T::bumps), inverseScale(Vec3(0.5, 1.5, 1))), 0.8)},
      {"bumps_turbulence", bumpy(turbulent(spec(T::bumps), Vec3(0.4)), 0.5)},
      {"dents", bumpy(spec(T::dents), 0.9)},
      {"dents_generator1", bumpy(generator(spec(T::dents), 1), 0.9)},
      {"wrinkles", bumpy(spec(T::wrinkles), 0.4)},
      {"ripples", bumpy(tuned(spec(T::ripples), 3, 0), 0.6)},
      {"waves", bumpy(tuned(spec(T::waves), 2, 0.1), 0.7)},
      {"granite", bumpy(spec(T::granite), 0.3)},
      {"bozo", bumpy(placed(spec(T::bozo), inverseScale(Vec3(0.5))), 0.6)},
      {"marble", bumpy(turbulent(spec(T::marble), Vec3(0.5)), 0.5)},
      {"crackle", bumpy(spec(T::crackle), 0.5)},
      {"agate", bumpy(spec(T::agate), 0.4)},
      {"onion", bumpy(waved(spec(T::onion), WaveShape::sine), 0.5)},
      {"leopard", bumpy(placed(spec(T::leopard), inverseScale(Vec3(0.2))), 0.5)},
      {"gradient", bumpy(tuned(axis(spec(T::gradient), Vec3(1, 0, 0)), 2, 0), 0.5)},
      {"wood", bumpy(turbulent(spec(T::wood), Vec3(0.1)), 0.5)},
      {"spiral1", bumpy(arms(spec(T::spiral1), 3), 0.5)},
      {"spiral2", bumpy(arms(spec(T::spiral2), 2), 0.5)},
      {"radial", bumpy(tuned(spec(T::radial), 6, 0), 0.4)},
      {"spotted", bumpy(generator(spec(T::spotted), 3), 0.5)},
      {"slope_rotated", bumpy(placed(spec(T::granite), then(inverseRotate(Vec3(20, 30, 40)),
                                                            inverseScale(Vec3(1, 0.5, 2)))),
                              0.6)},
      {"planar", bumpy(spec(T::planar), 0.8)},
      {"planar_rotated",
       bumpy(placed(spec(T::planar), then(inverseRotate(Vec3(0, 0, 40)), inverseScale(Vec3(1.5)))),
             0.6)},
      {"quilted", bumpy(placed(quilted(0.5, 0.8), inverseScale(Vec3(0.7))), 0.6)},
      {"mandel", bumpy(placed(fractal(T::mandel, 30), inverseScale(Vec3(1.5))), 0.5)},
      {"normal_map", mapped(placed(axis(spec(T::gradient), Vec3(1, 0, 0)), inverseScale(Vec3(2))),
                            {{0.3, bumpy(placed(spec(T::bumps), inverseScale(Vec3(0.5))), 0.6)},
                             {0.7, bumpy(turbulent(spec(T::marble), Vec3(0.5)), 0.5)}})},
      {"normal_map_three",
       mapped(placed(spec(T::bozo), inverseScale(Vec3(0.7))),
              {{0.2, bumpy(tuned(spec(T::ripples), 3, 0), 0.6)},
               {0.5, bumpy(spec(T::granite), 0.3)},
               {0.8, bumpy(placed(spec(T::leopard), inverseScale(Vec3(0.2))), 0.5)}})},
      {"checker_normals", mapped(placed(spec(T::bozo), inverseScale(Vec3(0.9))),
                                 {{0, bumpy(placed(spec(T::bumps), inverseScale(Vec3(0.3))), 0.8)},
                                  {1, bumpy(spec(T::wrinkles), 0.5)}},
                                 NormalBlock::checker)},
      {"hexagon_normals",
       mapped(placed(spec(T::bozo), then(inverseRotate(Vec3(90, 0, 0)), inverseScale(Vec3(0.6)))),
              {{0, bumpy(spec(T::ripples), 0.5)},
               {1, bumpy(spec(T::granite), 0.4)},
               {2, bumpy(spec(T::bumps), 0.7)}},
              NormalBlock::hexagon)},
      {"brick_normals",
       bricked(mapped(spec(T::bozo),
                      {{0, bumpy(spec(T::granite), 0.3)},
                       {1, bumpy(placed(spec(T::bumps), inverseScale(Vec3(0.2))), 0.8)}},
                      NormalBlock::brick),
               Vec3(1, 0.4, 0.6), 0.1)},
      {"slope_map", sloped(bumpy(placed(spec(T::onion), inverseScale(Vec3(0.6))), 0.8),
                           {{0, 0, 1}, {0.5, 1, 1}, {0.5, 1, -1}, {1, 0, -1}})},
      {"slope_map_sine",
       sloped(bumpy(placed(axis(spec(T::gradient), Vec3(1, 1, 0)), inverseScale(Vec3(0.8))), 0.6),
              {{0, 0.5, 1}, {0.25, 1, 0}, {0.5, 0.5, -1}, {0.75, 0, 0}, {1, 0.5, 1}})},
      {"checker_slope",
       bumpy(mapped(placed(spec(T::bozo), inverseScale(Vec3(0.7))), {}, NormalBlock::checker),
             0.5)},
      {"hexagon_slope", bumpy(mapped(placed(spec(T::bozo), then(inverseRotate(Vec3(90, 0, 0)),
                                                                inverseScale(Vec3(0.5)))),
                                     {}, NormalBlock::hexagon),
                              0.6)},
      {"brick_slope",
       bumpy(bricked(mapped(spec(T::bozo), {}, NormalBlock::brick), Vec3(1, 0.4, 0.6), 0.1), 0.75)},
      {"slope_map_granite",
       sloped(bumpy(spec(T::granite), 0.5), {{0, 0, 0}, {0.4, 0.2, 2}, {1, 1, 0}})},
      {"spherical", bumpy(placed(spec(T::spherical), inverseScale(Vec3(2))), 0.7)},
      {"cylindrical", bumpy(placed(spec(T::cylindrical),
                                   then(inverseScale(Vec3(1.5)), inverseRotate(Vec3(0, 0, 30)))),
                            0.5)},
      {"boxed",
       bumpy(placed(spec(T::boxed), then(inverseScale(Vec3(1.7)), inverseRotate(Vec3(0, 0, 20)))),
             0.6)},
      {"cells", bumpy(placed(spec(T::cells), inverseScale(Vec3(0.6))), 0.5)},
      {"pigment_pattern",
       bumpy(pigmentPattern(withMap(placed(spec(T::granite), inverseScale(Vec3(0.5))), {})), 0.6)},
  };
}

}  // namespace lucent::test
