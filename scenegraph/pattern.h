// Procedural patterns as POV-Ray 3.7 defines them: the plain data a scene keeps. The
// renderer evaluates them with render/patterns/ (docs/patterns-noise.md).
#pragma once

#include "primitives/math.h"
#include "primitives/scalar_field.h"
#include "scenegraph/pattern_warp.h"

#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lucent {

// How a pattern's value is shaped after frequency and phase (POV-Ray's wave types).
enum class WaveShape { ramp, sine, triangle, scallop, cubic, poly };

// The pattern functions of POV-Ray 3.7 that Lucent reproduces (pattern.cpp, normal.cpp).
// A new pattern: its row in kPatternTypes below and its value in
// render/patterns/pattern_value.cpp, whose switch covers every type (docs/architecture.md).
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
  planar,
  quilted,
  mandel,
  julia,
  magnet,
  function,
  spherical,
  cylindrical,
  boxed,
  cells,
  pigment,
  slope,
  tiling,
  facets,
  pavement,
  image,
  object,
};

// What the parser's names, the schema, the POV-Ray exporter and the renderer's defaults
// read about a pattern type.
struct PatternTypeInfo {
  PatternType type;
  std::string_view name;  // type="..." of <pattern> and <normal>
  std::string_view pov;   // POV-Ray's keyword (its extra tokens, as gradient's axis, are
                          // written by povray/pov_patterns.cpp)
  bool colour;            // a colour pattern; false: only a <normal> takes it
  WaveShape wave;         // POV-Ray's default wave for it (parstxtr.cpp, Parse_Pattern)
  bool turbulenceInside;  // turbulence works inside the pattern and leaves the point alone
  std::string_view doc;   // one line, for the schema
};

