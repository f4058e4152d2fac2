// Image files, the format chosen by the file's extension: PNG and PPM are written by the
// built-in part of the image layer (images/builtin/), everything else is read and written
// through OpenImageIO (the plugin of images/image_plugin.h, loaded on first use).
#pragma once

#include "image.h"

#include <optional>
#include <stdexcept>
#include <string>

namespace lucent {

// A file that cannot be written or read; the message names the file and the reason.
struct ImageIOError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

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

// How readImageFile() returns integer-encoded pixels.
enum class PixelDecoding {
  Linear,   // decoded from sRGB to linear RGB (float formats are returned as stored)
  AsStored  // the stored code values scaled to [0,1] (v/255, v/65535), no colour decoding
};

// Opens the file and reads its header only, throwing ImageIOError for everything
// readImageFile() would refuse from the header (not an image, no pixels, too large).
void checkImageFile(const std::string& path);

// Reads the first three channels (a grey image is repeated into all three).
Image readImageFile(const std::string& path, PixelDecoding decoding = PixelDecoding::Linear);

}  // namespace lucent
