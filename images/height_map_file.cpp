// Reading a height field's image (height_map_file.h says what POV-Ray does and why).
#include "height_map_file.h"

#include "images/builtin/builtin_images.h"
#include "images/image_reading.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <vector>

namespace lucent {

namespace {

// What OpenImageIO hides: a PNG's colour type and bit depth (its IHDR chunk; a palette PNG's
// indices are read through libpng; a GIF's through giflib, readGif).
// A PNG's IHDR facts, when the file is a PNG.
struct PngFacts {
  bool png = false;
  int depth = 0, type = 0;
};

PngFacts pngFacts(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  unsigned char b[26] = {};
  f.read(reinterpret_cast<char*>(b), sizeof b);
  const std::streamsize n = f.gcount();
  static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (n < 26 || !std::equal(png, png + 8, b)) return {};
  const int depth = b[24], type = b[25];
  return {true, depth, type};
}

// A PNM file's header (P2, P3, P5, P6) names its maximum value, which Netpbm allows from 1
// to 65535; OpenImageIO reads others anyway (a maximum of 0 as 8-bit white), so they are
// refused here, before it.
void refuseBadPnmMaximum(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  char magic[2] = {};
  if (!f.read(magic, 2) || magic[0] != 'P' ||
      (magic[1] != '2' && magic[1] != '3' && magic[1] != '5' && magic[1] != '6'))
    return;
  // Width, height and maximum: whitespace-separated, with '#' comments to the end of a line.
  std::string token;
  for (int field = 0; field < 3; ++field) {
    token.clear();
    for (int c; (c = f.get()) != EOF;) {
      if (c == '#' && token.empty()) {
        while ((c = f.get()) != EOF && c != '\n' && c != '\r') {
        }
        continue;
      }
      if (std::isspace(c)) {
        if (token.empty()) continue;
        break;
      }
      token += static_cast<char>(c);
      if (token.size() > 20) break;
    }
  }
  const bool digits =
      !token.empty() && token.size() <= 6 &&
      std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; });
  const long max = digits ? std::stol(token) : -1;
  if (max < 1 || max > 65535)
    throw HeightMapError(fmt::format(
        "a PNM image whose maximum value is '{}': Netpbm allows 1 to 65535", token.substr(0, 20)));
}

// The limits every height map's image is held to, once its header is known.
void checkHeader(const ImageHeader& h) {
  if (h.width <= 0 || h.height <= 0 || h.channels <= 0)
    throw HeightMapError("the image has no pixels");
  if (h.width > kMaxHeightFieldSide || h.height > kMaxHeightFieldSide || h.channels > 4)
    throw HeightMapError(
        fmt::format("a {}x{} image with {} channels is beyond the height field's limit of {} "
                    "pixels a side and 4 channels",
                    h.width, h.height, h.channels, kMaxHeightFieldSide));
  if (h.width < 2 || h.height < 2)
    throw HeightMapError(fmt::format("a {}x{} image: a height field needs at least 2 x 2 pixels",
                                     h.width, h.height));
  if (h.floating || !(h.eightBit || h.sixteenBit))
    throw HeightMapError(
        "only 8- or 16-bit integer images are read as heights (not floating point)");
}

// An image's header and its values as floats of 0 to 1 (code / max), as the plugin gives.
struct StoredImage {
  ImageHeader header;
  std::vector<float> values;
};

// A PNG through libpng (images/builtin): no OpenImageIO to load for the commonest height
// map. Its values are the same code values OpenImageIO gives.
StoredImage readPng(const std::string& path) {
  PngPixels png;
  std::string error = readPngHeader(path, png);
  if (!error.empty()) throw HeightMapError(error);
  StoredImage out;
  out.header.width = png.width;
  out.header.height = png.height;
  out.header.channels = png.channels;
  out.header.eightBit = !png.sixteenBit;
  out.header.sixteenBit = png.sixteenBit;
  checkHeader(out.header);
  error = readPngValues(path, png);
  if (!error.empty()) throw HeightMapError(error);
  const float top = png.sixteenBit ? 65535.0f : 255.0f;
  out.values.resize(png.values.size());
  for (size_t i = 0; i < png.values.size(); ++i) out.values[i] = float(png.values[i]) / top;
  return out;
}

StoredImage readThroughPlugin(const std::string& path) {
  std::string error;
  std::unique_ptr<ImageReader> in = openImageReader(path, error);
  if (!in) throw HeightMapError(error.empty() ? std::string("not an image") : error);
  StoredImage out;
  out.header = in->header();
  checkHeader(out.header);
  const ImageHeader& h = out.header;
  out.values.resize(static_cast<size_t>(h.width) * h.height * h.channels);
  error = readImagePixels(*in, out.values.data());
  if (!error.empty()) throw HeightMapError(error);
  return out;
}

}  // namespace

