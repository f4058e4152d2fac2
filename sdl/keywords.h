// POV-Ray 3.7's reserved words: every word a scene may not use as an identifier, and the
// part of them the language core gives a meaning (functions, colour keys, directives). The
// rest (sphere, texture, camera...) start scene items, read by the scene reader.
#pragma once

#include <string_view>

namespace lucent::sdl {

// The reserved words the core reads, by what they are.
// clang-format off
#define LUCENT_SDL_FLOAT_FUNCTIONS(X) \
  X(abs) X(acos) X(acosh) X(asc) X(asin) X(asinh) X(atan) X(atan2) X(atanh) X(bitwise_and) \
  X(bitwise_or) X(bitwise_xor) X(ceil) X(clock) X(clock_on) X(cos) X(cosh) X(defined) \
  X(degrees) X(dimension_size) X(dimensions) X(div) X(exp) X(false) X(file_exists) X(floor) \
  X(inside) X(int) X(ln) X(log) X(max) X(min) X(mod) X(no) X(now) X(off) X(on) X(pi) X(pow) \
  X(radians) X(rand) X(seed) X(select) X(sin) X(sinh) X(sqrt) X(strcmp) X(strlen) X(tan) \
  X(tanh) X(true) X(val) X(vdot) X(version) X(vlength) X(yes) X(sum) X(prod)
#define LUCENT_SDL_VECTOR_FUNCTIONS(X) \
  X(vaxis_rotate) X(vcross) X(vnormalize) X(vrotate) X(vturbulence) X(x) X(y) X(z) X(trace) \
  X(min_extent) X(max_extent)
#define LUCENT_SDL_COLOUR_KEYS(X) \
  X(alpha) X(blue) X(filter) X(gray) X(green) X(red) X(rgb) X(rgbf) X(rgbft) X(rgbt) X(srgb) \
  X(srgbf) X(srgbft) X(srgbt) X(transmit)
#define LUCENT_SDL_STRING_FUNCTIONS(X) \
  X(str) X(vstr) X(concat) X(chr) X(datetime) X(substr) X(strupr) X(strlwr)
#define LUCENT_SDL_DIRECTIVES(X) \
  X(if) X(ifdef) X(ifndef) X(else) X(elseif) X(end) X(while) X(for) X(switch) X(case) \
  X(range) X(break) X(declare) X(local) X(undef) X(macro) X(include) X(debug) X(warning) \
  X(error) X(default) X(fopen) X(fclose) X(read) X(write) X(render) X(statistics)
#define LUCENT_SDL_OTHER_WORDS(X) X(t) X(u) X(v) X(color) X(colour) X(array) X(deprecated) X(once)
// clang-format on

#define LUCENT_SDL_ENUM(name) k_##name,
enum class Kw : unsigned short {
  None,  // an identifier, or a reserved word the core leaves to the scene reader
  LUCENT_SDL_FLOAT_FUNCTIONS(LUCENT_SDL_ENUM) FloatFunctionsEnd,
  LUCENT_SDL_VECTOR_FUNCTIONS(LUCENT_SDL_ENUM) VectorFunctionsEnd,
  LUCENT_SDL_COLOUR_KEYS(LUCENT_SDL_ENUM) ColourKeysEnd,
  LUCENT_SDL_STRING_FUNCTIONS(LUCENT_SDL_ENUM) StringFunctionsEnd,
  LUCENT_SDL_DIRECTIVES(LUCENT_SDL_ENUM) DirectivesEnd,
  LUCENT_SDL_OTHER_WORDS(LUCENT_SDL_ENUM)
};
#undef LUCENT_SDL_ENUM

inline bool isFloatFunction(Kw k) { return k > Kw::None && k < Kw::FloatFunctionsEnd; }
inline bool isVectorFunction(Kw k) {
  return k > Kw::FloatFunctionsEnd && k < Kw::VectorFunctionsEnd;
}
inline bool isColourKey(Kw k) { return k > Kw::VectorFunctionsEnd && k < Kw::ColourKeysEnd; }
inline bool isStringFunction(Kw k) { return k > Kw::ColourKeysEnd && k < Kw::StringFunctionsEnd; }
inline bool isDirective(Kw k) { return k > Kw::StringFunctionsEnd && k < Kw::DirectivesEnd; }

// The index of `word` among the reserved words, or -1 for an identifier.
int keywordIndex(std::string_view word);
std::string_view keywordName(int index);
// What the core does with the reserved word at `index` (Kw::None: nothing).
Kw keywordKind(int index);

}  // namespace lucent::sdl
