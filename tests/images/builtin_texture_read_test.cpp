// Textures without OpenImageIO: every PNG and JPEG texture of the examples, the test
// files of tests/data/png_kinds and jpeg_kinds (palettes, tRNS, alpha with and without
// gamma, 16 bits, interlacing, grey, progressive, CMYK) and POV-Ray's include images are
// read by the built-in readers and by the plugin's OpenImageIO: the same header and the
// same float pixels, bit for bit. The lookup that replaced OpenImageIO's
// interppixel_NDC gives its values bit for bit; the sRGB decoding is exact, where
// OpenImageIO's approximates the power (within 1.4e-5 of it, measured).
#include "images/builtin/builtin_images.h"
#include "images/image_plugin.h"
#include "images/periodic_bilinear.h"
#include "images/srgb_decoding.h"

#include "../support/paths.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>
#include <set>
#include <string>
#include <vector>

using namespace lucent;
namespace fs = std::filesystem;

namespace {

bool isTextureFile(const fs::path& p) {
  std::string ext = p.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".png" || ext == ".jpg" || ext == ".jpeg";
}

// The PNG and JPEG files under `folder`, recursively.
void addTextures(const fs::path& folder, std::set<std::string>& files) {
  if (!fs::is_directory(folder)) return;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file() && isTextureFile(entry.path())) files.insert(entry.path().string());
}

std::vector<float> pixelsOf(ImageReader& in) {
  const ImageHeader& h = in.header();
  std::vector<float> px(static_cast<size_t>(h.width) * h.height * h.channels);
  REQUIRE(in.readPixels(px.data()).empty());
  return px;
}

}  // namespace

TEST_CASE("built-in PNG and JPEG readers: OpenImageIO's header and pixels, bit for bit",
          "[images][png][jpeg]") {
  const fs::path source = lucentSourceDir();
  std::set<std::string> files;
  addTextures(source / "examples", files);
  addTextures(source / "tests/data/png_kinds", files);
  addTextures(source / "tests/data/jpeg_kinds", files);
  addTextures("/usr/share/povray-3.7/include", files);  // povray-includes
  REQUIRE(files.size() >= 40);
  int jpegs = 0;
  for (const std::string& file : files) {
    INFO(file);
    std::string error;
    auto builtin = builtinOpenFile(file, error);
    REQUIRE(error.empty());
    REQUIRE(builtin);
    auto reference = imagePlugin().openFile(file, error);
    REQUIRE(reference);
    const ImageHeader &a = builtin->header(), &b = reference->header();
    CHECK(a.width == b.width);
    CHECK(a.height == b.height);
    REQUIRE(a.channels == b.channels);
    CHECK(a.eightBit == b.eightBit);
    CHECK(a.sixteenBit == b.sixteenBit);
    CHECK(a.floating == b.floating);
    CHECK(a.alphaChannel == b.alphaChannel);
    CHECK(a.colorSpace == b.colorSpace);
    const std::vector<float> pa = pixelsOf(*builtin), pb = pixelsOf(*reference);
    REQUIRE(pa.size() == pb.size());
    size_t differ = 0;
    for (size_t i = 0; i < pa.size(); ++i)
      differ += std::memcmp(&pa[i], &pb[i], sizeof(float)) != 0;
    CHECK(differ == 0);
    jpegs += fs::path(file).extension() == ".jpg";
  }
  CHECK(jpegs >= 4);
}

TEST_CASE("built-in GIF reader: the palette's colours, OpenImageIO's where opaque",
          "[images][gif]") {
  // make_gif_maps.py's GIFs: four colours (red, blue, white, green) in 2 x 2 blocks, index
  // (x / 2 + y / 2) % 4; in gif_transparent.gif blue (index 1) is transparent.
  const std::string folder = std::string(lucentSourceDir()) + "/tests/data/sdl/scenes/";
  const float palette[4][3] = {{1, 0, 0}, {0, 0, 1}, {1, 1, 1}, {0, 160.0f / 255.0f, 0}};
  for (const bool transparent : {false, true}) {
    const std::string file = folder + (transparent ? "gif_transparent.gif" : "gif_plain.gif");
    INFO(file);
    std::string error;
    auto builtin = builtinOpenFile(file, error);
    REQUIRE(builtin);
    auto reference = imagePlugin().openFile(file, error);
    REQUIRE(reference);
    const ImageHeader &a = builtin->header(), &b = reference->header();
    CHECK(a.width == 8);
    CHECK(a.height == 8);
    CHECK(a.channels == (transparent ? 4 : 3));
    CHECK(a.alphaChannel == (transparent ? 3 : -1));
    CHECK(b.alphaChannel == 3);  // OpenImageIO's GIF reader named channel 4 of 4 before
    CHECK(a.eightBit);
    CHECK(a.colorSpace == b.colorSpace);
    const std::vector<float> pa = pixelsOf(*builtin), pb = pixelsOf(*reference);
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) {
        const int index = (x / 2 + y / 2) % 4, p = y * 8 + x;
        const float* own = &pa[static_cast<size_t>(p * a.channels)];
        const float* oiio = &pb[static_cast<size_t>(p * b.channels)];
        const bool clear = transparent && index == 1;
        INFO("pixel " << x << ", " << y);
        for (int c = 0; c < 3; ++c) {
          CHECK(own[c] == palette[index][c]);
          // OpenImageIO blackens a transparent pixel; the palette keeps its colour, which
          // POV-Ray's interpolation blends.
          CHECK(oiio[c] == (clear ? 0.0f : own[c]));
        }
        if (transparent) CHECK(own[3] == (clear ? 0.0f : 1.0f));
        CHECK(oiio[3] == (clear ? 0.0f : 1.0f));
      }
  }
}