// The pattern table: one row per PatternType, in its order.
inline constexpr PatternTypeInfo kPatternTypes[] = {
    {PatternType::gradient, "gradient", "gradient", true, WaveShape::ramp, false,
     "the value rises from 0 to 1 along axis over one unit, then repeats"},
    {PatternType::onion, "onion", "onion", true, WaveShape::ramp, false,
     "concentric spheres about the origin, one unit apart"},
    {PatternType::radial, "radial", "radial", true, WaveShape::ramp, false,
     "the angle about the y axis, 0 to 1 once around"},
    {PatternType::spiral1, "spiral1", "spiral1", true, WaveShape::triangle, false,
     "a spiral of arms arms about the z axis, winding along z"},
    {PatternType::spiral2, "spiral2", "spiral2", true, WaveShape::triangle, false,
     "two crossed spirals of arms arms about the z axis"},
    {PatternType::wood, "wood", "wood", true, WaveShape::triangle, true,
     "concentric cylinders about the z axis, bent by turbulence"},
    {PatternType::marble, "marble", "marble", true, WaveShape::triangle, true,
     "bands across the x axis, bent by turbulence"},
    {PatternType::agate, "agate", "agate", true, WaveShape::ramp, false,
     "agate's turbulent bands (their turbulence scaled by agate-turb)"},
    {PatternType::granite, "granite", "granite", true, WaveShape::ramp, false,
     "six octaves of absolute noise"},
    {PatternType::bozo, "bozo", "bozo", true, WaveShape::ramp, false, "smooth noise"},
    {PatternType::spotted, "spotted", "spotted", true, WaveShape::ramp, false,
     "smooth noise (as bozo)"},
    {PatternType::leopard, "leopard", "leopard", true, WaveShape::ramp, false,
     "regular spots, the square of the mean of sin x, sin y and sin z"},
    {PatternType::crackle, "crackle", "crackle", true, WaveShape::ramp, false,
     "cells about random points, the distance to the nearest cell wall"},
    {PatternType::wrinkles, "wrinkles", "wrinkles", true, WaveShape::ramp, false,
     "ten octaves of noise"},
    {PatternType::bumps, "bumps", "bumps", true, WaveShape::ramp, false,
     "smooth noise (as bozo; as a normal, the noise's gradient)"},
    {PatternType::dents, "dents", "dents", true, WaveShape::ramp, false,
     "the noise's gradient scaled by the noise cubed"},
    {PatternType::ripples, "ripples", "ripples", true, WaveShape::ramp, false,
     "circular waves from ten sources around the origin"},
    {PatternType::waves, "waves", "waves", true, WaveShape::ramp, false,
     "as ripples, each source with a frequency of its own"},
    {PatternType::planar, "planar", "planar", true, WaveShape::ramp, false,
     "1 on the plane y = 0, falling linearly to 0 at |y| = 1, 0 beyond"},
    {PatternType::quilted, "quilted", "quilted", true, WaveShape::ramp, false,
     "unit cubes with rounded, sunken centres shaped by control0 and control1"},
    {PatternType::mandel, "mandel", "mandel", true, WaveShape::ramp, false,
     "the Mandelbrot set z^power + c in the x-y plane"},
    {PatternType::julia, "julia", "julia", true, WaveShape::ramp, false,
     "the Julia set z^power + c of the constant c in the x-y plane"},
    {PatternType::magnet, "magnet", "magnet", true, WaveShape::ramp, false,
     "the magnet fractals of type 1 or 2 in the x-y plane, Mandelbrot or Julia form"},
    {PatternType::function, "function", "function", true, WaveShape::ramp, false,
     "the value of an expression of x, y and z (above 1 its fractional part)"},
    {PatternType::spherical, "spherical", "spherical", true, WaveShape::ramp, false,
     "1 at the origin, falling linearly to 0 at distance 1, 0 beyond"},
    {PatternType::cylindrical, "cylindrical", "cylindrical", true, WaveShape::ramp, false,
     "1 on the y axis, falling linearly to 0 at distance 1 from it, 0 beyond"},
    {PatternType::boxed, "boxed", "boxed", true, WaveShape::ramp, false,
     "1 at the origin, falling linearly to 0 on the cube of half-side 1, 0 outside it"},
    {PatternType::cells, "cells", "cells", true, WaveShape::ramp, false,
     "one random value for each unit cube"},
    {PatternType::pigment, "pigment-pattern", "pigment_pattern", true, WaveShape::ramp, false,
     "the grey level of a pigment's colour (0.297 r + 0.589 g + 0.114 b)"},
    {PatternType::slope, "slope", "slope", true, WaveShape::ramp, false,
     "the surface normal's angle to a direction, optionally mixed with the height along another"},
    {PatternType::tiling, "tiling", "tiling", true, WaveShape::ramp, false,
     "one of POV-Ray's 27 tilings of the x-z plane: 1 on a tile's edge, falling inside it"},
    {PatternType::facets, "facets", "facets", false, WaveShape::ramp, false,
     "flat facets: the normal (or, with coords, the point) snapped to the nearest random point"},
    {PatternType::pavement, "pavement", "pavement", true, WaveShape::ramp, false,
     "POV-Ray's pavements of the x-z plane: tiles of 1 to 6 triangles, squares or hexagons"},
    {PatternType::image, "image-pattern", "image_pattern", true, WaveShape::ramp, false,
     "the grey level (or with use-alpha the transparency) of a projected image"},
    {PatternType::object, "object", "object", true, WaveShape::ramp, false,
     "1 inside the solid that 'object' names, 0 outside it (POV-Ray's object pattern)"},
};
inline constexpr int kPatternTypeCount = static_cast<int>(std::size(kPatternTypes));

constexpr const PatternTypeInfo& patternTypeInfo(PatternType type) {
  return kPatternTypes[static_cast<int>(type)];
}

// Every row sits at its enumerator's index, so patternTypeInfo is a plain lookup.
constexpr bool patternRowsInOrder() {
  for (int i = 0; i < kPatternTypeCount; ++i)
    if (static_cast<int>(kPatternTypes[i].type) != i) return false;
  return true;
}
static_assert(patternRowsInOrder(), "kPatternTypes: one row per PatternType, in its order");

// Where a pattern sits on its object and how turbulence displaces it. The object point is
// carried into pattern space first, then through the warps (last written first), then
// turbulence displaces it; so turbulence scales with the pattern (POV-Ray's warp list: the
// transforms and warps in reverse written order, its classic turbulence last).
struct PatternPlacement {
  Mat4 patternFromObject{1.0};
  // The warps as written (each changes the pattern built so far, as POV-Ray's); empty for
  // a pattern with only a transform, which then costs nothing more.
  std::vector<PatternWarp> warps{};
  Vec3 turbulence{0.0};  // per-axis strength; zero means none
  int octaves = 6;       // POV-Ray clamps to 1..10; so does the evaluation
  double omega = 0.5;    // amplitude factor per octave
  double lambda = 2.0;   // frequency factor per octave
  // POV-Ray's uv_mapping: the point carried into pattern space is POV-Ray's (u, v, 0) of
  // the shape (Shape::povUV; on a shape without, the world point's x and y) instead of the
  // object point.
  bool uv = false;
};

