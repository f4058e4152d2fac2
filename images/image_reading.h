// Reading an image file through the plugin, as every reader of textures and height maps
// does: opening it and decoding its pixels, each step shielded in sanitized builds from
// a leak of OpenImageIO 2.4's PNG reader on damaged files (image_reading.cpp).
#pragma once

#include "image_plugin.h"

#include <memory>
#include <string>

namespace lucent {

// imagePlugin().openFile(path, error).
std::unique_ptr<ImageReader> openImageReader(const std::string& path, std::string& error);
// in.readPixels(out): "" or the reason.
std::string readImagePixels(ImageReader& in, float* out);

}  // namespace lucent
