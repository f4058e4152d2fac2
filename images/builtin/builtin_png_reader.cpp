// A PNG as OpenImageIO 2.4's PNG reader gives it, through the built-in libpng reader
// (builtin_png_read.cpp): palettes and bits below 8 widened, tRNS as an alpha channel, and
// the alpha premultiplied into the colour as OpenImageIO does by default (in the stored
// integers, truncating; through the file's gamma when it has a gAMA chunk and no sRGB
// chunk). The colour-space label is OpenImageIO's: "sRGB" for an sRGB chunk or none,
// "linear" or "GammaG" (G = 1/gAMA to two decimals) for a gAMA chunk, and a tEXt
// "oiio:ColorSpace" (which Lucent's own PNGs carry) overriding either.
#include "builtin_images.h"
#include "builtin_readers.h"

#include <cmath>
#include <cstdio>

namespace lucent::builtin {

namespace {

// OpenImageIO's gamma for premultiplying: 1/gAMA rounded to hundredths, 1 without gAMA.
float premultiplyGamma(const PngPixels& p) {
  if (p.srgbChunk || p.fileGamma <= 0.0) return 1.0f;
  const float g = static_cast<float>(1.0 / p.fileGamma);
  return std::round(100.0f * g) / 100.0f;
}

std::string colorSpaceLabel(const PngPixels& p) {
  if (!p.colorSpaceText.empty()) return p.colorSpaceText;
  if (p.srgbChunk || p.fileGamma <= 0.0) return "sRGB";
  const float g = premultiplyGamma(p);
  if (g == 1.0f) return "linear";
  char label[32];
  std::snprintf(label, sizeof label, "Gamma%.2g", static_cast<double>(g));
  return label;
}

// The colour of each pixel times its alpha, in the stored integers (OpenImageIO's rule).
void premultiply(PngPixels& p, float gamma) {
  const int n = p.channels, alpha = n - 1;
  const unsigned max = p.sixteenBit ? 65535u : 255u;
  const float inverseMax = static_cast<float>(1.0 / max);
  for (size_t i = 0; i + n <= p.values.size(); i += n) {
    std::uint16_t* v = &p.values[i];
    if (gamma == 1.0f) {
      for (int c = 0; c < alpha; ++c)
        v[c] = static_cast<std::uint16_t>(v[c] * unsigned(v[alpha]) / max);
    } else {
      const float weight = static_cast<float>(std::pow(v[alpha] * inverseMax, gamma));
      for (int c = 0; c < alpha; ++c) v[c] = static_cast<std::uint16_t>(v[c] * weight);
    }
  }
}

class PngReader final : public ImageReader {
 public:
  PngReader(std::string path, PngPixels pixels)
      : path_(std::move(path)), pixels_(std::move(pixels)) {
    header_.width = pixels_.width;
    header_.height = pixels_.height;
    header_.channels = pixels_.channels;
    header_.eightBit = !pixels_.sixteenBit;
    header_.sixteenBit = pixels_.sixteenBit;
    header_.alphaChannel =
        pixels_.channels == 2 || pixels_.channels == 4 ? pixels_.channels - 1 : -1;
    header_.colorSpace = colorSpaceLabel(pixels_);
  }

  const ImageHeader& header() const override { return header_; }

  std::string readPixels(float* out) override {
    std::string error = readPngValues(path_, pixels_);
    if (!error.empty()) return error;
    if (header_.alphaChannel >= 0) premultiply(pixels_, premultiplyGamma(pixels_));
    const float scale = pixels_.sixteenBit ? 1.0f / 65535.0f : 1.0f / 255.0f;
    for (size_t i = 0; i < pixels_.values.size(); ++i)
      out[i] = static_cast<float>(pixels_.values[i]) * scale;
    pixels_.values = {};
    return "";
  }

 private:
  std::string path_;
  PngPixels pixels_;
  ImageHeader header_;
};

}  // namespace

std::unique_ptr<ImageReader> openPng(const std::string& path, std::string& error) {
  PngPixels pixels;
  pixels.expandAsOiio = true;
  error = readPngHeader(path, pixels);
  if (!error.empty()) return nullptr;
  return std::make_unique<PngReader>(path, std::move(pixels));
}

}  // namespace lucent::builtin
