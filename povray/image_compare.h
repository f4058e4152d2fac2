// Image metrics for `lucent compare`: PSNR, RMSE and maximum difference through
// OpenImageIO's ImageBufAlgo::compare, SSIM on luminance (OpenImageIO has none), the share
// of pixels off by more than a threshold, and a difference heat map.
#pragma once

#include <string>
#include <vector>

namespace lucent {

// Three floats per pixel, row-major, row 0 at the top.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;

  RgbImage() = default;
  RgbImage(int w, int h) : width(w), height(h), rgb(static_cast<size_t>(w) * h * 3, 0.0f) {}
  float* at(int x, int y) { return &rgb[(static_cast<size_t>(y) * width + x) * 3]; }
  const float* at(int x, int y) const { return &rgb[(static_cast<size_t>(y) * width + x) * 3]; }
};

struct ImageMetrics {
  double psnr = 0.0;       // dB, 20·log10(1/RMSE); infinite for identical images
  double ssim = 0.0;       // mean SSIM of the luminance, in [-1, 1]
  double rmse = 0.0;       // over all pixels and channels
  double maxDiff = 0.0;    // largest channel difference
  int maxX = 0, maxY = 0;  // where it is
  long pixelsOver = 0;     // pixels with some channel off by more than `threshold`
  double shareOver = 0.0;  // pixelsOver / pixel count
  double threshold = 0.0;
};

// Compares two images of equal size (values as encoded for display, in [0, 1]).
// Throws std::invalid_argument for different sizes.
ImageMetrics compareImages(const RgbImage& a, const RgbImage& b, double threshold);

// Mean SSIM (Wang, Bovik, Sheikh, Simoncelli 2004, eq. 13) of the Rec. 709 luminance of two
// images: Gaussian window σ = 1.5 truncated at 11×11 and renormalised at the image border,
// C1 = (0.01)², C2 = (0.03)² for values in [0, 1].
double ssimLuminance(const RgbImage& a, const RgbImage& b);

// The largest channel difference per pixel through the "inferno" colour map, black for
// none and brightest at `fullScale` or more.
RgbImage differenceHeatMap(const RgbImage& a, const RgbImage& b, double fullScale);

// sRGB encoding of every channel (clamped to [0, 1]), as POV-Ray writes 8-bit files.
RgbImage srgbEncoded(const RgbImage& linear);

// 16-bit PNG files holding linear values (POV-Ray's +FN16 File_Gamma=1.0), through
// OpenImageIO; both throw std::runtime_error naming the file.
void writeLinear16Png(const RgbImage& image, const std::string& path);
RgbImage readLinear16Png(const std::string& path);
// An 8-bit PNG of display-encoded values (heat maps, previews).
void writeDisplayPng(const RgbImage& image, const std::string& path);

}  // namespace lucent