// POV-Ray's crackle modifiers and their defaults (metric 2, form <-1,1,0>, offset 0).
struct CrackleParams {
  double metric = 2.0;
  Vec3 form{-1.0, 1.0, 0.0};
  double offset = 0.0;
  bool solid = false;  // every cell one noise value instead of the distance pattern
};

// POV-Ray's slope: the angle of the surface normal (world space, facing the ray) to
// `direction`, or to the way towards the world point `pointAt`, mapped from -90..90 degrees
// to 0..1; with `altitude`, mixed with the pattern point's height along it, the two weighed
// by the lengths of direction and altitude. A range (low, high) stretches its part so that
// low..high becomes 0..1 (both 0: none).
struct SlopeParams {
  Vec3 direction{0.0, 1.0, 0.0};
  bool pointAt = false;  // direction is a world point to look towards
  double low = 0.0, high = 0.0;
  Vec3 altitude{0.0};  // zero: the slope alone
  double altitudeLow = 0.0, altitudeHigh = 0.0;
  bool operator==(const SlopeParams& o) const {
    return direction == o.direction && pointAt == o.pointAt && low == o.low && high == o.high &&
           altitude == o.altitude && altitudeLow == o.altitudeLow && altitudeHigh == o.altitudeHigh;
  }
  bool operator!=(const SlopeParams& o) const { return !(*this == o); }
};

// POV-Ray's facets (normal.cpp, facets; a normal only, its depth unused): with coords 0
// the unit normal scaled by 1/size is replaced by the nearest of crackle's random points
// (one per unit cube), so that each small patch of directions shares one normal; with
// coords c the point scaled by 1/size finds that nearest point, and c times the noise
// gradient there, less its part along the normal, is added to the normal. Distances in
// `metric` (2 Euclidean; 1 POV-Ray's dx + dy + dz, signed; else the sum of |d|^metric).
struct FacetsParams {
  double size = 0.1;
  double coords = 0.0;
  double metric = 2.0;
  bool operator==(const FacetsParams& o) const {
    return size == o.size && coords == o.coords && metric == o.metric;
  }
  bool operator!=(const FacetsParams& o) const { return !(*this == o); }
};

// POV-Ray's pavement: tiles made of `tiles` cells with `sides` sides, arrangement `number`
// (1..the count for sides and tiles, render/patterns/pavement_layouts.h), the shapes of
// its outer and inner corners (0 sharp, 1 cut, 2 rounded) and `form`, its turning cells'.
struct PavementParams {
  int sides = 3, tiles = 1, number = 1, exterior = 0, interior = 0, form = 0;
};

// POV-Ray's quilted modifiers: the cubic that rounds each cube (defaults 1 and 1).
struct QuiltedParams {
  double control0 = 1.0;
  double control1 = 1.0;
};

// How a fractal pattern turns an escaped or a bounded point into a value (POV-Ray's
// exterior types 0..8 and interior types 0..6, each with its factor).
struct FractalColouring {
  int type = 0;
  double factor = 1.0;
};

// POV-Ray's mandel, julia and magnet: iterations, the exponent of z (mandel and julia,
// 2..33), julia's constant c (and the julia form of magnet), magnet's type (1 or 2), and
// the exterior (default type 1: iterations to escape over the maximum) and interior
// (default type 0: the factor) colourings.
struct FractalParams {
  int iterations = 1;
  int power = 2;
  double cReal = 0.0, cImaginary = 0.0;
  int magnetType = 1;
  bool juliaForm = false;  // magnet: the Julia form (c given), else the Mandelbrot form
  FractalColouring exterior{1, 1.0};
  FractalColouring interior{0, 1.0};
  bool operator==(const FractalParams& o) const {
    return iterations == o.iterations && power == o.power && cReal == o.cReal &&
           cImaginary == o.cImaginary && magnetType == o.magnetType && juliaForm == o.juliaForm &&
           exterior.type == o.exterior.type && exterior.factor == o.exterior.factor &&
           interior.type == o.interior.type && interior.factor == o.interior.factor;
  }
  bool operator!=(const FractalParams& o) const { return !(*this == o); }
};

