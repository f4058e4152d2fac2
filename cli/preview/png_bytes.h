// A PNG file in memory, for the images the preview page is sent.
#pragma once

#include "render/image.h"

#include <string>

namespace lucent::preview {

// 8-bit sRGB PNG bytes of `image` (srgbByte, as `render` writes PNGs), fast zlib level.
std::string pngBytes(const Image& image);

}  // namespace lucent::preview
