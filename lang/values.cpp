#include "values.h"

#include "color_names.h"
#include "did_you_mean.h"
#include "pov_library.h"

#include "primitives/value_limits.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace lucent {

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string quote(std::string_view text) { return "'" + std::string(text) + "'"; }

// Splits a list into number tokens: separators are whitespace with at most one comma.
// Returns false (with error) on an empty field such as "1,,2" or a leading comma.
bool splitList(std::string_view text, std::vector<std::string_view>& tokens, std::string& error) {
  size_t i = 0;
  bool comma = true;  // a comma is not allowed before the first token
  bool first = true;
  while (i < text.size()) {
    char c = text[i];
    if (isSpace(c)) {
      ++i;
      continue;
    }
    if (c == ',') {
      if (comma) {
        error = first ? "unexpected ',' before the first value in " + quote(text)
                      : "two ',' without a value between them in " + quote(text);
        return false;
      }
      comma = true;
      ++i;
      continue;
    }
    size_t start = i;
    while (i < text.size() && !isSpace(text[i]) && text[i] != ',') ++i;
    tokens.push_back(text.substr(start, i - start));
    comma = false;
    first = false;
  }
  if (comma && !first) {
    error = "unexpected ',' after the last value in " + quote(text);
    return false;
  }
  return true;
}

}  // namespace

std::string_view trim(std::string_view text) {
  while (!text.empty() && isSpace(text.front())) text.remove_prefix(1);
  while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
  return text;
}

Parsed<double> parseNumber(std::string_view text, bool allowInfinity) {
  std::string_view t = trim(text);
  std::string_view digits = t;
  // std::from_chars takes no leading '+' (and no hex without chars_format::hex: good).
  if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+')
    digits.remove_prefix(1);
  double value = 0.0;
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || end != digits.data() + digits.size() ||
      (ec != std::errc() && ec != std::errc::result_out_of_range))
    return {std::nullopt, "expected a number, got " + quote(t)};
  // from_chars leaves the value unset on overflow and on underflow alike: refuse both.
  if (ec == std::errc::result_out_of_range)
    return {std::nullopt, "the number " + quote(t) + " is out of the range of double precision"};
  if (std::isnan(value))
    return {std::nullopt, "expected a number, got " + quote(t) + " (NaN is not allowed)"};
  if (std::isinf(value) && !allowInfinity)
    return {std::nullopt, "expected a finite number, got " + quote(t) +
                              " (inf is allowed only for distances that may be infinite)"};
  if (!allowInfinity && std::abs(value) > kMaxMagnitude)
    return {std::nullopt,
            "the number " + quote(t) + " is too large (the limit is 1e30 in magnitude)"};
  if (value != 0.0 && std::abs(value) < kMinMagnitude)
    return {std::nullopt,
            "the number " + quote(t) +
                " is too small (a nonzero number must be at least 1e-30 in magnitude)"};
  return {value, {}};
}

Parsed<std::vector<double>> parseNumberList(std::string_view text) {
  std::vector<std::string_view> tokens;
  std::string error;
  if (!splitList(text, tokens, error)) return {std::nullopt, error};
  std::vector<double> values;
  values.reserve(tokens.size());
  for (std::string_view tok : tokens) {
    Parsed<double> n = parseNumber(tok);
    if (!n) return {std::nullopt, n.error};
    values.push_back(*n);
  }
  return {std::move(values), {}};
}

Parsed<Vec3> parseVector(std::string_view text) {
  auto list = parseNumberList(text);
  if (!list) return {std::nullopt, list.error};
  const auto& v = *list;
  if (v.size() != 3)
    return {std::nullopt,
            "expected 3 numbers, got " + std::to_string(v.size()) + " (" + quote(trim(text)) + ")"};
  return {Vec3(v[0], v[1], v[2]), {}};
}

Parsed<long long> parseInteger(std::string_view text) {
  std::string_view t = trim(text);
  std::string_view digits = t;
  if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-') digits.remove_prefix(1);
  long long value = 0;
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || end != digits.data() + digits.size())
    return {std::nullopt, "expected a whole number, got " + quote(t)};
  if (ec != std::errc()) return {std::nullopt, "the number " + quote(t) + " is too large"};
  return {value, {}};
}

Parsed<std::vector<long long>> parseIntegerList(std::string_view text) {
  std::vector<std::string_view> tokens;
  std::string error;
  if (!splitList(text, tokens, error)) return {std::nullopt, error};
  std::vector<long long> values;
  values.reserve(tokens.size());
  for (std::string_view tok : tokens) {
    Parsed<long long> n = parseInteger(tok);
    if (!n) return {std::nullopt, n.error};
    values.push_back(*n);
  }
  return {std::move(values), {}};
}

