// The built-in PNG reader (images/builtin/builtin_png_read.cpp) gives the values the file
// stores, widened as OpenImageIO widens them: each test file of tests/data/png_kinds
// (bits below 8, grey with alpha, RGBA of 16 bits, Adam7, tRNS) against the formula that
// made it, and those without alpha against OpenImageIO's reading of the same file.
#include "images/builtin/builtin_images.h"
#include "images/image_plugin.h"

#include "../support/paths.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

using namespace lucent;

namespace {

std::string kindFile(const std::string& name) {
  return std::string(lucentSourceDir()) + "/tests/data/png_kinds/" + name;
}

PngPixels readBuiltin(const std::string& path) {
  PngPixels p;
  REQUIRE(readPngHeader(path, p).empty());
  REQUIRE(readPngValues(path, p).empty());
  return p;
}

}  // namespace

TEST_CASE("built-in PNG reader: values as the file's formula made them", "[images][png]") {
  // make.py: greyN.png holds (3x + y) mod 2^N, widened to 8 bits as libpng widens (x 255/max).
  for (int depth : {1, 2, 4}) {
    INFO(depth);
    const PngPixels p = readBuiltin(kindFile("grey" + std::to_string(depth) + ".png"));
    REQUIRE((p.width == 11 && p.height == 7 && p.channels == 1 && !p.sixteenBit));
    CHECK(p.storedDepth == depth);
    const int max = (1 << depth) - 1;
    int wrong = 0;
    for (int y = 0; y < 7; ++y)
      for (int x = 0; x < 11; ++x)
        wrong += p.values[y * 11 + x] != (x * 3 + y) % (max + 1) * 255 / max;
    CHECK(wrong == 0);
  }
  const PngPixels rgba = readBuiltin(kindFile("rgba16.png"));
  REQUIRE((rgba.channels == 4 && rgba.sixteenBit));
  CHECK(rgba.values[(3 * 11 + 5) * 4 + 0] == 25000);  // x 5000
  CHECK(rgba.values[(3 * 11 + 5) * 4 + 1] == 27000);  // y 9000
  CHECK(rgba.values[(3 * 11 + 5) * 4 + 3] == 65535 - 500);
  const PngPixels ga = readBuiltin(kindFile("grey_alpha8.png"));
  REQUIRE(ga.channels == 2);
  CHECK(ga.values[(2 * 11 + 4) * 2] == (4 * 23 + 2 * 5) % 256);  // the grey as stored
  CHECK(ga.values[(2 * 11 + 4) * 2 + 1] == 28);                  // its alpha
  const PngPixels trns = readBuiltin(kindFile("grey_trns8.png"));
  REQUIRE(trns.channels == 1);           // tRNS adds no channel here
  CHECK(trns.values[1 * 11 + 1] == 12);  // the transparent grey keeps its value
  const PngPixels inter = readBuiltin(kindFile("interlaced8.png"));
  int wrong = 0;
  for (int y = 0; y < 7; ++y)
    for (int x = 0; x < 11; ++x) wrong += inter.values[y * 11 + x] != (x * 19 + y * 31) % 256;
  CHECK(wrong == 0);
}

TEST_CASE("built-in PNG reader: the values OpenImageIO reads, for files without alpha",
          "[images][png]") {
  // With alpha (or tRNS) OpenImageIO multiplies the colour by it; POV-Ray's height fields
  // take the stored colour (height_map_file_test.cpp), as this reader gives it.
  for (const char* name :
       {"grey1.png", "grey2.png", "grey4.png", "interlaced8.png", "interlaced_rgb16.png"}) {
    INFO(name);
    const PngPixels p = readBuiltin(kindFile(name));
    std::string error;
    auto in = imagePlugin().openFile(kindFile(name), error);  // OpenImageIO, the reference
    REQUIRE(in);
    const ImageHeader& h = in->header();
    REQUIRE((h.width == p.width && h.height == p.height));
    REQUIRE(h.channels >= p.channels);  // OpenImageIO may add alpha for a tRNS chunk
    CHECK(h.sixteenBit == p.sixteenBit);
    std::vector<float> px(static_cast<size_t>(h.width) * h.height * h.channels);
    REQUIRE(in->readPixels(px.data()).empty());
    const float top = p.sixteenBit ? 65535.0f : 255.0f;
    int wrong = 0;
    for (int i = 0; i < p.width * p.height; ++i)
      for (int c = 0; c < p.channels; ++c)
        wrong += std::lround(px[static_cast<size_t>(i) * h.channels + c] * top) !=
                 p.values[static_cast<size_t>(i) * p.channels + c];
    CHECK(wrong == 0);
  }
}

TEST_CASE("built-in PNG reader: a damaged or foreign file gives its reason", "[images][png]") {
  const std::string bad = std::string(lucentSourceDir()) + "/tests/bad/scenes/heights/";
  PngPixels p;
  CHECK_FALSE(isPngFile(bad + "text.png"));
  CHECK(isPngFile(bad + "truncated.png"));
  REQUIRE(readPngHeader(bad + "truncated.png", p).empty());
  CHECK(readPngValues(bad + "truncated.png", p) ==
        "a damaged PNG: the file ends before its image does");
  PngPixels pal;
  REQUIRE(readPngHeader(bad + "palette.png", pal).empty());
  CHECK(pal.palette);
}
