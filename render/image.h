// A linear-RGB float image, row 0 at the top (as image files store it).
#pragma once

#include "primitives/math.h"

#include <vector>

namespace lucent {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<Color> pixels;  // row-major, width * height

  Image() = default;
  Image(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(w) * h, Color(0.0f)) {}

  Color& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
  const Color& at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
};

// sRGB encoding of one linear value, clamped to [0,1] (IEC 61966-2-1), as POV-Ray writes PNGs.
float srgbEncode(float linear);
// The 8-bit value POV-Ray stores for a linear value: floor(clamp(sRGB(x))·255 + 0.5).
// Found in a table of the 255 values where the byte steps up, built once from that
// formula, so it is the formula's own answer for every float.
int srgbByte(float linear);
// The formula itself, computed (for the tests of srgbByte).
int srgbByteFormula(float linear);

}  // namespace lucent
