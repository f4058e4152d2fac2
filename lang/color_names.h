// The CSS named colours (CSS Color Module Level 4, 148 names with the grey/gray pairs) as
// sRGB bytes, for colour attributes written as a word ("midnightblue").
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace lucent {

struct SrgbBytes {
  uint8_t r, g, b;
};

// The colour of a CSS name, ASCII case-insensitive; nullopt for any other word.
std::optional<SrgbBytes> cssColorByName(std::string_view name);

// Every name, lower case, in alphabetical order (for "did you mean" hints and the docs).
const std::vector<std::string_view>& cssColorNames();

}  // namespace lucent
