// The textures of a <material> (its colour child) and the table of texture kinds: the
// element name, POV-Ray's keyword and one line of documentation of each alternative of
// Texture, which the parser's element names, the schema and the exporter read.
#pragma once

#include "gamma_curve.h"
#include "pattern.h"
#include "source_loc.h"

#include "primitives/math.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace lucent {

// What the parser, the schema and the exporter read about a texture kind.
struct TextureKindInfo {
  std::string_view element;  // <element> inside <material>; its schema type is element + "Type"
  std::string_view pov;      // POV-Ray's pigment keyword ("" for <pattern>: its type's)
  std::string_view doc;      // one line, for the schema
};

// An entry of a map or a list of whole textures (POV-Ray's pigment_map, a block pattern's
// list of pigments, average's map), defined below Texture: a plain colour or a texture.
struct TextureMapEntry;

// <checker color1 color2 scale transform turbulence...>: a solid 3-D checker in pattern
// space (the shape's object space carried by the placement, as <pattern>'s); the cube
// [0, scale)^3 of pattern space has color1.
struct CheckerTexture {
  static constexpr TextureKindInfo kind{
      "checker", "checker",
      "A solid 3-D checker of cubes of edge scale in the object space of the shape (placed by "
      "transform, as a pattern); the cube [0, scale)³ has color1 (as POV-Ray's checker)."};
  Color color1{1.0f};
  Color color2{0.0f};
  double scale = 1.0;
  PatternPlacement placement;
  FilterTransmit ft1{}, ft2{};  // color1's and color2's
  // POV-Ray's `checker pigment {..} pigment {..}`: two textures instead of the colours
  // (empty: the colours), each evaluated at the checker's pattern point divided by scale.
  std::vector<TextureMapEntry> pigments{};
};

// How an <image> finds its pixel: at the shape's (u,v), or projected from pattern space as
// POV-Ray's image_map `map_type` 0 (planar), 1 (spherical), 2 (cylindrical), 5 (torus).
enum class ImageProjection { uv, planar, spherical, cylindrical, torus };
// How the pixels around that point are blended (POV-Ray's `interpolate`: none, 2, 3, 4).
enum class ImageInterpolation { none, bilinear, bicubic, normalized };

struct ImageValueGrid;  // images/image_values_file.h, below the scene graph

// <palette index filter transmit>: a palette image's entry with a filter or transmit of its
// own (POV-Ray's image_map `filter N, F` and `transmit N, F`), each in place of the image's
// `filter`/`transmit` (its `all`) where given.
struct PaletteEntryFT {
  int index = 0;
  std::optional<float> filter, transmit;
  bool operator==(const PaletteEntryFT& o) const {
    return index == o.index && filter == o.filter && transmit == o.transmit;
  }
};

// <image src scale projection transform once interpolate filter transmit>: an image looked
// up with the shape's (u,v) or projected (render/image_projection.h). The pixels are loaded
// by the renderer; the scene keeps the resolved path.
struct ImageTexture {
  static constexpr TextureKindInfo kind{
      "image", "image_map",
      "An image looked up with the shape's (u,v) texture coordinates, or projected from "
      "pattern space as POV-Ray's image_map."};
  std::string path;  // resolved, absolute or relative to the working directory
  Vec2 scale{1.0, 1.0};
  SourceLoc loc;
  ImageProjection projection = ImageProjection::uv;
  PatternPlacement placement;  // a projected image's pattern space (unused at (u,v))
  bool once = false;           // one copy: outside it the surface is clear (transmit 1)
  ImageInterpolation interpolation = ImageInterpolation::bilinear;
  FilterTransmit all{};  // POV-Ray's filter all / transmit all, added to every pixel
  // Palette entries' own filter and transmit, and the image's palette indices (read with
  // the scene when there are entries; a palette PNG's).
  std::vector<PaletteEntryFT> palette{};
  std::shared_ptr<const ImageValueGrid> paletteIndices{};
  // use-alpha: the image's own transparency adds to each pixel's transmit (POV-Ray's
  // image_map reads it so); its 1 − alpha per pixel, read with the scene (null: opaque).
  bool useAlpha = false;
  std::shared_ptr<const ImageValueGrid> alphaTransmit{};
  // How the file's values encode light (<image gamma>, POV-Ray's image_map `gamma`): they
  // are decoded with it. None: Lucent's rule, integer files decoded from sRGB unless they
  // name another colour space, float files taken as linear.
  std::optional<GammaCurve> fileGamma{};

