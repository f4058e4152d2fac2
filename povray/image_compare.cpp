#include "image_compare.h"

#include "images/image_plugin.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>

namespace lucent {

namespace {

std::vector<double> luminance(const RgbImage& img) {
  std::vector<double> y(static_cast<size_t>(img.width) * img.height);
  for (size_t p = 0; p < y.size(); ++p)
    y[p] = 0.2126 * img.rgb[p * 3] + 0.7152 * img.rgb[p * 3 + 1] + 0.0722 * img.rgb[p * 3 + 2];
  return y;
}

// Separable Gaussian filter, window truncated at ±5 and renormalised where it leaves the
// image (so a constant image stays constant up to the border).
std::vector<double> gaussianBlur(const std::vector<double>& in, int w, int h) {
  constexpr int kRadius = 5;
  constexpr double kSigma = 1.5;
  double weights[2 * kRadius + 1];
  for (int k = -kRadius; k <= kRadius; ++k)
    weights[k + kRadius] = std::exp(-(k * k) / (2.0 * kSigma * kSigma));
  std::vector<double> tmp(in.size()), out(in.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double sum = 0.0, norm = 0.0;
      for (int k = -kRadius; k <= kRadius; ++k) {
        int xx = x + k;
        if (xx < 0 || xx >= w) continue;
        sum += weights[k + kRadius] * in[static_cast<size_t>(y) * w + xx];
        norm += weights[k + kRadius];
      }
      tmp[static_cast<size_t>(y) * w + x] = sum / norm;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double sum = 0.0, norm = 0.0;
      for (int k = -kRadius; k <= kRadius; ++k) {
        int yy = y + k;
        if (yy < 0 || yy >= h) continue;
        sum += weights[k + kRadius] * tmp[static_cast<size_t>(yy) * w + x];
        norm += weights[k + kRadius];
      }
      out[static_cast<size_t>(y) * w + x] = sum / norm;
    }
  return out;
}

void requireSameSize(const RgbImage& a, const RgbImage& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument(fmt::format("images differ in size: {}x{} and {}x{}", a.width,
                                            a.height, b.width, b.height));
}

}  // namespace

double ssimLuminance(const RgbImage& a, const RgbImage& b) {
  requireSameSize(a, b);
  const int w = a.width, h = a.height;
  if (w == 0 || h == 0) return 1.0;
  std::vector<double> x = luminance(a), y = luminance(b);
  std::vector<double> xx(x.size()), yy(x.size()), xy(x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    xx[i] = x[i] * x[i];
    yy[i] = y[i] * y[i];
    xy[i] = x[i] * y[i];
  }
  std::vector<double> mx = gaussianBlur(x, w, h), my = gaussianBlur(y, w, h);
  std::vector<double> sxx = gaussianBlur(xx, w, h), syy = gaussianBlur(yy, w, h),
                      sxy = gaussianBlur(xy, w, h);
  const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  double total = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    double varX = sxx[i] - mx[i] * mx[i];
    double varY = syy[i] - my[i] * my[i];
    double cov = sxy[i] - mx[i] * my[i];
    total += ((2.0 * mx[i] * my[i] + c1) * (2.0 * cov + c2)) /
             ((mx[i] * mx[i] + my[i] * my[i] + c1) * (varX + varY + c2));
  }
  return total / static_cast<double>(x.size());
}

ImageMetrics compareImages(const RgbImage& a, const RgbImage& b, double threshold) {
  requireSameSize(a, b);
  CompareStats r = imagePlugin().compare(a.rgb.data(), b.rgb.data(), a.width, a.height,
                                         static_cast<float>(threshold));
  ImageMetrics m;
  m.rmse = r.rmsError;
  m.psnr = r.rmsError > 0.0 ? 20.0 * std::log10(1.0 / r.rmsError)
                            : std::numeric_limits<double>::infinity();
  m.maxDiff = r.maxError;
  m.maxX = r.maxX;
  m.maxY = r.maxY;
  m.pixelsOver = r.pixelsOver;
  long pixels = static_cast<long>(a.width) * a.height;
  m.shareOver = pixels > 0 ? static_cast<double>(m.pixelsOver) / pixels : 0.0;
  m.threshold = threshold;
  m.ssim = ssimLuminance(a, b);
  return m;
}

