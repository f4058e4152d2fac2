// The metrics of lucent compare: SSIM against its closed form, PSNR/RMSE/maximum and the
// share of pixels over the threshold on images with known differences, the heat map, and
// the povray command line.
#include "povray/image_compare.h"
#include "povray/pov_runner.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace lucent;

namespace {

RgbImage constant(int w, int h, float v) {
  RgbImage img(w, h);
  std::fill(img.rgb.begin(), img.rgb.end(), v);
  return img;
}

// A deterministic pattern with texture, so SSIM has variances to compare.
RgbImage pattern(int w, int h) {
  RgbImage img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, y)[c] = 0.5f + 0.4f * std::sin(0.7f * x + 1.3f * y + c);
  return img;
}

}  // namespace

TEST_CASE("SSIM is 1 for identical images and the closed form for two constants",
          "[povray][metrics]") {
  RgbImage p = pattern(32, 24);
  CHECK(ssimLuminance(p, p) == Approx(1.0).epsilon(1e-12));

  // No variance: SSIM = (2ab + C1)/(a² + b² + C1) · C2/C2.
  const double a = 0.5, b = 0.25, c1 = 1e-4;
  double expected = (2 * a * b + c1) / (a * a + b * b + c1);
  CHECK(ssimLuminance(constant(20, 20, 0.5f), constant(20, 20, 0.25f)) ==
        Approx(expected).epsilon(1e-6));
}

TEST_CASE("SSIM drops for noise and structure changes", "[povray][metrics]") {
  RgbImage p = pattern(40, 30);
  RgbImage shifted(40, 30);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x)
      for (int c = 0; c < 3; ++c) shifted.at(x, y)[c] = p.at((x + 2) % 40, y)[c];
  double s = ssimLuminance(p, shifted);
  CHECK(s < 0.9);
  CHECK(s > -1.0);
}

TEST_CASE("compareImages counts the pixels over the threshold and finds the maximum",
          "[povray][metrics]") {
  RgbImage a = constant(10, 10, 0.5f), b = a;
  b.at(3, 4)[1] = 0.6f;               // 0.1 off: over 2/255
  b.at(7, 1)[0] = 0.5f + 1.0f / 255;  // under 2/255
  ImageMetrics m = compareImages(a, b, 2.0 / 255.0);
  CHECK(m.pixelsOver == 1);
  CHECK(m.shareOver == Approx(0.01));
  CHECK(m.maxDiff == Approx(0.1).epsilon(1e-6));
  CHECK(m.maxX == 3);
  CHECK(m.maxY == 4);
  double mse = (0.1 * 0.1 + (1.0 / 255) * (1.0 / 255)) / 300.0;
  CHECK(m.rmse == Approx(std::sqrt(mse)).epsilon(1e-5));
  CHECK(m.psnr == Approx(-10.0 * std::log10(mse)).epsilon(1e-5));

  ImageMetrics same = compareImages(a, a, 2.0 / 255.0);
  CHECK(same.rmse == 0.0);
  CHECK(std::isinf(same.psnr));
  CHECK(same.pixelsOver == 0);
  CHECK(same.ssim == Approx(1.0));

  CHECK_THROWS_AS(compareImages(a, constant(5, 5, 0.0f), 0.01), std::invalid_argument);
}

TEST_CASE("the heat map is black where images agree and bright where they differ most",
          "[povray][metrics]") {
  RgbImage a = constant(4, 4, 0.2f), b = a;
  b.at(2, 2)[2] = 0.9f;
  RgbImage heat = differenceHeatMap(a, b, 0.1);
  const float* same = heat.at(0, 0);
  const float* differ = heat.at(2, 2);
  CHECK(same[0] + same[1] + same[2] < 0.05f);
  CHECK(differ[0] + differ[1] + differ[2] > 2.0f);  // inferno's top is pale yellow
}

TEST_CASE("sRGB encoding matches POV-Ray's 8-bit table", "[povray][metrics]") {
  // The 8-bit codes POV-Ray 3.7 writes: 0.5 -> 188, 0.18 -> 118, 0.01 -> 25.
  RgbImage img(1, 1);
  img.rgb = {0.5f, 0.18f, 0.01f};
  RgbImage s = srgbEncoded(img);
  CHECK(std::floor(s.rgb[0] * 255 + 0.5f) == 188);
  CHECK(std::floor(s.rgb[1] * 255 + 0.5f) == 118);
  CHECK(std::floor(s.rgb[2] * 255 + 0.5f) == 25);
}

TEST_CASE("povray runs without display, 16-bit linear, and without antialiasing for one sample",
          "[povray][runner]") {
  PovrayRender r;
  r.input = "/tmp/a b/scene.pov";
  r.output = "/tmp/out.png";
  r.width = 64;
  r.height = 48;
  CHECK(commandLine("povray", povrayArguments(r)) ==
        "povray '+I\"/tmp/a b/scene.pov\"' +O/tmp/out.png +W64 +H48 -D -V -GS -GR +FN16 "
        "File_Gamma=1.0 -A");  // a path with a space quoted, as POV-Ray's options need
  r.samples = 9;
  r.threads = 2;
  std::vector<std::string> args = povrayArguments(r);
  CHECK(std::vector<std::string>(args.end() - 5, args.end()) ==
        std::vector<std::string>{"+A0.0", "-J", "+AM1", "+R3", "+WT2"});
  // The clock of the frame compared, in its shortest exact text; none at POV-Ray's 0.
  r.clock = 0.1;
  CHECK(povrayArguments(r).back() == "+K0.1");
  r.clock = 2.0 / 3.0;
  CHECK(std::stod(povrayArguments(r).back().substr(2)) == 2.0 / 3.0);
  r.clock = 0.0;
  CHECK(povrayArguments(r).back() == "+WT2");
}

TEST_CASE("corner sampling runs POV-Ray's method 2 without jitter, at the same threshold and depth",
          "[povray][runner]") {
  PovrayRender r;
  r.input = "scene.pov";
  r.output = "out.png";
  r.width = 64;
  r.height = 48;
  r.samples = 9;  // not used: corners choose their own samples
  r.corners = true;
  r.cornerThreshold = 0.3;
  r.cornerDepth = 4;
  std::vector<std::string> args = povrayArguments(r);
  CHECK(std::vector<std::string>(args.end() - 4, args.end()) ==
        std::vector<std::string>{"+AM2", "+A0.3", "-J", "+R4"});
  CHECK(cornerThresholdFlag(0.0) == "+A0.0");
  CHECK(cornerThresholdFlag(1.0) == "+A1.0");
  CHECK(cornerThresholdFlag(0.125) == "+A0.125");
}
