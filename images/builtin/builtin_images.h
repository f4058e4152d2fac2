// The image files Lucent writes without OpenImageIO: PNG through libpng and binary PPM in
// plain code. A render to either never loads the plugin (image_plugin.h says what that
// costs). Each writes exactly what the plugin's OpenImageIO writer writes for the same
// ImageToWrite: the same pixels, bit depth and colour-space chunks, so the two paths give
// identical images (tests/images/builtin_png_test.cpp).
#pragma once

#include "images/image_plugin.h"

#include <string>

namespace lucent {

// Does the built-in part write this file? PNG of grey or RGB 8- or 16-bit integers tagged
// "sRGB" or "Linear", and binary PPM of 8-bit RGB. Not alpha: OpenImageIO's PNG writer
// un-premultiplies it, which the built-in writer does not copy.
bool builtinWrites(const ImageToWrite& image);

// Writes the file (`image.format` decides, whatever the path's extension); only for an
// image that builtinWrites() accepts.
WriteFailure builtinWriteFile(const std::string& path, const ImageToWrite& image);

// Does the file decode completely as an image of this format and size? Every row is
// decoded (PNG: every zlib block and checksum up to the end chunk).
bool builtinReadsBackComplete(const std::string& path, const ImageToWrite& image);

}  // namespace lucent
