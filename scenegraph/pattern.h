// Procedural patterns as POV-Ray 3.7 defines them: the plain data a scene keeps. The
// renderer evaluates them with render/patterns/ (docs/patterns-noise.md).
#pragma once

#include "primitives/math.h"

#include <optional>
#include <vector>

namespace lucent {

// The pattern functions of POV-Ray 3.7 that Lucent reproduces (pattern.cpp, normal.cpp).
enum class PatternType {
  gradient,
  onion,
  radial,
  spiral1,
  spiral2,
  wood,
  marble,
  agate,
  granite,
  bozo,
  spotted,
  leopard,
  crackle,
  wrinkles,
  bumps,
  dents,
  ripples,
  waves,
};
constexpr int kPatternTypeCount = 18;

// How a pattern's value is shaped after frequency and phase (POV-Ray's wave types).
enum class WaveShape { ramp, sine, triangle, scallop, cubic, poly };

// POV-Ray's parser gives marble, wood and both spirals a triangle wave, every other
// pattern a ramp (parstxtr.cpp, Parse_Pattern).
constexpr WaveShape defaultWave(PatternType type) {
  switch (type) {
    case PatternType::marble:
    case PatternType::wood:
    case PatternType::spiral1:
    case PatternType::spiral2:
      return WaveShape::triangle;
    default:
      return WaveShape::ramp;
  }
}

// Where a pattern sits on its object and how turbulence displaces it. The object point is
// carried into pattern space first; turbulence then works in pattern space, so it scales
// with the pattern (POV-Ray's warp list: the transform, then the turbulence warp).
struct PatternPlacement {
  Mat4 patternFromObject{1.0};
  Vec3 turbulence{0.0};  // per-axis strength; zero means none
  int octaves = 6;       // POV-Ray clamps to 1..10; so does the evaluation
  double omega = 0.5;    // amplitude factor per octave
  double lambda = 2.0;   // frequency factor per octave
};

// POV-Ray's crackle modifiers and their defaults (metric 2, form <-1,1,0>, offset 0).
struct CrackleParams {
  double metric = 2.0;
  Vec3 form{-1.0, 1.0, 0.0};
  double offset = 0.0;
  bool solid = false;  // every cell one noise value instead of the distance pattern
};

struct PatternSpec {
  PatternType type = PatternType::bozo;
  PatternPlacement placement;
  Vec3 axis{0.0, 1.0, 0.0};  // gradient's direction (normalised when evaluated, as POV-Ray)
  int arms = 1;              // spiral1, spiral2
  double frequency = 1.0;    // 0 leaves the value unwrapped (POV-Ray's rule)
  double phase = 0.0;
  std::optional<WaveShape> wave;  // nullopt: defaultWave(type)
  double exponent = 1.0;          // poly_wave's exponent
  CrackleParams crackle;
  int noiseGenerator = 2;  // 1 original, 2 range corrected (3.7's default), 3 Perlin

  WaveShape waveShape() const { return wave.value_or(defaultWave(type)); }
};

// A colour map: entries sorted by `at`, colours interpolated linearly between them and
// constant beyond the ends. An empty map is POV-Ray's grey map [0 black][1 white].
struct ColorMapEntry {
  double at = 0.0;
  Color color{0.0f};
};
struct ColorMap {
  std::vector<ColorMapEntry> entries;
};

// POV-Ray's hexagon: three colours on hexagons in the x-z plane (defaults as POV-Ray's).
struct HexagonSpec {
  Color colors[3] = {Color(0.0f, 0.0f, 1.0f), Color(0.0f, 1.0f, 0.0f), Color(1.0f, 0.0f, 0.0f)};
};

// POV-Ray's brick: color1 is the mortar, color2 the brick (defaults as POV-Ray's).
struct BrickSpec {
  Color color1{0.5f, 0.5f, 0.5f};
  Color color2{0.6f, 0.15f, 0.15f};
  double mortar = 0.5;
  Vec3 size{8.0, 3.0, 4.5};
};

// A normal perturbation: POV-Ray's `normal { PATTERN depth }` (depth is its bump_size).
struct NormalSpec {
  PatternSpec pattern;
  double depth = 0.5;
};

}  // namespace lucent
