#include "image_compare.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucent {

namespace {

// A view of the pixels as an OpenImageIO buffer (no copy).
OIIO::ImageBuf wrap(const RgbImage& image) {
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
  return OIIO::ImageBuf(spec, const_cast<float*>(image.rgb.data()));
}

RgbImage fromBuffer(const OIIO::ImageBuf& buf) {
  const OIIO::ImageSpec& spec = buf.spec();
  RgbImage out(spec.width, spec.height);
  std::vector<float> all(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  buf.get_pixels(OIIO::ROI(spec.x, spec.x + spec.width, spec.y, spec.y + spec.height, 0, 1, 0,
                           spec.nchannels),
                 OIIO::TypeDesc::FLOAT, all.data());
  for (size_t p = 0; p < static_cast<size_t>(spec.width) * spec.height; ++p)
    for (int c = 0; c < 3; ++c)
      out.rgb[p * 3 + c] = all[p * spec.nchannels + std::min(c, spec.nchannels - 1)];
  return out;
}

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
  OIIO::ImageBuf bufA = wrap(a), bufB = wrap(b);
  // failthresh = threshold: nfail counts the pixels with a channel off by more than it.
  OIIO::ImageBufAlgo::CompareResults r = OIIO::ImageBufAlgo::compare(
      bufA, bufB, static_cast<float>(threshold), static_cast<float>(threshold));
  // (r.error is set whenever some pixel fails the threshold: not a processing error.)
  ImageMetrics m;
  m.rmse = r.rms_error;
  m.psnr = r.rms_error > 0.0 ? 20.0 * std::log10(1.0 / r.rms_error)
                             : std::numeric_limits<double>::infinity();
  m.maxDiff = r.maxerror;
  m.maxX = r.maxx;
  m.maxY = r.maxy;
  m.pixelsOver = static_cast<long>(r.nfail);
  long pixels = static_cast<long>(a.width) * a.height;
  m.shareOver = pixels > 0 ? static_cast<double>(m.pixelsOver) / pixels : 0.0;
  m.threshold = threshold;
  m.ssim = ssimLuminance(a, b);
  return m;
}

RgbImage differenceHeatMap(const RgbImage& a, const RgbImage& b, double fullScale) {
  requireSameSize(a, b);
  OIIO::ImageBuf diff = OIIO::ImageBufAlgo::absdiff(wrap(a), wrap(b));
  OIIO::ImageBuf largest = OIIO::ImageBufAlgo::maxchan(diff);
  OIIO::ImageBuf scaled = OIIO::ImageBufAlgo::mul(largest, static_cast<float>(1.0 / fullScale));
  OIIO::ImageBuf clamped = OIIO::ImageBufAlgo::clamp(scaled, 0.0f, 1.0f);
  OIIO::ImageBuf mapped = OIIO::ImageBufAlgo::color_map(clamped, 0, "inferno");
  if (mapped.has_error()) throw std::runtime_error("heat map: " + mapped.geterror());
  return fromBuffer(mapped);
}

RgbImage srgbEncoded(const RgbImage& linear) {
  RgbImage out = linear;
  for (float& v : out.rgb) {
    float x = std::clamp(v, 0.0f, 1.0f);
    // IEC 61966-2-1, in float as POV-Ray computes it (shared/povray-notes.md section 5).
    v = x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
  }
  return out;
}

void writeLinear16Png(const RgbImage& image, const std::string& path) {
  OIIO::ImageBuf buf = wrap(image);
  // Tagged linear, so readers do not decode it as sRGB (POV-Ray writes gAMA 1.0).
  buf.specmod().attribute("oiio:ColorSpace", "Linear");
  buf.set_write_format(OIIO::TypeDesc::UINT16);
  if (!buf.write(path, OIIO::TypeDesc::UINT16, "png"))
    throw std::runtime_error(fmt::format("cannot write '{}': {}", path, buf.geterror()));
}

RgbImage readLinear16Png(const std::string& path) {
  // The stored code values scaled to [0, 1]: no colour conversion whatever the file says.
  OIIO::ImageBuf buf(path);
  if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT))
    throw std::runtime_error(fmt::format("cannot read '{}': {}", path, buf.geterror()));
  return fromBuffer(buf);
}

void writeDisplayPng(const RgbImage& image, const std::string& path) {
  OIIO::ImageBuf buf = wrap(image);
  buf.specmod().attribute("oiio:ColorSpace", "sRGB");
  if (!buf.write(path, OIIO::TypeDesc::UINT8, "png"))
    throw std::runtime_error(fmt::format("cannot write '{}': {}", path, buf.geterror()));
}

}  // namespace lucent
