#include "image_read.h"

#include "images/image_reading.h"
#include "images/srgb_decoding.h"
#include "memory/system_memory.h"
#include "scenegraph/render_limits.h"

#include <fmt/core.h>

#include <cstdint>
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

}  // namespace

void checkImageFile(const std::string& path) { openCheckedImage(path); }

Image readImageFile(const std::string& path, PixelDecoding decoding) {
  std::unique_ptr<ImageReader> in = openCheckedImage(path);
  const ImageHeader& spec = in->header();
  const int channels = spec.channels;
  std::string error;
  std::vector<float> data(static_cast<size_t>(spec.width) * spec.height * channels);
  error = readImagePixels(*in, data.data());
  if (!error.empty()) throw ImageIOError(fmt::format("cannot read '{}': {}", path, error));

  Image image(spec.width, spec.height);
  for (size_t p = 0; p < image.pixels.size(); ++p) {
    const float* px = &data[p * static_cast<size_t>(channels)];
    image.pixels[p] = channels < 3 ? Color(px[0]) : Color(px[0], px[1], px[2]);
  }
  // Integer files are sRGB-encoded unless they say otherwise: their code values decoded
  // exactly, as colours written as sRGB in a scene are.
  const bool integer = spec.eightBit || spec.sixteenBit;
  if (decoding == PixelDecoding::Linear && integer && (spec.colorSpace.empty() || spec.saysSrgb()))
    decodeSrgbCodeValues(&image.pixels[0][0], 3 * image.pixels.size(), spec.eightBit ? 255 : 65535);
  return image;
}

}  // namespace lucent
