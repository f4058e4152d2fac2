// Image files: round trips through OpenImageIO, and failures that leave old files intact.
#include "render/image_io.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>

#include <unistd.h>

using namespace lucent;
namespace fs = std::filesystem;

namespace {

// A fresh folder per test case, removed afterwards.
struct TempDir {
  fs::path path;
  TempDir() {
    static int counter = 0;
    path = fs::temp_directory_path() /
           ("lucent-io-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::string file(const std::string& name) const { return (path / name).string(); }
  size_t entries() const { return static_cast<size_t>(std::distance(fs::directory_iterator(path), {})); }
};

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

}  // namespace

TEST_CASE("PNG and PPM store POV-Ray's 8-bit sRGB encoding", "[render][io]") {
  TempDir dir;
  Image img = testImage();
  for (const char* name : {"a.png", "a.ppm"}) {
    writeImageFile(img, dir.file(name));
    Image back = readImageFile(dir.file(name), PixelDecoding::AsStored);
    REQUIRE(back.width == img.width);
    REQUIRE(back.height == img.height);
    for (size_t i = 0; i < img.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        INFO(name << " pixel " << i << " channel " << c);
        CHECK(back.pixels[i][c] * 255.0f == Approx(srgbByte(img.pixels[i][c])).margin(1e-3));
      }
  }
  // The sRGB table of POV-Ray's notes: 0.5 -> 188, 0.18 -> 118, 0.001 -> 3.
  Image back = readImageFile(dir.file("a.png"), PixelDecoding::AsStored);
  CHECK(back.at(0, 0).r * 255.0f == Approx(3));
  CHECK(back.at(0, 0).g * 255.0f == Approx(118));
  CHECK(back.at(0, 0).b * 255.0f == Approx(188));
}

TEST_CASE("EXR keeps linear float values exactly, HDR to RGBE precision, TIFF in 16 bits",
          "[render][io]") {
  TempDir dir;
  Image img = testImage();
  writeImageFile(img, dir.file("a.exr"));
  Image exr = readImageFile(dir.file("a.exr"));
  REQUIRE(exr.pixels.size() == img.pixels.size());
  CHECK(exr.pixels == img.pixels);  // bit for bit, negative values included

  writeImageFile(img, dir.file("a.hdr"));
  Image hdr = readImageFile(dir.file("a.hdr"));
  for (size_t i = 0; i < img.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      float v = std::max(0.0f, img.pixels[i][c]);
      // RGBE shares one exponent: 8 bits of mantissa relative to the largest channel.
      CHECK(hdr.pixels[i][c] == Approx(v).margin(maxComponent(img.pixels[i]) / 128.0f + 1e-6f));
    }

  writeImageFile(img, dir.file("a.tif"));
  Image tif = readImageFile(dir.file("a.tif"), PixelDecoding::AsStored);
  for (size_t i = 0; i < img.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      CHECK(tif.pixels[i][c] * 65535.0f ==
            Approx(std::floor(srgbEncode(img.pixels[i][c]) * 65535.0f + 0.5f)).margin(1e-2));

  writeImageFile(img, dir.file("a.jpg"));
  Image jpg = readImageFile(dir.file("a.jpg"));
  CHECK(jpg.width == img.width);
}

TEST_CASE("a write that fails leaves the existing file untouched and no temporary behind",
          "[render][io]") {
  TempDir dir;
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
  TempDir dir;
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
