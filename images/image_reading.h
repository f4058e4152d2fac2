// Reading an image file, as every reader of textures and height maps does: PNG and JPEG
// by the built-in readers (builtin/builtin_readers.h), every other format through the
// plugin, each step shielded in sanitized builds from a leak of OpenImageIO 2.4's PNG
// reader on damaged files (image_reading.cpp).
#pragma once

#include "image_plugin.h"

#include <memory>
#include <string>

namespace lucent {

// builtinOpenFile(path, error) for PNG and JPEG, else imagePlugin().openFile(path, error).
std::unique_ptr<ImageReader> openImageReader(const std::string& path, std::string& error);
// in.readPixels(out): "" or the reason.
std::string readImagePixels(ImageReader& in, float* out);

}  // namespace lucent
