// The value syntax of attributes (contract, "Lexical rules"): decimal numbers, vectors of
// three numbers separated by spaces and/or commas, colours (3 numbers, 1 number for grey,
// or #rrggbb or a CSS name in sRGB), booleans, integers. Each parser returns the value or an error
// message without location; the caller names the element and attribute.
#pragma once

#include "images/srgb_decoding.h"
#include "primitives/math.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lucent {

template <class T>
struct Parsed {
  std::optional<T> value;
  std::string error;  // set when value is empty
  explicit operator bool() const { return value.has_value(); }
  const T& operator*() const { return *value; }
  const T* operator->() const { return &*value; }
};

// One decimal number (a leading '+' is allowed). `inf` (and `+inf`, `-inf`, `infinity`)
// only if allowInfinity; NaN and hexadecimal never; trailing junk ("1.5x") is an error.
// A finite magnitude above kMaxMagnitude (1e30) is an error unless allowInfinity, and so
// is a nonzero one below kMinMagnitude (1e-30).
Parsed<double> parseNumber(std::string_view text, bool allowInfinity = false);

// Finite numbers separated by whitespace and/or single commas ("1 2 3", "1,2,3", "1, 2").
Parsed<std::vector<double>> parseNumberList(std::string_view text);

// Exactly three finite numbers.
Parsed<Vec3> parseVector(std::string_view text);

// A decimal integer without sign, exponent or fraction ("640", not "640.0").
Parsed<long long> parseInteger(std::string_view text);
// Non-negative integers separated like numbers.
Parsed<std::vector<long long>> parseIntegerList(std::string_view text);

struct ParsedColor {
  Color color{0.0f};
  bool scalar = false;  // written as one number
};
// 3 numbers (linear RGB), 1 number (grey), #rrggbb or a CSS colour name (sRGB-encoded,
// decoded to linear).
Parsed<ParsedColor> parseColor(std::string_view text);

// srgbToLinear(c): sRGB's exact decoding, shared with image files.

// "true" or "false".
Parsed<bool> parseBool(std::string_view text);

// The text without leading and trailing whitespace.
std::string_view trim(std::string_view text);

}  // namespace lucent
