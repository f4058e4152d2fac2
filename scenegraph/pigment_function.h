// A pigment called as a function in a function expression (POV-Ray's
// `#declare F = function { pigment { P } }` and `F(x, y, z).red`): the pigment, evaluated by
// the renderer's pattern evaluator at the point the call's arguments give (in the pigment's
// own placement), and the one component of its colour the call takes.
#pragma once

#include "texture_spec.h"

#include <iterator>
#include <optional>
#include <string>
#include <string_view>

namespace lucent {

// The components a call takes: POV-Ray's members .red (.x .u), .green (.y .v), .blue (.z),
// .filter (.t), .transmit and .gray (.grey: 0.297 red + 0.589 green + 0.114 blue); and
// value, a <pattern>'s own value (POV-Ray's pattern functions, `function { pattern { } }`
// and f_noise3d), in double precision where the colours are single.
enum class PigmentComponent { red, green, blue, filter, transmit, gray, value };

inline constexpr std::string_view kPigmentComponentNames[] = {"red",      "green", "blue", "filter",
                                                              "transmit", "gray",  "value"};

inline std::string_view pigmentComponentName(PigmentComponent c) {
  return kPigmentComponentNames[static_cast<int>(c)];
}

inline std::optional<PigmentComponent> pigmentComponentNamed(std::string_view name) {
  for (size_t i = 0; i < std::size(kPigmentComponentNames); ++i)
    if (kPigmentComponentNames[i] == name) return static_cast<PigmentComponent>(i);
  return std::nullopt;
}

// `name(x, y, z)` in the expression is the component of the pigment's colour at (x, y, z),
// a point of the space the expression's own x, y and z are in.
struct PigmentFunction {
  std::string name;
  PigmentComponent component = PigmentComponent::red;
  Texture pigment;
};

// The component taken of a colour (POV-Ray's grey weights for gray).
inline double pigmentComponent(const PigmentColor& c, PigmentComponent component) {
  switch (component) {
    case PigmentComponent::red:
      return c.rgb.r;
    case PigmentComponent::green:
      return c.rgb.g;
    case PigmentComponent::blue:
      return c.rgb.b;
    case PigmentComponent::filter:
      return c.ft.filter;
    case PigmentComponent::transmit:
      return c.ft.transmit;
    case PigmentComponent::gray:
      return 0.297 * c.rgb.r + 0.589 * c.rgb.g + 0.114 * c.rgb.b;
    case PigmentComponent::value:  // (its pattern's value is taken before the colour)
      return c.rgb.r;
  }
  return 0.0;
}

}  // namespace lucent
