#include "srgb_decoding.h"

#include <array>
#include <cmath>

namespace lucent {

double srgbToLinear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

namespace {

const std::array<float, 256>& byteTable() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[i] = static_cast<float>(srgbToLinear(i / 255.0));
    return t;
  }();
  return table;
}

}  // namespace

void decodeSrgbCodeValues(float* values, std::size_t count, int top) {
  const float scale = static_cast<float>(top);
  if (top == 255) {
    const auto& table = byteTable();
    for (std::size_t i = 0; i < count; ++i)
      values[i] = table[static_cast<std::size_t>(std::lround(values[i] * scale)) & 255];
    return;
  }
  for (std::size_t i = 0; i < count; ++i) {
    const long code = std::lround(values[i] * scale);
    values[i] = static_cast<float>(srgbToLinear(static_cast<double>(code) / top));
  }
}

}  // namespace lucent
