// An image read as POV-Ray 3.7's image_pattern reads it (core/support/imageutil.cpp,
// image_pattern; the parser reads its file without gamma correction): one value per pixel,
//   the grey level 0.297 r + 0.589 g + 0.114 b of its colour (in single precision), or
//   with use_alpha its transmit 1 - alpha where the image can hold transparency, and its
//   red channel where it cannot.
// Colours are the stored values over their maximum (v / 255, v / 65535), as POV-Ray's
// integer images give them: a palette PNG's or a GIF's from its palette (whose alphas, 1
// where its tRNS chunk or its transparent index gives none, make it an image that holds
// transparency), a grey PNG of up to 8
// bits through POV-Ray's grey colour map (images/height_map_file.h).
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace lucent {

struct ImageValuesError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The pixels' values, rows top first. `indices`: a palette image's palette indices (empty
// for other images).
struct ImageValueGrid {
  int width = 0;
  int height = 0;
  std::vector<float> values;
  std::vector<std::uint8_t> indices;
  int paletteSize = 0;  // the palette's entries (0 without one)
  float at(int x, int y) const { return values[static_cast<size_t>(y) * width + x]; }
};

// The largest image side read as a pattern.
constexpr int kMaxImagePatternSide = 16384;

// Throws ImageValuesError with the reason (the caller names the file).
std::shared_ptr<const ImageValueGrid> readImagePatternValues(const std::string& path,
                                                             bool useAlpha);

// An image as POV-Ray 3.7's material_map reads it (imageutil.cpp, material_map): a palette
// image's indices, and for every image each pixel's red channel (v / 255, v / 65535; a grey
// image's grey), whose value times 255 gives the material number where there is no palette.
std::shared_ptr<const ImageValueGrid> readImageIndexValues(const std::string& path);

// An image's own transparency as POV-Ray 3.7's image_map reads it: each pixel's transmit
// 1 − alpha (an alpha channel's, a palette PNG's tRNS entries'); null when the image holds
// no transparency or every pixel is opaque.
std::shared_ptr<const ImageValueGrid> readImageTransmit(const std::string& path);

// A palette image's indices (a bump map's heights with use_index, an image map's entries
// with their own filter and transmit): the grid of a palette PNG or of a GIF, null for an
// image without a palette (whose grey levels a bump map reads then).
std::shared_ptr<const ImageValueGrid> paletteIndices(const std::string& path);

// Whether Lucent reads the file's palette, when it has one: a PNG's or a GIF's (other
// formats' palettes OpenImageIO hides).
bool readsPalette(const std::string& path);

}  // namespace lucent
