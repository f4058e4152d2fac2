// sRGB's transfer function, decoded exactly: the one rule for colours written as sRGB in a
// scene (lang/values.cpp) and for the code values of 8- and 16-bit image files
// (render/image_read.cpp), so that a texture pixel of bytes (r, g, b) is the colour
// srgb(r, g, b) to the last bit.
#pragma once

#include <cstddef>

namespace lucent {

// The exact sRGB decoding (IEC 61966-2-1): c/12.92 at or below 0.04045, else
// ((c + 0.055)/1.055)^2.4; c in [0, 1].
double srgbToLinear(double c);

// Decodes `count` floats in place, each an integer code value over `top` (255 or 65535,
// as an image reader gives them): the exact decoding of that code value, rounded once to
// float. An 8-bit image takes its 256 values from a table.
void decodeSrgbCodeValues(float* values, std::size_t count, int top);

}  // namespace lucent