TEST_CASE("built-in readers: other formats are left to the plugin, damaged files refused",
          "[images][png][jpeg]") {
  const std::string bad = std::string(lucentSourceDir()) + "/tests/bad/scenes/";
  std::string error;
  CHECK_FALSE(builtinOpenFile(bad + "heights/text.png", error));  // not a PNG inside
  CHECK(error.empty());
  auto png = builtinOpenFile(bad + "heights/truncated.png", error);
  REQUIRE(png);
  std::vector<float> px(static_cast<size_t>(png->header().width) * png->header().height *
                        png->header().channels);
  CHECK(png->readPixels(px.data()) == "a damaged PNG: the file ends before its image does");

  // A JPEG cut in its scan (which starts at byte 1459 of 2302): its header reads, its
  // pixels are refused (libjpeg alone would fill the rest with grey and warn).
  const fs::path whole = fs::path(lucentSourceDir()) / "tests/data/jpeg_kinds/rgb420.jpg";
  const fs::path cut = fs::temp_directory_path() / "lucent_test_cut.jpg";
  fs::copy_file(whole, cut, fs::copy_options::overwrite_existing);
  fs::resize_file(cut, 1800);
  auto jpeg = builtinOpenFile(cut.string(), error);
  REQUIRE(jpeg);
  px.assign(static_cast<size_t>(jpeg->header().width) * jpeg->header().height * 3, 0.0f);
  const std::string why = jpeg->readPixels(px.data());
  CHECK(why.rfind("a damaged JPEG: ", 0) == 0);
  fs::resize_file(cut, 100);  // inside the header's tables
  CHECK_FALSE(builtinOpenFile(cut.string(), error));
  CHECK(error.rfind("a damaged JPEG: ", 0) == 0);
  fs::remove(cut);
}

TEST_CASE("sRGB code values decode exactly, near OpenImageIO's approximation", "[images]") {
  std::vector<float> bytes(256), words(65536);
  for (int i = 0; i < 256; ++i) bytes[i] = static_cast<float>(i) * (1.0f / 255.0f);
  for (int i = 0; i < 65536; ++i) words[i] = static_cast<float>(i) * (1.0f / 65535.0f);
  std::vector<float> oiioBytes = bytes, oiioWords = words;
  decodeSrgbCodeValues(bytes.data(), bytes.size(), 255);
  decodeSrgbCodeValues(words.data(), words.size(), 65535);
  REQUIRE(imagePlugin().srgbToLinear(oiioBytes.data(), 256, 1, 1).empty());
  REQUIRE(imagePlugin().srgbToLinear(oiioWords.data(), 65536, 1, 1).empty());
  double worst = 0.0;
  for (int i = 0; i < 256; ++i) {
    REQUIRE(bytes[i] == static_cast<float>(srgbToLinear(i / 255.0)));
    if (i) worst = std::max(worst, std::fabs(double(oiioBytes[i]) - bytes[i]) / bytes[i]);
  }
  for (int i = 0; i < 65536; i += 7) {
    REQUIRE(words[i] == static_cast<float>(srgbToLinear(i / 65535.0)));
    if (i) worst = std::max(worst, std::fabs(double(oiioWords[i]) - words[i]) / words[i]);
  }
  CHECK(bytes[255] == 1.0f);
  CHECK(bytes[10] == static_cast<float>(10 / 255.0 / 12.92));  // the linear segment
  CHECK(worst < 2e-5);
}

TEST_CASE("periodic bilinear lookup: OpenImageIO's interppixel_NDC, bit for bit", "[images]") {
  const int w = 13, h = 7;
  std::vector<float> rgb(3 * w * h);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), wide(-3.0f, 3.0f);
  for (float& v : rgb) v = unit(random);
  const PeriodicBilinear ours(rgb.data(), w, h);
  auto reference = imagePlugin().textureSampler(rgb.data(), w, h);
  std::vector<std::pair<float, float>> points = {
      {0.0f, 0.0f}, {1.0f, 1.0f}, {0.5f / w, 0.5f / h}, {-0.0f, 1.0f - 1e-7f}, {2.0f, -1.0f}};
  for (int i = 0; i < 20000; ++i) points.emplace_back(wide(random), wide(random));
  int differ = 0;
  for (auto [s, t] : points) {
    float a[3], b[3];
    ours.lookup(s, t, a);
    reference->lookup(s, t, b);
    differ += std::memcmp(a, b, sizeof a) != 0;
  }
  CHECK(differ == 0);
  // Between two pixel centres of row 0: the mean of the two.
  float mid[3];
  ours.lookup(1.0f / w, 0.5f / h, mid);
  CHECK(mid[0] == Approx(0.5f * (rgb[0] + rgb[3])).epsilon(1e-6));
  // Far outside, and not a number: finite values, no crash.
  ours.lookup(3e9f, -7e8f, mid);
  CHECK(std::isfinite(mid[0]));
  ours.lookup(std::nanf(""), 0.5f, mid);
  CHECK(mid[0] == 0.0f);
}
