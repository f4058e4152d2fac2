// Image files: the values each format stores, held to references independent of Lucent's
// encoder (the sRGB formula written out here, a PPM read byte by byte, EXR's exact floats),
// and failures that leave old files intact.
#include "app/image_output.h"
#include "../temp_dir.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

using namespace lucent;
namespace fs = std::filesystem;
using lucent::test::TempDir;

namespace {

// Values spanning the range, including out-of-range ones the 8-bit formats clamp.
Image testImage() {
  Image img(7, 5);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      img.at(x, y) = Color(x / 6.0f, y / 4.0f, (x * 5 + y) / 34.0f * 1.5f - 0.2f);
  img.at(0, 0) = Color(0.001f, 0.18f, 0.5f);
  return img;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The reference the files are held to, written here from IEC 61966-2-1 in double precision
// rather than taken from Lucent's encoder: the sRGB value of a linear one, clamped to [0, 1].
double referenceSrgb(double linear) {
  const double x = std::clamp(linear, 0.0, 1.0);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

// Checks a stored code value against the reference scaled to `maxCode` and rounded half up
// (POV-Ray's rounding). Within 1e-3 of a rounding boundary the encoder's float arithmetic
// may round either way, so either neighbour is accepted there.
void checkCode(int stored, float linear, int maxCode) {
  const double exact = referenceSrgb(linear) * maxCode;
  const double rounded = std::floor(exact + 0.5);
  INFO("linear " << linear << ": sRGB code " << exact);
  if (std::abs(exact + 0.5 - rounded) < 1e-3 || std::abs(exact + 0.5 - rounded - 1.0) < 1e-3)
    CHECK(std::abs(stored - exact) < 0.5 + 1e-3);
  else CHECK(stored == static_cast<int>(rounded));
}

// A binary PPM (P6, maxval 255) read byte by byte, without any image library.
struct Ppm {
  int width = 0, height = 0, maxval = 0;
  std::vector<unsigned char> bytes;  // RGB, row 0 first
};

Ppm readPpm(const std::string& path) {
  std::istringstream in(slurp(path));
  Ppm p;
  std::string magic;
  in >> magic >> p.width >> p.height >> p.maxval;
  in.get();  // the single whitespace byte before the pixels
  REQUIRE(magic == "P6");
  p.bytes.assign(std::istreambuf_iterator<char>(in), {});
  return p;
}

}  // namespace

TEST_CASE("the sRGB reference of this test reproduces POV-Ray's 8-bit table", "[render][io]") {
  // Hand-computed from the formula: 0.001 -> 3.29, 0.18 -> 117.65, 0.5 -> 187.52,
  // 0.2 -> 123.55, 0.0031308 -> 10.31 (the end of the linear segment), 1 -> 255.
  CHECK(referenceSrgb(0.001) * 255 == Approx(3.2946).margin(1e-4));
  CHECK(referenceSrgb(0.18) * 255 == Approx(117.6458).margin(1e-4));
  CHECK(referenceSrgb(0.5) * 255 == Approx(187.5160).margin(1e-4));
  CHECK(referenceSrgb(0.2) * 255 == Approx(123.5549).margin(1e-4));
  CHECK(referenceSrgb(0.0031308) * 255 == Approx(10.3147).margin(1e-4));
  CHECK(referenceSrgb(1.0) == Approx(1.0));
  CHECK(referenceSrgb(-0.5) == 0.0);
  CHECK(referenceSrgb(7.0) == Approx(1.0));
}

TEST_CASE("PPM stores POV-Ray's 8-bit sRGB encoding, byte for byte", "[render][io]") {
  TempDir dir("io");
  Image img = testImage();
  writeImageFile(img, dir.file("a.ppm"));
  Ppm ppm = readPpm(dir.file("a.ppm"));
  REQUIRE(ppm.width == img.width);
  REQUIRE(ppm.height == img.height);
  REQUIRE(ppm.maxval == 255);
  REQUIRE(ppm.bytes.size() == img.pixels.size() * 3);
  for (size_t i = 0; i < img.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      INFO("pixel " << i << " channel " << c);
      checkCode(ppm.bytes[i * 3 + c], img.pixels[i][c], 255);
    }
  // The sRGB table of POV-Ray's notes: 0.001 -> 3, 0.18 -> 118, 0.5 -> 188.
  CHECK(int(ppm.bytes[0]) == 3);
  CHECK(int(ppm.bytes[1]) == 118);
  CHECK(int(ppm.bytes[2]) == 188);
}

TEST_CASE("PNG stores the same 8-bit sRGB codes as decoded by OpenImageIO", "[render][io]") {
  TempDir dir("io");
  Image img = testImage();
  writeImageFile(img, dir.file("a.png"));
  Image back = readImageFile(dir.file("a.png"), PixelDecoding::AsStored);
  REQUIRE(back.width == img.width);
  REQUIRE(back.height == img.height);
  for (size_t i = 0; i < img.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      INFO("pixel " << i << " channel " << c);
      const float code = back.pixels[i][c] * 255.0f;
      REQUIRE(std::abs(code - std::round(code)) < 1e-3f);  // an 8-bit file
      checkCode(static_cast<int>(std::round(code)), img.pixels[i][c], 255);
    }
  CHECK(back.at(0, 0).r * 255.0f == Approx(3));
  CHECK(back.at(0, 0).g * 255.0f == Approx(118));
  CHECK(back.at(0, 0).b * 255.0f == Approx(188));
}

TEST_CASE("EXR keeps linear float values exactly, HDR to RGBE precision, TIFF in 16 bits",
          "[render][io]") {
  TempDir dir("io");
  Image img = testImage();
  writeImageFile(img, dir.file("a.exr"));
  Image exr = readImageFile(dir.file("a.exr"));
  REQUIRE(exr.pixels.size() == img.pixels.size());
  CHECK(exr.pixels == img.pixels);  // bit for bit, negative values included

  writeImageFile(img, dir.file("a.hdr"));
  Image hdr = readImageFile(dir.file("a.hdr"));
  REQUIRE(hdr.pixels.size() == img.pixels.size());
  for (size_t i = 0; i < img.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      float v = std::max(0.0f, img.pixels[i][c]);
      // RGBE shares one exponent: 8 bits of mantissa relative to the largest channel.
      CHECK(hdr.pixels[i][c] == Approx(v).margin(maxComponent(img.pixels[i]) / 128.0f + 1e-6f));
    }

  writeImageFile(img, dir.file("a.tif"));
  Image tif = readImageFile(dir.file("a.tif"), PixelDecoding::AsStored);
  REQUIRE(tif.pixels.size() == img.pixels.size());
  for (size_t i = 0; i < img.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      INFO("pixel " << i << " channel " << c);
      checkCode(static_cast<int>(std::lround(tif.pixels[i][c] * 65535.0f)), img.pixels[i][c],
                65535);
    }
}

TEST_CASE("JPEG stores sRGB codes within its compression error", "[render][io]") {
  // A flat image: JPEG's blocks reproduce a constant to within a code value or two.
  TempDir dir("io");
  Image flat(16, 16);
  for (Color& p : flat.pixels) p = Color(0.18f, 0.5f, 0.001f);
  writeImageFile(flat, dir.file("a.jpg"));
  Image jpg = readImageFile(dir.file("a.jpg"), PixelDecoding::AsStored);
  REQUIRE(jpg.width == 16);
  REQUIRE(jpg.height == 16);
  const Color centre = jpg.at(8, 8) * 255.0f;
  CHECK(centre.r == Approx(118).margin(3));
  CHECK(centre.g == Approx(188).margin(3));
  CHECK(centre.b == Approx(3).margin(3));
}

TEST_CASE("a write that fails leaves the existing file untouched and no temporary behind",
          "[render][io]") {
  TempDir dir("io");
  const std::string out = dir.file("keep.png");
  writeImageFile(testImage(), out);
  const std::string before = slurp(out);
  REQUIRE(!before.empty());

  SECTION("missing folder") {
    CHECK_THROWS_WITH(writeImageFile(Image(2, 2), dir.file("no/such/dir/x.png")),
                      Catch::Contains("folder") && Catch::Contains("does not exist"));
  }
  SECTION("unknown extension") {
    CHECK_THROWS_WITH(writeImageFile(Image(2, 2), dir.file("keep.xyz")),
                      Catch::Contains("unknown image format '.xyz'") &&
                          Catch::Contains("png, exr, tif, jpg, hdr, ppm"));
  }
  SECTION("no extension") {
    CHECK_THROWS_WITH(writeImageFile(Image(2, 2), dir.file("keep")),
                      Catch::Contains("no file extension"));
  }
  SECTION("the target is a folder") {
    fs::create_directory(dir.path / "sub.png");
    CHECK_THROWS_WITH(writeImageFile(Image(2, 2), dir.file("sub.png")),
                      Catch::Contains("not a regular file"));
  }
  SECTION("a device is never replaced") {
    CHECK_THROWS_AS(writeImageFile(Image(2, 2), "/dev/full"), ImageIOError);
    CHECK(fs::is_character_file("/dev/full"));
  }
  CHECK(slurp(out) == before);
  // Only the original file (and the folder made by one section) are left.
  for (const auto& e : fs::directory_iterator(dir.path))
    CHECK(e.path().filename().string().find(".lucent-") == std::string::npos);
}

TEST_CASE("a successful write replaces the old file completely", "[render][io]") {
  TempDir dir("io");
  const std::string out = dir.file("img.exr");
  writeImageFile(Image(3, 3), out);
  Image bigger(9, 4);
  bigger.at(8, 3) = Color(2.0f);
  writeImageFile(bigger, out);
  Image back = readImageFile(out);
  CHECK(back.width == 9);
  CHECK(back.at(8, 3) == Color(2.0f));
  CHECK(dir.entries() == 1);
}