RgbImage differenceHeatMap(const RgbImage& a, const RgbImage& b, double fullScale) {
  requireSameSize(a, b);
  std::string error;
  RgbImage out(a.width, a.height);
  out.rgb = imagePlugin().heatMap(a.rgb.data(), b.rgb.data(), a.width, a.height,
                                  static_cast<float>(fullScale), error);
  if (!error.empty()) throw std::runtime_error("heat map: " + error);
  return out;
}

RgbImage srgbEncoded(const RgbImage& linear) {
  RgbImage out = linear;
  for (float& v : out.rgb) {
    float x = std::clamp(v, 0.0f, 1.0f);
    // IEC 61966-2-1, in float as POV-Ray computes it (its 8-bit files: 0.5 -> 188).
    v = x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
  }
  return out;
}

namespace {

// Writes a PNG of 8- or 16-bit code values round(v · max) of values clamped to [0, 1].
void writePng(const RgbImage& image, const std::string& path, bool sixteenBit,
              const char* colorSpace) {
  ImageToWrite file;
  file.format = "png";
  file.width = image.width;
  file.height = image.height;
  file.colorSpace = colorSpace;
  std::vector<uint8_t> bytes;
  std::vector<uint16_t> words;
  const float scale = sixteenBit ? 65535.0f : 255.0f;
  auto code = [scale](float v) { return std::floor(std::clamp(v, 0.0f, 1.0f) * scale + 0.5f); };
  if (sixteenBit) {
    words.reserve(image.rgb.size());
    for (float v : image.rgb) words.push_back(static_cast<uint16_t>(code(v)));
    file.type = StoredType::UInt16;
    file.pixels = words.data();
  } else {
    bytes.reserve(image.rgb.size());
    for (float v : image.rgb) bytes.push_back(static_cast<uint8_t>(code(v)));
    file.type = StoredType::UInt8;
    file.pixels = bytes.data();
  }
  if (WriteFailure failed = imagePlugin().writeFile(path, file))
    throw std::runtime_error(fmt::format("cannot write '{}': {}", path, failed.reason));
}

}  // namespace

void writeLinear16Png(const RgbImage& image, const std::string& path) {
  // Tagged linear, so readers do not decode it as sRGB (POV-Ray writes gAMA 1.0).
  writePng(image, path, /*sixteenBit=*/true, "Linear");
}

RgbImage readLinear16Png(const std::string& path) {
  // The stored code values scaled to [0, 1]: no colour conversion whatever the file says.
  std::string error;
  std::unique_ptr<ImageReader> in = imagePlugin().openFile(path, error);
  if (!in) throw std::runtime_error(fmt::format("cannot read '{}': {}", path, error));
  const ImageHeader& h = in->header();
  if (h.width <= 0 || h.height <= 0 || h.channels <= 0)
    throw std::runtime_error(fmt::format("cannot read '{}': the image has no pixels", path));
  std::vector<float> all(static_cast<size_t>(h.width) * h.height * h.channels);
  error = in->readPixels(all.data());
  if (!error.empty()) throw std::runtime_error(fmt::format("cannot read '{}': {}", path, error));
  RgbImage out(h.width, h.height);
  for (size_t p = 0; p < static_cast<size_t>(h.width) * h.height; ++p)
    for (int c = 0; c < 3; ++c)
      out.rgb[p * 3 + c] = all[p * h.channels + std::min(c, h.channels - 1)];
  return out;
}

void writeDisplayPng(const RgbImage& image, const std::string& path) {
  writePng(image, path, /*sixteenBit=*/false, "sRGB");
}

}  // namespace lucent