// POV-Ray's default frequency: 0 for quilted, image_pattern and object (their values are
// used unwrapped), 1 otherwise.
constexpr double defaultFrequency(PatternType type) {
  return type == PatternType::quilted || type == PatternType::image || type == PatternType::object
             ? 0.0
             : 1.0;
}

// The patterns that take FractalParams.
constexpr bool isFractal(PatternType type) {
  return type == PatternType::mandel || type == PatternType::julia || type == PatternType::magnet;
}

struct PigmentFunction;  // pigment_function.h

// A function pattern's expression (the contract's expressions, of x, y and z; the names
// that stood for numbers with their values; the pigments it calls) and its compiled field.
struct PatternFunction {
  std::string text;
  std::vector<std::pair<std::string, double>> constants;
  std::shared_ptr<const ScalarField> field;
  std::vector<std::shared_ptr<const PigmentFunction>> pigments{};
};

// pigment-pattern's pigment: a plain colour or a texture (scenegraph/texture_spec.h; its
// `at` unused).
struct TextureMapEntry;
struct ImagePattern;   // image_pattern.h
struct ObjectPattern;  // object_pattern.h

// POV-Ray's default number_of_waves, and the most sources Lucent's ripples and waves take
// (each costs a sine at every evaluation).
constexpr int kDefaultWaveSources = 10;
constexpr int kMaxWaveSources = 1000;

struct PatternSpec {
  PatternType type = PatternType::bozo;
  PatternPlacement placement;
  Vec3 axis{0.0, 1.0, 0.0};  // gradient's direction (normalised when evaluated, as POV-Ray)
  int arms = 1;              // spiral1, spiral2
  double frequency = 1.0;    // 0 leaves the value unwrapped; parsers start from defaultFrequency
  double phase = 0.0;
  std::optional<WaveShape> wave;  // nullopt: POV-Ray's default for the type
  double exponent = 1.0;          // poly_wave's exponent
  CrackleParams crackle;
  QuiltedParams quilted;
  FractalParams fractal;
  double agateTurb = 1.0;  // agate's turbulence scale (POV-Ray's agate_turb)
  // ripples and waves: how many of POV-Ray's fixed wave sources they sum (its
  // global_settings number_of_waves, 1 to kMaxWaveSources).
  int waveSources = kDefaultWaveSources;
  SlopeParams slope;        // type slope
  int tiling = 1;           // tiling's number, 1..27 (render/patterns/tiling.h)
  FacetsParams facets;      // type facets
  PavementParams pavement;  // type pavement
  std::shared_ptr<const PatternFunction> function;  // type function
  std::shared_ptr<const TextureMapEntry> pigment;   // type pigment (pigment-pattern)
  std::shared_ptr<const ImagePattern> image;        // type image (image-pattern)
  std::shared_ptr<const ObjectPattern> object;      // type object
  int noiseGenerator = 2;  // 1 original, 2 range corrected (3.7's default), 3 Perlin

  WaveShape waveShape() const { return wave ? *wave : patternTypeInfo(type).wave; }
};

// POV-Ray's filter and transmit of a pattern's colour (the f and t of its rgbft): where
// the texture takes such a colour the surface lets light through, tinted by the colour
// (filter) or not (transmit), and its own light is scaled by 1 - filter - transmit
// (docs/scene-language.md, "Filter and transmit"). Both 0: an opaque colour.
struct FilterTransmit {
  float filter = 0.0f;
  float transmit = 0.0f;
  bool any() const { return filter != 0.0f || transmit != 0.0f; }
  bool operator==(const FilterTransmit& o) const {
    return filter == o.filter && transmit == o.transmit;
  }
  bool operator!=(const FilterTransmit& o) const { return !(*this == o); }
};

// A texture's colour at a point with its filter and transmit (POV-Ray's RGBFT colour).
struct PigmentColor {
  Color rgb{1.0f};
  FilterTransmit ft;
};

