// The image files Lucent writes without OpenImageIO: PNG through libpng and binary PPM in
// plain code; and those it reads without it: PNG and JPEG (builtin_readers.h). A render
// that reads and writes only those never loads the plugin (image_plugin.h says what that
// costs). Each writes exactly what the plugin's OpenImageIO writer writes for the same
// ImageToWrite: the same pixels, bit depth and colour-space chunks, so the two paths give
// identical images (tests/images/builtin_png_test.cpp).
#pragma once

#include "images/image_plugin.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace lucent {

// Does the built-in part write this file? PNG of grey or RGB 8- or 16-bit integers tagged
// "sRGB" or "Linear", and binary PPM of 8-bit RGB. Not alpha: OpenImageIO's PNG writer
// un-premultiplies it, which the built-in writer does not copy.
bool builtinWrites(const ImageToWrite& image);

// Writes the file (`image.format` decides, whatever the path's extension); only for an
// image that builtinWrites() accepts.
WriteFailure builtinWriteFile(const std::string& path, const ImageToWrite& image);

// Opens a PNG, JPEG or GIF file (told by its first bytes) for reading without OpenImageIO:
// null with `error` empty for any other file, null with `error` set for a damaged one.
std::unique_ptr<ImageReader> builtinOpenFile(const std::string& path, std::string& error);

// Does the file decode completely as an image of this format and size? Every row is
// decoded (PNG: every zlib block and checksum up to the end chunk).
bool builtinReadsBackComplete(const std::string& path, const ImageToWrite& image);

// A PNG's stored values, read without OpenImageIO (builtin_png_read.cpp): for readers that
// take values as they are stored (height fields), with no colour conversion.
struct PngPixels {
  // Set before reading: widen as OpenImageIO does (a palette to its colours, a tRNS chunk
  // to an alpha channel) rather than keep palette indices and leave tRNS unapplied.
  bool expandAsOiio = false;
  int width = 0, height = 0;
  int channels = 0;         // after widening: 1 grey, 2 grey and alpha, 3 RGB, 4 RGBA
  bool sixteenBit = false;  // values of 0 to 65535; else 0 to 255
  int storedDepth = 0;      // the file's bit depth (1, 2, 4, 8 or 16)
  bool palette = false;     // a palette image: its values are the palette indices
  // A palette image's colours with their alphas (255 where its tRNS chunk says none).
  std::vector<std::array<std::uint8_t, 4>> paletteColours;
  bool transparencyChunk = false;     // the file has a tRNS chunk (left unapplied)
  bool srgbChunk = false;             // the file has an sRGB chunk
  double fileGamma = 0.0;             // its gAMA chunk's value (0.4545 for 2.2), 0 if none
  std::string colorSpaceText;         // a tEXt "oiio:ColorSpace" before the pixels, if any
  std::vector<std::uint16_t> values;  // rows top first, width x channels values each
};

// Whether the file starts with PNG's signature.
bool isPngFile(const std::string& path);
// The header's facts into `out`: "" or the reason the file cannot be read.
std::string readPngHeader(const std::string& path, PngPixels& out);
// The values of a file whose header `pixels` holds (a palette image's indices): "" or the
// reason.
std::string readPngValues(const std::string& path, PngPixels& pixels);

// A GIF's first image through giflib (builtin_gif_read.cpp), as POV-Ray 3.7 reads one: a
// palette image, its colours the image's own colour table or else the file's, the entry a
// graphic control extension marks transparent of alpha 0 (the others 255).
struct GifPixels {
  int width = 0, height = 0;
  std::vector<std::array<std::uint8_t, 4>> paletteColours;
  bool transparentIndex = false;      // an entry is transparent
  std::vector<std::uint8_t> indices;  // rows top first, width each
};

// Whether the file starts with GIF's signature (GIF87a or GIF89a).
bool isGifFile(const std::string& path);
// "" or the reason the file cannot be read (every index checked against the palette).
std::string readGif(const std::string& path, GifPixels& out);

}  // namespace lucent
