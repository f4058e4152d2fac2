// The image files read without OpenImageIO: PNG (libpng) and JPEG (libjpeg-turbo), each
// giving what the plugin's OpenImageIO reader gives for the same file (header, channels,
// colour-space label and float pixels), so that textures and height maps in those formats
// never load the plugin (image_plugin.h says what that costs); and GIF (giflib), read only
// here, its palette's straight colours where OpenImageIO's reader blackens a transparent
// entry's.
#pragma once

#include "images/image_plugin.h"

#include <memory>
#include <string>

namespace lucent::builtin {

// builtin_png_reader.cpp: the file must start with PNG's signature.
std::unique_ptr<ImageReader> openPng(const std::string& path, std::string& error);

// builtin_jpeg_read.cpp
bool isJpegFile(const std::string& path);
std::unique_ptr<ImageReader> openJpeg(const std::string& path, std::string& error);

// builtin_gif_read.cpp
std::unique_ptr<ImageReader> openGif(const std::string& path, std::string& error);

}  // namespace lucent::builtin