// A colour map: entries sorted by `at`, colours (and filter and transmit) interpolated
// linearly between them and constant beyond the ends. An empty map is POV-Ray's grey map
// [0 black][1 white].
struct ColorMapEntry {
  ColorMapEntry() = default;
  ColorMapEntry(double at_, const Color& color_, const FilterTransmit& ft_ = {})
      : at(at_), color(color_), ft(ft_) {}
  double at = 0.0;
  Color color{0.0f};
  FilterTransmit ft;
};
struct ColorMap {
  std::vector<ColorMapEntry> entries;
  // Some entry has a filter or a transmit: only then is the map looked up with them.
  bool seeThrough() const {
    for (const ColorMapEntry& e : entries)
      if (e.ft.any()) return true;
    return false;
  }
};

// POV-Ray's hexagon: three colours on hexagons in the x-z plane (defaults as POV-Ray's).
struct HexagonSpec {
  Color colors[3] = {Color(0.0f, 0.0f, 1.0f), Color(0.0f, 1.0f, 0.0f), Color(1.0f, 0.0f, 0.0f)};
  FilterTransmit ft[3] = {};
  bool seeThrough() const { return ft[0].any() || ft[1].any() || ft[2].any(); }
};

// POV-Ray's brick: color1 is the mortar, color2 the brick (defaults as POV-Ray's).
struct BrickSpec {
  Color color1{0.5f, 0.5f, 0.5f};
  Color color2{0.6f, 0.15f, 0.15f};
  FilterTransmit ft1{}, ft2{};
  double mortar = 0.5;
  Vec3 size{8.0, 3.0, 4.5};
};

struct WeightedNormal;  // below NormalSpec
struct NormalMapEntry;  // below NormalSpec

// POV-Ray's block patterns as a normal's pattern (`normal { checker normal {..} normal {..} }`):
// the cell's index (checker 0 or 1, hexagon 0 to 2, brick 0 mortar or 1 brick) picks the
// entry of the normal's list.
enum class NormalBlock { none, checker, hexagon, brick };

// An entry of POV-Ray's slope_map: at the pattern value `at`, the height and the slope the
// bumps take (its `[at <height, slope>]`).
struct SlopeMapEntry {
  double at = 0.0;
  double height = 0.0;
  double slope = 0.0;
};

// A normal perturbation: POV-Ray's `normal { PATTERN depth }` (depth is its bump_size).
struct NormalSpec {
  PatternSpec pattern;
  double depth = 0.5;
  // POV-Ray's `normal { average normal_map { [w N] ... } }`: when not empty, the normal is
  // the weighted mean of these normals (each bent at the point the pattern's placement
  // gives, in its space), normalised; the pattern's type and values and depth are unused.
  std::vector<WeightedNormal> average{};
  // POV-Ray's normal_map (entries in ascending `at`) or, with `block`, a block pattern's
  // list of normals (entries at 0, 1, 2): the pattern's value picks one entry or blends two
  // bent normals, each bent at the pattern's point in its space; depth is unused.
  std::vector<NormalMapEntry> map{};
  NormalBlock block = NormalBlock::none;
  BrickSpec brick;  // block brick: its size and mortar (the colours are unused)
  // POV-Ray's slope_map (entries in ascending `at`): the pattern's value becomes a height
  // by the entries' heights and slopes (Hermite cubics) before the slope is estimated.
  std::vector<SlopeMapEntry> slopeMap{};
  // POV-Ray's accuracy: the distance at which the slope of a pattern's value is sampled
  // (patterns whose normal is their own, bumps to quilted, do not sample).
  double accuracy = 0.02;
  // Where the bent normal faces away from the viewer: false (Lucent's rule) shades with the
  // unperturbed normal there; true keeps the bent one, as POV-Ray does.
  bool keepFacingAway = false;
  // bend-space="world" (a uv-mapped normal only): the world normal itself is carried into
  // pattern space by the placement and bent there, as POV-Ray bends the world normal by a
  // `normal { uv_mapping ... }`; otherwise (object) the shape's object-space normal is, as
  // POV-Ray bends it in a `texture { uv_mapping ... }`.
  bool bendInWorld = false;
};

struct WeightedNormal {
  double weight = 1.0;
  NormalSpec normal;
};

// An entry of a normal map or a block pattern's list: its value and its normal, or (flat)
// none: the normal left as the map's pattern space has it (POV-Ray's block list with fewer
// normals than cells).
struct NormalMapEntry {
  double at = 0.0;
  bool flat = false;
  NormalSpec normal;
};

}  // namespace lucent
