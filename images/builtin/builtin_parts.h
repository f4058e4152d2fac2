// The built-in writers, one per format; builtin_images.cpp picks one.
#pragma once

#include "images/image_plugin.h"

#include <string>

namespace lucent::builtin {

// builtin_png.cpp
WriteFailure writePng(const std::string& path, const ImageToWrite& image);
bool pngReadsBackComplete(const std::string& path, const ImageToWrite& image);

// builtin_ppm.cpp
WriteFailure writePpm(const std::string& path, const ImageToWrite& image);
bool ppmReadsBackComplete(const std::string& path, const ImageToWrite& image);

}  // namespace lucent::builtin