namespace {

// "pov:NAME": a colour of POV-Ray's colors.inc (and the other standard includes), linear.
Parsed<ParsedColor> povColor(std::string_view t) {
  const PovLibrary* lib = povLibrary();
  const std::string name(t);
  if (!lib) return {std::nullopt, "this program has no 'pov:' library (the lucent command has it)"};
  auto it = lib->colours.find(name);
  if (it == lib->colours.end()) {
    std::string what = lib->materials.count(name)
                           ? " ('" + name + "' is a texture: material=\"" + name + "\" takes it)"
                           : didYouMean(name, lib->colourNames);
    return {std::nullopt,
            "POV-Ray's library has no colour '" + name.substr(kPovPrefix.size()) + "'" + what};
  }
  const std::array<float, 5>& c = it->second;
  if (c[3] != 0.0f || c[4] != 0.0f)
    return {std::nullopt, fmt::format("'{}' has filter {} and transmit {}, which a colour here "
                                      "cannot hold: write its red, green and blue ({} {} {}) "
                                      "and the filter or transmit where the element takes them",
                                      name, c[3], c[4], c[0], c[1], c[2])};
  ParsedColor pc;
  pc.color = Color(c[0], c[1], c[2]);
  return {pc, {}};
}

}  // namespace

Parsed<ParsedColor> parseColor(std::string_view text) {
  std::string_view t = trim(text);
  if (!t.empty() && t[0] == '#') {
    auto hex = [](char c) -> int {
      if (c >= '0' && c <= '9') return c - '0';
      if (c >= 'a' && c <= 'f') return c - 'a' + 10;
      if (c >= 'A' && c <= 'F') return c - 'A' + 10;
      return -1;
    };
    bool ok = t.size() == 7;
    for (size_t i = 1; ok && i < 7; ++i) ok = hex(t[i]) >= 0;
    if (!ok) return {std::nullopt, "expected #rrggbb (six hexadecimal digits), got " + quote(t)};
    ParsedColor pc;
    for (int k = 0; k < 3; ++k) {
      int byte = hex(t[1 + 2 * k]) * 16 + hex(t[2 + 2 * k]);
      pc.color[k] = static_cast<float>(srgbToLinear(byte / 255.0));
    }
    return {pc, {}};
  }
  if (t.rfind(kPovPrefix, 0) == 0) return povColor(t);
  // A word is a CSS colour name: sRGB like #rrggbb.
  if (!t.empty() && std::isalpha(static_cast<unsigned char>(t[0]))) {
    bool word = std::all_of(t.begin(), t.end(), [](char c) {
      return std::isalpha(static_cast<unsigned char>(c)) != 0;
    });
    // nan and inf are numbers to the number parser, which says why they are refused.
    std::string lower(t);
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower == "nan" || lower == "inf" || lower == "infinity") word = false;
    if (word) {
      auto srgb = cssColorByName(t);
      if (!srgb)
        return {std::nullopt, "unknown colour name " + quote(t) + didYouMean(t, cssColorNames()) +
                                  "; a colour is 3 numbers, 1 number for grey, #rrggbb or a CSS "
                                  "colour name"};
      ParsedColor pc;
      const uint8_t bytes[3] = {srgb->r, srgb->g, srgb->b};
      for (int k = 0; k < 3; ++k) pc.color[k] = static_cast<float>(srgbToLinear(bytes[k] / 255.0));
      return {pc, {}};
    }
  }
  auto list = parseNumberList(t);
  if (!list) return {std::nullopt, list.error};
  const auto& v = *list;
  ParsedColor pc;
  if (v.size() == 1) {
    pc.color = Color(static_cast<float>(v[0]));
    pc.scalar = true;
  } else if (v.size() == 3) {
    pc.color = Color(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
  } else {
    return {std::nullopt,
            "expected a colour (3 numbers, 1 number for grey, #rrggbb or a CSS colour name), got " +
                std::to_string(v.size()) + " numbers (" + quote(t) + ")"};
  }
  // Unreachable while numbers stop at kMaxMagnitude (1e30 < FLT_MAX); kept should that change.
  if (!std::isfinite(pc.color.r) || !std::isfinite(pc.color.g) || !std::isfinite(pc.color.b))
    return {std::nullopt, "the colour " + quote(t) + " is too large for a float"};
  return {pc, {}};
}

Parsed<bool> parseBool(std::string_view text) {
  std::string_view t = trim(text);
  if (t == "true") return {true, {}};
  if (t == "false") return {false, {}};
  return {std::nullopt, "expected true or false, got " + quote(t)};
}

}  // namespace lucent
