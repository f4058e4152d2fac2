// POV-Ray's pigment (a colour), finish and interior, and the Lucent material they make
// (docs/povray-import.md, "Finish and pigment").
#pragma once

#include "pov_space.h"

#include "scenegraph/material.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lucent::sdl {

// A colour map's entry as written, with its filter and transmit (kept per colour unless
// every entry has the same transmit and no filter: then they are the pigment's).
struct PovColorMapEntry {
  double at = 0.0;
  Color color{0.0f};
  float filter = 0.0f;
  float transmit = 0.0f;
};

// A colour map as written, in the ascending order Lucent's maps keep, giving every value
// the colour POV-Ray's search of the written order gives it (sdl/read_patterns.cpp).
std::vector<PovColorMapEntry> ascendingMap(const std::vector<PovColorMapEntry>& map);
// An ascending map with entries outside [0, 1], as entries within it that give every pattern
// value the same colour (the XML language's maps lie in [0, 1]).
std::vector<PovColorMapEntry> unitMap(const std::vector<PovColorMapEntry>& map);

// `pigment { rgbft <r, g, b, f, t> }` or `pigment { PATTERN color_map {...} modifiers }`.
// POV-Ray's default pigment, an object's when nothing gives it one, is black.
struct PovPigment {
  Color color{0.0f};  // a solid colour's
  float filter = 0.0f;
  float transmit = 0.0f;
  // A pattern: Lucent's texture, whose placement's patternFromObject is set when the
  // object that wears it becomes nodes (docs/povray-import.md, "Texture transforms").
  Texture pattern;
  // The pigment's transforms in POV-Ray's space, from pattern space to the space of the
  // object it was written on (sdl/scene_reader.h, PovObject).
  PovTransform transform;
  // The colours as written: the colour map, or a block pattern's colours at 0, 1, 2;
  // empty: the pattern's default map.
  std::vector<PovColorMapEntry> map;
  SourceLoc mapLoc;
  // `uv_mapping`: the rest of its block is a pigment read at the shape's (u, v, 0), placed by
  // its own transforms only (uvTransform: those written in that block); the transforms
  // that reach it later are POV-Ray's outer pigment's, which its uv_mapping ignores.
  bool uv = false;
  PovTransform uvTransform;
  // A block pattern's (checker, hexagon, brick) frequency, phase and wave, which POV-Ray
  // applies to its cell number 0, 1, 2 before it looks the number up in its list or colour
  // map (Evaluate_TPat); its keyword sets the frequency to 0, which leaves the number as it
  // is. Null: none given (shared, as pigments are copied often; replaced, never changed).
  std::shared_ptr<const PatternSpec> blockValue;

  bool patterned() const { return !std::holds_alternative<std::monostate>(pattern); }
  bool block() const {
    return std::holds_alternative<CheckerTexture>(pattern) ||
           std::holds_alternative<HexagonTexture>(pattern) ||
           std::holds_alternative<BrickTexture>(pattern);
  }
  // blockValue, or the value modifiers that leave the cell number as it is.
  const PatternSpec& blockValueSpec() const;
};

// The value a block pattern's cell `cell` (0, 1, 2) takes after its frequency, phase and wave
// (POV-Ray's Evaluate_TPat), from which its list or colour map is read.
double blockCellValue(const PatternSpec& value, int cell);
// Whether they leave every one of its `cells` numbers as it is.
bool blockValuesUnchanged(const PatternSpec& value, int cells);

// `normal { PATTERN amount modifiers }`: Lucent's normal pattern and, as a pigment's, its
// transforms from pattern space to the space of the object it was written on.
// The pattern of a pigment's texture, and where it is placed (null: none).
inline PatternSpec* specOf(Texture& t) {
  auto* p = std::get_if<PatternTexture>(&t);
  return p ? &p->pattern : nullptr;
}
inline PatternPlacement* placementOf(Texture& t) {
  if (auto* p = std::get_if<PatternTexture>(&t)) return &p->pattern.placement;
  if (auto* c = std::get_if<CheckerTexture>(&t)) return &c->placement;
  if (auto* h = std::get_if<HexagonTexture>(&t)) return &h->placement;
  if (auto* b = std::get_if<BrickTexture>(&t)) return &b->placement;
  if (auto* a = std::get_if<AverageTexture>(&t)) return &a->placement;
  if (auto* i = std::get_if<ImageTexture>(&t)) return &i->placement;
  return nullptr;
}