bool isPotFileName(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".pot";
}

// POV-Ray reads a grey PNG of up to 8 bits through a grey colour map: each value v becomes
// c = v / max, then the grey of (c, c, c) by its float weights, stored truncated to 8 bits
// (base/image/png.cpp, image.cpp: RGB2Gray, SetGrayValue). This can lower v by one.
float povPngGrey(long v, int max) {
  const float c = float(v) / float(max);
  const float grey = c * 0.297f + c * 0.589f + c * 0.114f;
  return float(static_cast<unsigned char>(grey * 255.0f)) / 255.0f;
}

namespace {

// A GIF: POV-Ray's height is the palette index times 256 (the colours unused). A POT file
// (Fractint's, named .pot) is a GIF twice as wide as its field: a point's index in the left
// half is the height's high byte, the index as far right in the right half its low byte.
std::shared_ptr<const HeightMap> readGifHeights(const std::string& path) {
  GifPixels gif;
  const std::string error = readGif(path, gif);
  if (!error.empty()) throw HeightMapError(error);
  const bool pot = isPotFileName(path);
  if (pot && gif.width % 2 != 0)
    throw HeightMapError(fmt::format(
        "a POT file's image is twice as wide as its field: {} pixels is odd", gif.width));
  ImageHeader h;
  h.width = pot ? gif.width / 2 : gif.width;
  h.height = gif.height;
  h.channels = 1;
  h.eightBit = true;
  checkHeader(h);
  auto map = std::make_shared<HeightMap>();
  map->width = h.width;
  map->depth = h.height;
  map->values.resize(static_cast<size_t>(h.width) * h.height);
  for (int row = 0; row < h.height; ++row) {
    const int z = h.height - 1 - row;  // POV-Ray's z = 0 is the image's bottom row
    const std::uint8_t* line = &gif.indices[static_cast<size_t>(row) * gif.width];
    for (int x = 0; x < h.width; ++x)
      map->values[static_cast<size_t>(z) * h.width + x] =
          static_cast<uint16_t>(pot ? line[x] << 8 | line[x + h.width] : line[x] * 256);
  }
  return map;
}

}  // namespace

std::shared_ptr<const HeightMap> readHeightMapFile(const std::string& path) {
  if (isGifFile(path)) return readGifHeights(path);
  const PngFacts png = pngFacts(path);
  refuseBadPnmMaximum(path);
  const StoredImage image = png.png ? readPng(path) : readThroughPlugin(path);
  const ImageHeader& h = image.header;
  const std::vector<float>& px = image.values;

  auto map = std::make_shared<HeightMap>();
  map->width = h.width;
  map->depth = h.height;
  map->values.resize(static_cast<size_t>(h.width) * h.height);
  const float top = h.sixteenBit ? 65535.0f : 255.0f;
  const bool grey = h.channels < 3;
  for (int row = 0; row < h.height; ++row) {
    const int z = h.height - 1 - row;  // POV-Ray's z = 0 is the image's bottom row
    for (int x = 0; x < h.width; ++x) {
      const float* p = &px[(static_cast<size_t>(row) * h.width + x) * h.channels];
      // The stored code values, then POV-Ray's floats of them (value / max).
      auto code = [&](int c) { return static_cast<float>(std::lround(p[c] * top)) / top; };
      uint16_t v;
      if (png.png && png.type == 3) {
        // A palette image: POV-Ray's height is the palette index times 256.
        v = static_cast<uint16_t>(std::lround(p[0] * top) * 256);
      } else if (png.png && png.type == 0 && png.depth <= 8) {
        const int max = (1 << png.depth) - 1;
        v = static_cast<uint16_t>(povPngGrey(std::lround(p[0] * max), max) * 65535.0f);
      } else if (grey) {
        v = static_cast<uint16_t>(code(0) * 65535.0f);
      } else if (h.sixteenBit) {
        const float r = code(0), g = code(1), b = code(2);
        v = static_cast<uint16_t>(
            std::min(65535.0, (0.297 * r + 0.589 * g + 0.114 * b) * 65535.0f));
      } else {
        const float r = code(0), g = code(1);
        v = static_cast<uint16_t>((r * 256.0 + g) * 255.0);
      }
      map->values[static_cast<size_t>(z) * h.width + x] = v;
    }
  }
  return map;
}

}  // namespace lucent
