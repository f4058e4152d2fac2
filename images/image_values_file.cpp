// Reading an image as image_pattern's values (image_values_file.h says what POV-Ray does).
#include "image_values_file.h"

#include "images/builtin/builtin_images.h"
#include "images/height_map_file.h"
#include "images/image_reading.h"

#include <fmt/format.h>

#include <cmath>

namespace lucent {

namespace {

// One pixel as POV-Ray's image container hands it over: colour and alpha.
struct Pixel {
  float r, g, b, alpha;
};

// What is kept of each pixel.
enum class ValueRead { grey, alpha, red, transmit };

// The value image_pattern (or with `red` material_map) takes from a pixel.
float patternValue(const Pixel& p, ValueRead read, bool holdsTransparency) {
  if (read == ValueRead::red) return p.r;
  if (read == ValueRead::transmit) return holdsTransparency ? 1.0f - p.alpha : 0.0f;
  if (read == ValueRead::alpha) return holdsTransparency ? 1.0f - p.alpha : p.r;
  return static_cast<float>(0.297 * p.r + 0.589 * p.g + 0.114 * p.b);
}

void checkSize(int width, int height) {
  if (width <= 0 || height <= 0) throw ImageValuesError("the image has no pixels");
  if (width > kMaxImagePatternSide || height > kMaxImagePatternSide)
    throw ImageValuesError(fmt::format("a {}x{} image is beyond the limit of {} pixels a side",
                                       width, height, kMaxImagePatternSide));
}

// A PNG through libpng: its palette and bit depth are facts OpenImageIO hides.
std::shared_ptr<const ImageValueGrid> readPng(const std::string& path, ValueRead read) {
  const bool useAlpha = read == ValueRead::alpha;
  PngPixels png;
  std::string error = readPngHeader(path, png);
  if (!error.empty()) throw ImageValuesError(error);
  checkSize(png.width, png.height);
  const bool greyPalette = !png.palette && png.channels == 1 && png.storedDepth <= 8;
  if (greyPalette && png.transparencyChunk && useAlpha)
    throw ImageValuesError(
        "a grey PNG with a transparent grey (a tRNS chunk): POV-Ray reads its alpha from an "
        "undefined table; save the transparency as an alpha channel");
  error = readPngValues(path, png);
  if (!error.empty()) throw ImageValuesError(error);
  auto grid = std::make_shared<ImageValueGrid>();
  grid->width = png.width;
  grid->height = png.height;
  const size_t count = static_cast<size_t>(png.width) * png.height;
  grid->values.resize(count);
  const int n = png.channels;
  const float top = png.sixteenBit ? 65535.0f : 255.0f;
  const bool holdsTransparency = png.palette || n == 2 || n == 4;
  if (png.palette) {
    grid->indices.resize(count);
    grid->paletteSize = static_cast<int>(png.paletteColours.size());
  }
  for (size_t i = 0; i < count; ++i) {
    const std::uint16_t* v = &png.values[i * n];
    Pixel p{};
    if (png.palette) {
      const size_t index = v[0];
      grid->indices[i] = static_cast<std::uint8_t>(index);
      if (index >= png.paletteColours.size())  // POV-Ray's colour map would be read past its end
        throw ImageValuesError(
            fmt::format("a pixel's palette index {} is beyond the palette's {} "
                        "colours",
                        index, png.paletteColours.size()));
      const auto& c = png.paletteColours[index];
      p = {c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, c[3] / 255.0f};
    } else if (greyPalette) {
      // Widened to 8 bits by libpng: the stored value is v * 255 / max exactly.
      const int max = (1 << png.storedDepth) - 1;
      const float g = povPngGrey(std::lround(v[0] * max / 255.0), max);
      p = {g, g, g, 1.0f};
    } else if (n <= 2) {
      const float g = v[0] / top;
      p = {g, g, g, n == 2 ? v[1] / top : 1.0f};
    } else {
      p = {v[0] / top, v[1] / top, v[2] / top, n == 4 ? v[3] / top : 1.0f};
    }
    grid->values[i] = patternValue(p, read, holdsTransparency);
  }
  return grid;
}

// A GIF through giflib: a palette image, which POV-Ray's colour map always gives an alpha
// (1 but for the transparent entry), as a palette PNG's.
std::shared_ptr<const ImageValueGrid> readGifValues(const std::string& path, ValueRead read) {
  GifPixels gif;
  const std::string error = readGif(path, gif);
  if (!error.empty()) throw ImageValuesError(error);
  checkSize(gif.width, gif.height);
  auto grid = std::make_shared<ImageValueGrid>();
  grid->width = gif.width;
  grid->height = gif.height;
  grid->indices = gif.indices;
  grid->paletteSize = static_cast<int>(gif.paletteColours.size());
  grid->values.resize(gif.indices.size());
  for (size_t i = 0; i < gif.indices.size(); ++i) {
    const auto& c = gif.paletteColours[gif.indices[i]];
    const Pixel p{c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, c[3] / 255.0f};
    grid->values[i] = patternValue(p, read, true);
  }
  return grid;
}

// Other formats through OpenImageIO: integer code values over their maximum, floats as
// they are.
std::shared_ptr<const ImageValueGrid> readThroughPlugin(const std::string& path, ValueRead read) {
  std::string error;
  std::unique_ptr<ImageReader> in = openImageReader(path, error);
  if (!in) throw ImageValuesError(error.empty() ? std::string("not an image") : error);
  const ImageHeader& h = in->header();
  checkSize(h.width, h.height);
  if (h.channels <= 0 || h.channels > 4)
    throw ImageValuesError(fmt::format("an image of {} channels (1 to 4 are read)", h.channels));
  std::vector<float> px(static_cast<size_t>(h.width) * h.height * h.channels);
  error = readImagePixels(*in, px.data());
  if (!error.empty()) throw ImageValuesError(error);
  auto grid = std::make_shared<ImageValueGrid>();
  grid->width = h.width;
  grid->height = h.height;
  const size_t count = static_cast<size_t>(h.width) * h.height;
  grid->values.resize(count);
  const float top = h.sixteenBit ? 65535.0f : h.eightBit ? 255.0f : 0.0f;
  auto stored = [&](float x) { return top > 0.0f ? std::round(x * top) / top : x; };
  const int n = h.channels;
  const bool holdsTransparency = h.alphaChannel >= 0;
  for (size_t i = 0; i < count; ++i) {
    const float* v = &px[i * n];
    const float alpha = holdsTransparency ? stored(v[h.alphaChannel]) : 1.0f;
    Pixel p{};
    if (n - (holdsTransparency ? 1 : 0) < 3) p = {stored(v[0]), stored(v[0]), stored(v[0]), alpha};
    else p = {stored(v[0]), stored(v[1]), stored(v[2]), alpha};
    grid->values[i] = patternValue(p, read, holdsTransparency);
  }
  return grid;
}

// The file's values, by the reader that knows its palette, if it has one.
std::shared_ptr<const ImageValueGrid> readValues(const std::string& path, ValueRead read) {
  if (isPngFile(path)) return readPng(path, read);
  if (isGifFile(path)) return readGifValues(path, read);
  return readThroughPlugin(path, read);
}

}  // namespace

bool readsPalette(const std::string& path) { return isPngFile(path) || isGifFile(path); }

std::shared_ptr<const ImageValueGrid> readImagePatternValues(const std::string& path,
                                                             bool useAlpha) {
  return readValues(path, useAlpha ? ValueRead::alpha : ValueRead::grey);
}

std::shared_ptr<const ImageValueGrid> readImageTransmit(const std::string& path) {
  auto grid = readValues(path, ValueRead::transmit);
  for (float t : grid->values)
    if (t != 0.0f) return grid;
  return nullptr;
}

std::shared_ptr<const ImageValueGrid> paletteIndices(const std::string& path) {
  if (!readsPalette(path)) return nullptr;  // Lucent reads the palettes of PNGs and GIFs
  auto grid = readValues(path, ValueRead::red);
  return grid->indices.empty() ? nullptr : grid;
}

std::shared_ptr<const ImageValueGrid> readImageIndexValues(const std::string& path) {
  return readValues(path, ValueRead::red);
}

}  // namespace lucent