struct PovNormal {
  NormalSpec spec;
  std::optional<BumpMapSpec> bump;  // `bump_map { }` instead of a pattern
  PovTransform transform;
  bool average = false;  // `average` was read: its normal_map fills spec.average
  // A pattern was given (a #default normal may hold only a bump_size; POV-Ray then wants
  // one in every normal that starts from it).
  bool patterned = false;
  // Read at the shape's (u, v, 0): its own `uv_mapping`, its texture's or its object's,
  // placed by the transforms written in that block only (uvTransform). POV-Ray bends the
  // world normal for the normal's own and the object's (bendInWorld), and the normal in the
  // space of the transforms after the texture for a texture's.
  bool uv = false;
  bool ownUv = false;  // its own uv_mapping (uvTransform then stays that block's)
  bool bendInWorld = false;
  PovTransform uvTransform;
  SourceLoc uvLoc;  // its own uv_mapping's
};

// `reflection { MIN, MAX fresnel falloff exponent metallic }`, or `reflection C` alone
// (min = max = C).
struct PovReflection {
  Color min{0.0f};
  Color max{0.0f};
  bool fresnel = false;
  double falloff = 1.0;
  double exponent = 1.0;
  double metallic = 0.0;
};

// `finish { ... }` with POV-Ray 3.7's defaults (its Create_Finish): what an object without
// a finish gets, and what a finish block starts from unless `#default` changed it.
struct PovFinish {
  Color ambient{0.1f};
  Color emission{0.0f};
  double diffuse = 0.6;
  double brilliance = 1.0;
  double crand = 0.0;  // subtracted per light, times a random number and the pigment
  double phong = 0.0;
  double phongSize = 40.0;
  double specular = 0.0;
  double roughness = 0.05;  // the specular exponent is 1/roughness
  double metallic = 0.0;    // `metallic` alone is 1
  PovReflection reflection;
  bool conserveEnergy = false;
  double irid = 0.0;
  double iridThickness = 0.0;
  double iridTurbulence = 0.0;
  // POV-Ray 3.0's `ior` in a finish: at the end of an object whose texture is plain, it
  // becomes the object's interior's ior (POV-Ray's post-processing of each object).
  std::optional<double> ior;
};

// `interior { ior fade_distance fade_power fade_color }` (every object has one: ior 1).
struct PovInterior {
  double ior = 1.0;
  double fadeDistance = 0.0;
  double fadePower = 0.0;
  Color fadeColor{0.0f};
};

// `#default { pigment {...} finish {...} }`: what a texture starts from. A scene reader
// copies `finish` into each new finish block before reading its keywords (the keywords
// written change it), and gives an object without texture both.
struct PovDefaults {
  PovPigment pigment;
  std::optional<PovNormal> normal;  // `#default { normal {..} }`: what normals start from
  PovFinish finish;
};

struct MaterialImport {
  Material material;
  std::vector<std::string> differences;  // where Lucent's material differs from POV-Ray's
};
// The material of a one-layer texture: POV-Ray multiplies the pigment's colour by the
// finish and by the opacity 1 - filter - transmit; transmits pigment·filter + transmit.
// legacyOpacity (a scene of #version below 3.7): the opacity of a plain pigment is POV-Ray
// 3.6's 1 - (filter·max(r, g, b) + transmit), which POV-Ray 3.7 keeps for such scenes.
MaterialImport importMaterial(const PovPigment& pigment, const PovFinish& finish,
                              const PovInterior& interior, bool legacyOpacity = false);

}  // namespace lucent::sdl
