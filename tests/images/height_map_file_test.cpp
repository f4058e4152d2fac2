// A height field's image is read as POV-Ray 3.7 reads it: the heights of test images in
// every storage POV-Ray treats differently (grey and RGB, 8 and 16 bits) against POV-Ray's
// own, measured by tests/data/height_field/make_references.sh.
#include "images/height_map_file.h"

#include "../support/paths.h"
#include "../temp_dir.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

using namespace lucent;

namespace {

std::string dataFile(const std::string& name) {
  return std::string(lucentSourceDir()) + "/tests/data/height_field/" + name;
}

std::vector<long> povHeights(const std::string& name) {
  std::ifstream in(dataFile(name + ".pov-heights.txt"));
  std::vector<long> v;
  long x;
  while (in >> x) v.push_back(x);
  return v;
}

}  // namespace

TEST_CASE("height field images: every value is POV-Ray's height", "[images][height-field]") {
  for (const char* name : {"g8", "g16", "rgb8", "rgb16", "p8"}) {
    INFO(name);
    const std::vector<long> pov = povHeights(name);
    REQUIRE(pov.size() == 256);
    auto map = readHeightMapFile(dataFile(std::string(name) + ".png"));
    REQUIRE(map->width == 258);
    REQUIRE(map->depth == 3);
    int wrong = 0;
    for (int i = 0; i < 256; ++i) wrong += map->at(i + 1, 1) != pov[i];
    CHECK(wrong == 0);
  }
  // The 8-bit grey PNG goes through POV-Ray's grey colour map, which lowers 84 of the 256
  // values by one: 20 and 200 become 19 and 199 (x 257), 120 stays.
  auto g8 = readHeightMapFile(dataFile("g8.png"));
  CHECK(g8->at(21, 1) == 19 * 257);
  CHECK(g8->at(201, 1) == 199 * 257);
  CHECK(g8->at(121, 1) == 120 * 257);
}

TEST_CASE("height field images: a grey PNG with alpha gives its stored grey, as POV-Ray's",
          "[images][height-field]") {
  // tests/data/png_kinds/grey_alpha8.png: grey (23x + 5y) mod 256 under alpha 7x. POV-Ray
  // 3.7's trace() down its middle row (image row 3) at x = 1..9 gave 38, 61, ..., 222
  // times 257: the grey not multiplied by the alpha (which OpenImageIO's reading would be).
  auto map =
      readHeightMapFile(std::string(lucentSourceDir()) + "/tests/data/png_kinds/grey_alpha8.png");
  REQUIRE((map->width == 11 && map->depth == 7));
  for (int x = 1; x <= 9; ++x) CHECK(map->at(x, 3) == (x * 23 + 3 * 5) % 256 * 257);
}

TEST_CASE("height field images: the image's top row is at z = 1", "[images][height-field]") {
  // rgb8.png's rows are equal; g8.png's too: the flip shows in a 2 x 2 image of the tests'.
  auto map = readHeightMapFile(dataFile("flip.pgm"));
  REQUIRE(map->width == 2);
  REQUIRE(map->depth == 2);
  CHECK(map->at(0, 1) == 10 * 257);  // image row 0
  CHECK(map->at(1, 1) == 20 * 257);
  CHECK(map->at(0, 0) == 30 * 257);  // image row 1
  CHECK(map->at(1, 0) == 40 * 257);
}

TEST_CASE("height field images: a palette PNG's heights are its indices times 256",
          "[images][height-field]") {
  // p8.png's palette colours are not their indices' greys: the index alone counts.
  auto p8 = readHeightMapFile(dataFile("p8.png"));
  CHECK(p8->at(1, 1) == 0);
  CHECK(p8->at(101, 1) == 100 * 256);
  CHECK(p8->at(256, 1) == 255 * 256);
  // A 2 x 2 palette image of another bit depth's file.
  auto small = readHeightMapFile(dataFile("palette.png"));
  CHECK(small->width == 2);
}

TEST_CASE("height field images: a GIF's heights are its palette indices times 256",
          "[images][height-field][gif]") {
  // gif_plain.gif (tests/data/sdl/scenes/make_gif_maps.py): 8 x 8 pixels, index
  // (x / 2 + y / 2) % 4 at column x of row y (top first), colours unlike their indices.
  auto gif =
      readHeightMapFile(std::string(lucentSourceDir()) + "/tests/data/sdl/scenes/gif_plain.gif");
  REQUIRE(gif->width == 8);
  REQUIRE(gif->depth == 8);
  for (int z = 0; z < 8; ++z)
    for (int x = 0; x < 8; ++x) {
      const int row = 7 - z;  // POV-Ray's z = 0 is the image's bottom row
      INFO("x " << x << ", z " << z);
      CHECK(gif->at(x, z) == ((x / 2 + row / 2) % 4) * 256);
    }
}

TEST_CASE("height field images: a POT file's heights are its two halves' indices",
          "[images][height-field][gif]") {
  // gif_heights.pot (make_gif_maps.py): an 8 x 3 GIF of 256 greys for a 4 x 3 field, the
  // high byte 16 (x + 4 row) in the left half, the low byte 255 - 20 x - row in the right.
  auto pot =
      readHeightMapFile(std::string(lucentSourceDir()) + "/tests/data/sdl/scenes/gif_heights.pot");
  REQUIRE(pot->width == 4);
  REQUIRE(pot->depth == 3);
  for (int z = 0; z < 3; ++z)
    for (int x = 0; x < 4; ++x) {
      const int row = 2 - z;
      INFO("x " << x << ", z " << z);
      CHECK(pot->at(x, z) == (16 * (x + 4 * row)) * 256 + (255 - 20 * x - row));
    }
}

TEST_CASE("height field images: what is refused", "[images][height-field]") {
  CHECK_THROWS_AS(readHeightMapFile(dataFile("missing.png")), HeightMapError);
  CHECK_THROWS_WITH(readHeightMapFile(dataFile("one-pixel.pgm")),
                    Catch::Contains("at least 2 x 2"));
  CHECK_THROWS_AS(readHeightMapFile(dataFile("png.py")), HeightMapError);
}

TEST_CASE("height field images: a PNM maximum value outside 1..65535 is refused",
          "[images][height-field]") {
  const test::TempDir dir("height-pnm");
  const std::string path = (dir.path / "max.pgm").string();
  auto write = [&](const std::string& header) {
    std::ofstream out(path, std::ios::binary);
    out << header << std::string(8, '\x01');
  };
  for (const char* max : {"0", "65536", "70000", "-3", "x"}) {
    write(std::string("P5\n# a comment\n2 2\n") + max + "\n");
    CHECK_THROWS_WITH(readHeightMapFile(path),
                      Catch::Contains("maximum value is '" + std::string(max) + "'"));
  }
  // The bounds themselves are read.
  write("P5 2 2 255\n");
  CHECK(readHeightMapFile(path)->values.size() == 4);
  write("P5 2 2 65535\n");
  CHECK(readHeightMapFile(path)->values.size() == 4);
}