  // The filter and transmit of the pixels of palette index `index`.
  FilterTransmit paletteFT(int index) const {
    FilterTransmit ft = all;
    for (const PaletteEntryFT& e : palette)
      if (e.index == index) {
        ft.filter = e.filter.value_or(ft.filter);
        ft.transmit = e.transmit.value_or(ft.transmit);
      }
    return ft;
  }
  bool seeThrough() const {
    if (once || all.any() || alphaTransmit) return true;
    for (const PaletteEntryFT& e : palette)
      if (e.filter.value_or(0.0f) != 0.0f || e.transmit.value_or(0.0f) != 0.0f) return true;
    return false;
  }

  // Looked up with OpenImageIO's bilinear filter at (u,v), as before projections existed.
  bool plainUV() const {
    return projection == ImageProjection::uv && !once &&
           interpolation == ImageInterpolation::bilinear && !all.any() && palette.empty() &&
           !alphaTransmit;
  }
};

// <pattern type>: a procedural pattern's value turned into a colour by its colour map (an
// empty map: the value is the grey level).
struct PatternTexture {
  static constexpr TextureKindInfo kind{
      "pattern", "",
      "A procedural pattern (POV-Ray's of that name) in the shape's object space, through its "
      "colour map."};
  PatternSpec pattern;
  ColorMap map;
  // POV-Ray's pigment_map: whole textures at pattern values, blended as a colour map's
  // colours (filter and transmit too); used instead of `map` when not empty. Each is
  // evaluated at the pattern's point (after its transform and turbulence), so its own
  // placement composes with the pattern's.
  std::vector<TextureMapEntry> pigments{};
};

// <hexagon> and <brick>: block patterns with colours of their own.
struct HexagonTexture {
  static constexpr TextureKindInfo kind{
      "hexagon", "hexagon", "POV-Ray's hexagon: three colours on hexagonal columns along y."};
  HexagonSpec spec;
  PatternPlacement placement;
  std::vector<TextureMapEntry> pigments{};  // three textures instead of the colours (or none)
};
struct BrickTexture {
  static constexpr TextureKindInfo kind{"brick", "brick",
                                        "POV-Ray's brick: bricks of color2 in mortar of color1."};
  BrickSpec spec;
  PatternPlacement placement;
  std::vector<TextureMapEntry> pigments{};  // mortar's and brick's textures (or none)
};

// <average>: POV-Ray's `average pigment_map { [w P] ... }`, the textures' colours (filter
// and transmit too) weighted by w and divided by the sum of the weights, each evaluated at
// the average's pattern-space point.
struct AverageTexture {
  static constexpr TextureKindInfo kind{
      "average", "average",
      "POV-Ray's average: the weighted mean of whole textures, each placed inside the average's "
      "placement."};
  PatternPlacement placement;
  std::vector<TextureMapEntry> entries{};  // `at` is the weight
};

// A new kind: its struct above with its `kind`, appended here; then its reader in
// lang/texture_parser.cpp, its colour in render/texture.cpp and its pigment in
// povray/pov_materials.cpp, each a visit or a template that does not compile without it
// (docs/architecture.md).
using Texture = std::variant<std::monostate, CheckerTexture, ImageTexture, PatternTexture,
                             HexagonTexture, BrickTexture, AverageTexture>;

// An entry of a map or list of textures: `texture`, or where it holds none (monostate) the
// plain colour `color`. `at` is its pattern value in a pigment map, its weight in an
// average, and unused in a block pattern's list.
struct TextureMapEntry {
  double at = 0.0;
  PigmentColor color;
  Texture texture;
};

inline bool textureSeeThrough(const Texture& t);

// Some entry of a map or list is see-through.
inline bool entriesSeeThrough(const std::vector<TextureMapEntry>& entries) {
  for (const TextureMapEntry& e : entries)
    if (std::holds_alternative<std::monostate>(e.texture) ? e.color.ft.any()
                                                          : textureSeeThrough(e.texture))
      return true;
  return false;
}

