// The textures of a <material> (its colour child) and the table of texture kinds: the
// element name, POV-Ray's keyword and one line of documentation of each alternative of
// Texture, which the parser's element names, the schema and the exporter read.
#pragma once

#include "pattern.h"
#include "source_loc.h"

#include "primitives/math.h"

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
};

// <image src scale>: an image looked up with the shape's (u,v). The pixels are loaded by
// the renderer; the scene keeps the resolved path.
struct ImageTexture {
  static constexpr TextureKindInfo kind{
      "image", "image_map", "An image looked up with the shape's (u,v) texture coordinates."};
  std::string path;  // resolved, absolute or relative to the working directory
  Vec2 scale{1.0, 1.0};
  SourceLoc loc;
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
};

// <hexagon> and <brick>: block patterns with colours of their own.
struct HexagonTexture {
  static constexpr TextureKindInfo kind{
      "hexagon", "hexagon", "POV-Ray's hexagon: three colours on hexagonal columns along y."};
  HexagonSpec spec;
  PatternPlacement placement;
};
struct BrickTexture {
  static constexpr TextureKindInfo kind{"brick", "brick",
                                        "POV-Ray's brick: bricks of color2 in mortar of color1."};
  BrickSpec spec;
  PatternPlacement placement;
};

// A new kind: its struct above with its `kind`, appended here; then its reader in
// lang/texture_parser.cpp, its colour in render/texture.cpp and its pigment in
// povray/pov_materials.cpp, each a visit or a template that does not compile without it
// (docs/architecture.md).
using Texture = std::variant<std::monostate, CheckerTexture, ImageTexture, PatternTexture,
                             HexagonTexture, BrickTexture>;

// Some colour of the texture has a filter or a transmit (the surface then lets light
// through where it takes it).
inline bool textureSeeThrough(const Texture& t) {
  if (const auto* p = std::get_if<PatternTexture>(&t)) return p->map.seeThrough();
  if (const auto* c = std::get_if<CheckerTexture>(&t)) return c->ft1.any() || c->ft2.any();
  if (const auto* h = std::get_if<HexagonTexture>(&t)) return h->spec.seeThrough();
  if (const auto* b = std::get_if<BrickTexture>(&t)) return b->spec.ft1.any() || b->spec.ft2.any();
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
