// Small helpers the scene reader's files share: naming keywords, reading POV-Ray's values
// into the scene graph's types.
#pragma once

#include "token_stream.h"

#include "primitives/isosurface.h"
#include "primitives/math.h"
#include "scenegraph/pattern.h"
#include "scenegraph/texture_spec.h"

#include <array>
#include <functional>
#include <string_view>

namespace lucent::sdl {

// A reserved word the core leaves to the scene reader ("sphere", "finish"...).
inline bool isWord(const Token& t, std::string_view word) {
  return t.kind == TokenKind::Keyword && t.text() == word;
}

// What follows a pattern's keyword (read_patterns.cpp): gradient's axis, the spirals'
// arms, the fractals' constant and iterations; the type's default frequency.
void readPatternArguments(const Token& t, TokenStream& in, PatternSpec& s);

// A map entry's value (read_maps.cpp): required in a map, an optional weight (1 if left
// out) in an average's.
double entryValue(TokenStream& in, bool average);
// POV-Ray's check of a pavement once its block is read (`end`, its closing token): the
// corners' types modulo 3, the form modulo 4 (squares) or 3, the sides, tiles and
// arrangement within POV-Ray's limits, else its errors. Other patterns (or none) pass.
void settlePavement(const Token& end, TokenStream& in, PatternSpec* s);

// A shape's keyword, those Lucent refuses included (read_shapes.cpp).
bool isShapeKeyword(std::string_view word);

// A 2-D vector <u, v> (a float is promoted), read_shapes.cpp.
Vec2 parseUv(TokenStream& in);
// `contained_by { box { A, B } | sphere { C, R } }` after its keyword, in Lucent's space
// (read_isosurface.cpp); a sphere's radius is not checked.
IsosurfaceContainer readContainedBy(TokenStream& in);

inline Vec3 toVec3(const std::array<double, 3>& v) { return Vec3(v[0], v[1], v[2]); }

// Whether `t` starts a float, vector or colour expression (POV-Ray's optional arguments):
// the language core's own test.
inline bool startsNumber(const Token& t) { return startsExpression(t); }

// Whether `t` starts a colour (`color`, `rgb`..., or an expression).
inline bool isColourStart(const Token& t) {
  if (t.kind == TokenKind::Keyword)
    return t.kw == Kw::k_color || t.kw == Kw::k_colour || isColourKey(t.kw);
  return startsNumber(t);
}

// Reads the tokens up to the brace that closes the block `depth` levels out (the opening
// braces already read), nested blocks included.
inline void skipToClose(TokenStream& in, int depth) {
  while (depth > 0) {
    const Token& t = in.next();
    if (t.kind == TokenKind::End) in.error(t, "the block is not closed ('}' expected)");
    if (t.is("{")) ++depth;
    if (t.is("}")) --depth;
  }
}

// A `{ ... }` block that comes next, read whole; nothing when none comes.
inline void skipBlock(TokenStream& in) {
  if (!in.peek().is("{")) return;
  in.next();
  skipToClose(in, 1);
}

// Every pattern of a texture, those of the pigments in its maps and lists too
// (scene_reader.cpp).
void forEachTexturePattern(Texture& t, const std::function<void(PatternSpec&)>& f);

// The item an identifier token names, or null.
inline const Item* itemOf(const Token& t) {
  if (t.kind != TokenKind::Identifier) return nullptr;
  const Value* v = t.value();
  return v && v->type == ValueType::Item ? v->item.get() : nullptr;
}

// An optional boolean after a flag keyword (`hollow`, `hollow off`): true when absent.
inline bool optionalBool(TokenStream& in) {
  if (!startsNumber(in.peek())) return true;
  return in.parseFloat() != 0.0;
}

struct PovColour {
  Color rgb{0.0f};
  float filter = 0.0f;
  float transmit = 0.0f;
};
inline PovColour readColour(TokenStream& in) {
  const std::array<double, 5> c = in.parseColour();
  return {Color(static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])),
          static_cast<float>(c[3]), static_cast<float>(c[4])};
}

}  // namespace lucent::sdl