// Some colour of the texture has a filter or a transmit (the surface then lets light
// through where it takes it); for maps and lists of textures, some entry's.
inline bool textureSeeThrough(const Texture& t) {
  if (const auto* p = std::get_if<PatternTexture>(&t))
    return p->pigments.empty() ? p->map.seeThrough() : entriesSeeThrough(p->pigments);
  if (const auto* c = std::get_if<CheckerTexture>(&t))
    return c->pigments.empty() ? c->ft1.any() || c->ft2.any() : entriesSeeThrough(c->pigments);
  if (const auto* h = std::get_if<HexagonTexture>(&t))
    return h->pigments.empty() ? h->spec.seeThrough() : entriesSeeThrough(h->pigments);
  if (const auto* b = std::get_if<BrickTexture>(&t))
    return b->pigments.empty() ? b->spec.ft1.any() || b->spec.ft2.any()
                               : entriesSeeThrough(b->pigments);
  if (const auto* a = std::get_if<AverageTexture>(&t)) return entriesSeeThrough(a->entries);
  if (const auto* i = std::get_if<ImageTexture>(&t)) return i->seeThrough();
  return false;
}

// The texture, or one nested in it, is an image (whose pixels a material loads: a sky or a
// pigment function, evaluated away from any material, cannot hold one).
inline bool textureHoldsImage(const Texture& t);
inline bool entriesHoldImage(const std::vector<TextureMapEntry>& entries) {
  for (const TextureMapEntry& e : entries)
    if (textureHoldsImage(e.texture)) return true;
  return false;
}
inline bool textureHoldsImage(const Texture& t) {
  if (std::holds_alternative<ImageTexture>(t)) return true;
  if (const auto* p = std::get_if<PatternTexture>(&t)) return entriesHoldImage(p->pigments);
  if (const auto* c = std::get_if<CheckerTexture>(&t)) return entriesHoldImage(c->pigments);
  if (const auto* h = std::get_if<HexagonTexture>(&t)) return entriesHoldImage(h->pigments);
  if (const auto* b = std::get_if<BrickTexture>(&t)) return entriesHoldImage(b->pigments);
  if (const auto* a = std::get_if<AverageTexture>(&t)) return entriesHoldImage(a->entries);
  return false;
}

// The placement a texture's point goes through first (null for none), and whether it is
// uv-mapped: evaluated at the shape's (u, v, 0).
inline const PatternPlacement* texturePlacement(const Texture& t) {
  if (const auto* p = std::get_if<PatternTexture>(&t)) return &p->pattern.placement;
  if (const auto* c = std::get_if<CheckerTexture>(&t)) return &c->placement;
  if (const auto* h = std::get_if<HexagonTexture>(&t)) return &h->placement;
  if (const auto* b = std::get_if<BrickTexture>(&t)) return &b->placement;
  if (const auto* a = std::get_if<AverageTexture>(&t)) return &a->placement;
  if (const auto* i = std::get_if<ImageTexture>(&t))
    return i->projection == ImageProjection::uv ? nullptr : &i->placement;
  return nullptr;
}
inline bool textureUvMapped(const Texture& t) {
  const PatternPlacement* p = texturePlacement(t);
  return p && p->uv;
}

// The texture or an entry of its maps and lists (at any depth) is uv-mapped.
inline bool textureUsesUv(const Texture& t);
inline bool entriesUseUv(const std::vector<TextureMapEntry>& entries) {
  for (const TextureMapEntry& e : entries)
    if (textureUsesUv(e.texture)) return true;
  return false;
}
inline bool textureUsesUv(const Texture& t) {
  if (textureUvMapped(t)) return true;
  if (const auto* p = std::get_if<PatternTexture>(&t)) return entriesUseUv(p->pigments);
  if (const auto* c = std::get_if<CheckerTexture>(&t)) return entriesUseUv(c->pigments);
  if (const auto* h = std::get_if<HexagonTexture>(&t)) return entriesUseUv(h->pigments);
  if (const auto* b = std::get_if<BrickTexture>(&t)) return entriesUseUv(b->pigments);
  if (const auto* a = std::get_if<AverageTexture>(&t)) return entriesUseUv(a->entries);
  return false;
}

// Every kind of texture, in Texture's order (monostate, no texture, left out).
template <class... Kinds>
std::vector<TextureKindInfo> textureKindsOf(const std::variant<std::monostate, Kinds...>*) {
  return {Kinds::kind...};
}
inline const std::vector<TextureKindInfo>& textureKinds() {
  static const std::vector<TextureKindInfo> kinds = textureKindsOf(static_cast<Texture*>(nullptr));
  return kinds;
}

}  // namespace lucent
