// The output image, the format chosen by the file's extension: PNG and PPM are written by
// the built-in part of the image layer (images/builtin/), everything else through
// OpenImageIO (the plugin of images/image_plugin.h, loaded on first use). A file is only ever
// replaced by a complete one.
#pragma once

#include "render/image.h"
#include "render/image_read.h"

#include <optional>
#include <string>

namespace lucent {

// What each format stores:
//   png, jpg, ppm  8-bit sRGB-encoded, srgbByte() (POV-Ray's exact encoding), clamped
//   tif            16-bit sRGB-encoded, clamped
//   exr            32-bit float linear, unclamped (exact values, for comparisons)
//   hdr            Radiance RGBE linear, unclamped
enum class ImageFormat { Png, Jpeg, Ppm, Tiff, Exr, Hdr };

// The format for the path's extension (case-insensitive: .png .jpg .jpeg .ppm .tif .tiff
// .exr .hdr), or nullopt.
std::optional<ImageFormat> imageFormatForPath(const std::string& path);
// "png, exr, tif, jpg, hdr, ppm", for messages.
const char* supportedImageExtensions();

// Checks, before a long render, what can be checked early: a known extension, an existing
// folder, and that the path is not a folder or device. Throws ImageIOError.
void checkImageOutputPath(const std::string& path);

// Writes the image so that `path` is only ever replaced by a complete file: the pixels go
// to a hidden temporary file in the same folder, which is flushed to disk, read back and
// checked, and then renamed over `path` (an atomic replacement on POSIX file systems).
// On any failure the temporary file is removed, an existing `path` is untouched, and
// ImageIOError says what went wrong.
//
// `writer`: Automatic writes PNG and PPM with the built-in writers (and reads them back
// with the same), every other format through the plugin; Plugin sends every format through
// OpenImageIO, as before the built-in writers existed (the tests compare the two).
enum class ImageWriter { Automatic, Plugin };
void writeImageFile(const Image& image, const std::string& path,
                    ImageWriter writer = ImageWriter::Automatic);

}  // namespace lucent
