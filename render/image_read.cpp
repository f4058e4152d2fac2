#include "image_read.h"
#include "working_gamma.h"

#include "images/builtin/builtin_images.h"
#include "images/image_reading.h"
#include "images/srgb_decoding.h"
#include "memory/system_memory.h"
#include "scenegraph/render_limits.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

namespace lucent {

namespace {

// Opens the file and refuses, from its header alone, what reading it would refuse.
std::unique_ptr<ImageReader> openCheckedImage(const std::string& path) {
  std::string error;
  std::unique_ptr<ImageReader> in = openImageReader(path, error);
  if (!in) throw ImageIOError(fmt::format("cannot read '{}': {}", path, error));
  const ImageHeader& spec = in->header();
  const int channels = spec.channels;
  if (spec.width <= 0 || spec.height <= 0 || channels <= 0)
    throw ImageIOError(fmt::format("cannot read '{}': the image has no pixels", path));
  // A small compressed file can claim an enormous image (a "decompression bomb"): refuse
  // it from its header, before any pixel is allocated.
  if (spec.width > kMaxImageSide || spec.height > kMaxImageSide || channels > 64)
    throw ImageIOError(
        fmt::format("cannot read '{}': a {}x{} image with {} channels is beyond the "
                    "limit of {} pixels a side",
                    path, spec.width, spec.height, channels, kMaxImageSide));
  // Float pixels as read, a decoded copy, and the linear RGB image kept.
  const std::uintmax_t need = std::uintmax_t(spec.width) * std::uintmax_t(spec.height) *
                              (2 * sizeof(float) * std::uintmax_t(channels) + sizeof(Color));
  if (auto available = availableMemoryBytes(); available && need > *available)
    throw ImageIOError(
        fmt::format("cannot read '{}': the {}x{} image needs about {} of memory, more "
                    "than the {} available",
                    path, spec.width, spec.height, formatBytes(need), formatBytes(*available)));
  return in;
}

// A PNG's values over their maximum, widened as the reader widens them (a palette to its
// colours, tRNS to alpha) but not premultiplied.
std::string readStraightPng(const std::string& path, std::vector<float>& out) {
  PngPixels png;
  png.expandAsOiio = true;
  std::string error = readPngHeader(path, png);
  if (error.empty()) error = readPngValues(path, png);
  if (!error.empty()) return error;
  if (png.values.size() != out.size()) return "the image's size changed while it was read";
  const float scale = png.sixteenBit ? 1.0f / 65535.0f : 1.0f / 255.0f;
  for (size_t i = 0; i < out.size(); ++i) out[i] = static_cast<float>(png.values[i]) * scale;
  return "";
}

// The power of alpha the readers premultiplied the colour by (OpenImageIO's rule): the
// gamma a file's colour space names ("Gamma2.2" for a PNG's gAMA), else 1.
float premultipliedGamma(const ImageHeader& spec) {
  if (spec.colorSpace.rfind("Gamma", 0) != 0) return 1.0f;
  const float g = std::strtof(spec.colorSpace.c_str() + 5, nullptr);
  return g > 0.0f ? g : 1.0f;
}

// Decodes `count` values in place with `curve`, each an integer code value over `top` (255
// or 65535), or for top 0 a float value (a negative one keeps its sign). Integer values take
// theirs from a table: the exact decoding of each code value, rounded once to float.
void decodeWithCurve(const GammaCurve& curve, float* values, size_t count, int top) {
  if (curve.linear()) return;
  if (curve.srgb && top > 0) {
    decodeSrgbCodeValues(values, count, top);
    return;
  }
  auto decode = [&](double v) { return static_cast<float>(workingToLinear(curve, v)); };
  if (top == 0) {
    for (size_t i = 0; i < count; ++i) values[i] = decode(values[i]);
    return;
  }
  std::vector<float> table(static_cast<size_t>(top) + 1);
  for (int c = 0; c <= top; ++c) table[c] = decode(static_cast<double>(c) / top);
  for (size_t i = 0; i < count; ++i) {
    const long c = std::lround(static_cast<double>(values[i]) * top);
    values[i] = table[static_cast<size_t>(std::clamp<long>(c, 0, top))];
  }
}

}  // namespace

void checkImageFile(const std::string& path) { openCheckedImage(path); }

Image readImageFile(const std::string& path, PixelDecoding decoding,
                    const std::optional<GammaCurve>& fileGamma) {
  std::unique_ptr<ImageReader> in = openCheckedImage(path);
  const ImageHeader& spec = in->header();
  const int channels = spec.channels;
  std::string error;
  std::vector<float> data(static_cast<size_t>(spec.width) * spec.height * channels);
  // A PNG's straight colours from its stored values (the reader would premultiply them);
  // other files' through the reader, divided by alpha below.
  const bool straightPng = decoding == PixelDecoding::StraightLinear && isPngFile(path);
  error = straightPng ? readStraightPng(path, data) : readImagePixels(*in, data.data());
  if (!error.empty()) throw ImageIOError(fmt::format("cannot read '{}': {}", path, error));

  Image image(spec.width, spec.height);
  const int alpha =
      decoding == PixelDecoding::StraightLinear && !straightPng ? spec.alphaChannel : -1;
  const float gamma = premultipliedGamma(spec);
  for (size_t p = 0; p < image.pixels.size(); ++p) {
    const float* px = &data[p * static_cast<size_t>(channels)];
    image.pixels[p] = channels < 3 ? Color(px[0]) : Color(px[0], px[1], px[2]);
    if (alpha >= 0 && px[alpha] > 0.0f) {
      const float weight = gamma == 1.0f ? px[alpha] : std::pow(px[alpha], gamma);
      image.pixels[p] = glm::min(image.pixels[p] / weight, Color(1.0f));
    }
  }
  // Integer files are sRGB-encoded unless they say otherwise: their code values decoded
  // exactly, as colours written as sRGB in a scene are.
  const bool integer = spec.eightBit || spec.sixteenBit;
  if (decoding != PixelDecoding::AsStored && fileGamma) {
    decodeWithCurve(*fileGamma, &image.pixels[0][0], 3 * image.pixels.size(),
                    !integer        ? 0
                    : spec.eightBit ? 255
                                    : 65535);
    return image;
  }
  if (decoding != PixelDecoding::AsStored && integer &&
      (spec.colorSpace.empty() || spec.saysSrgb()))
    decodeSrgbCodeValues(&image.pixels[0][0], 3 * image.pixels.size(), spec.eightBit ? 255 : 65535);
  return image;
}

}  // namespace lucent
