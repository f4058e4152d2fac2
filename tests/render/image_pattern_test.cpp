// image_pattern's value is POV-Ray 3.7's: images of every kind the reader tells apart
// (palette with and without tRNS, grey of 2 and 8 bits, grey with alpha, RGB and RGBA, 16-bit
// grey and RGB), each with every interpolation, with and without use_alpha, through every
// map_type, some once, at points where POV-Ray's own pattern function was evaluated
// (tests/data/image_pattern/make_references.sh).
#include "scenegraph/image_pattern.h"
#include "images/builtin/builtin_images.h"
#include "images/image_values_file.h"
#include "render/patterns/pattern_value.h"

#include "../support/paths.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace lucent;

namespace {

std::string dataFile(const std::string& name) {
  return std::string(lucentSourceDir()) + "/tests/data/image_pattern/" + name;
}

struct Reference {
  std::string image;
  int mapType = 0, once = 0, interpolate = 0, useAlpha = 0;
  Vec3 p{0.0};
  double value = 0.0;
};

std::vector<Reference> references() {
  std::ifstream in(dataFile("values.csv"));
  std::vector<Reference> refs;
  std::string line;
  while (std::getline(in, line)) {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream s(line);
    Reference r;
    s >> r.image >> r.mapType >> r.once >> r.interpolate >> r.useAlpha >> r.p.x >> r.p.y >> r.p.z >>
        r.value;
    if (s) refs.push_back(r);
  }
  return refs;
}

PatternSpec imagePatternSpec(const Reference& r) {
  static std::map<std::pair<std::string, bool>, std::shared_ptr<const ImageValueGrid>> grids;
  auto& grid = grids[{r.image, r.useAlpha != 0}];
  if (!grid) grid = readImagePatternValues(dataFile(r.image + ".png"), r.useAlpha != 0);
  auto im = std::make_shared<ImagePattern>();
  static const ImageProjection kByMapType[] = {
      ImageProjection::planar, ImageProjection::spherical, ImageProjection::cylindrical,
      ImageProjection::planar, ImageProjection::planar,    ImageProjection::torus};
  im->projection = kByMapType[r.mapType];
  im->once = r.once != 0;
  static const ImageInterpolation kByNumber[] = {
      ImageInterpolation::none, ImageInterpolation::none, ImageInterpolation::bilinear,
      ImageInterpolation::bicubic, ImageInterpolation::normalized};
  im->interpolation = kByNumber[r.interpolate];
  im->useAlpha = r.useAlpha != 0;
  im->values = grid;
  PatternSpec s;
  s.type = PatternType::image;
  s.frequency = defaultFrequency(PatternType::image);
  s.image = im;
  return s;
}

}  // namespace

TEST_CASE("image_pattern: every reference value is POV-Ray's", "[patterns][image-pattern]") {
  const std::vector<Reference> refs = references();
  REQUIRE(refs.size() == 2592);
  int checked = 0;
  double worst = 0.0;
  for (const Reference& r : refs) {
    INFO(r.image << " map_type " << r.mapType << " once " << r.once << " interpolate "
                 << r.interpolate << " use_alpha " << r.useAlpha << " at " << r.p.x << " " << r.p.y
                 << " " << r.p.z);
    const double v = patternValue(imagePatternSpec(r), r.p);
    // Unblended pixels are POV-Ray's floats exactly; blends differ only by where single
    // precision rounds (POV-Ray blends colours, then takes the grey).
    CHECK(v == Approx(r.value).margin(r.interpolate == 0 ? 1e-12 : 1e-6));
    worst = std::max(worst, std::fabs(v - r.value));
    ++checked;
  }
  CHECK(checked == 2592);
  INFO("largest difference " << worst);
  CHECK(worst < 1e-6);
}

TEST_CASE("image_pattern: a palette PNG's value is its colour's grey, not its index",
          "[patterns][image-pattern]") {
  // Each pixel's value is 0.297 r + 0.589 g + 0.114 b of its palette colour over 255, in
  // single precision (image_pattern's use_color, its default), whatever its index.
  auto grid = readImagePatternValues(dataFile("palette.png"), false);
  REQUIRE(grid->width == 5);
  REQUIRE(grid->height == 4);
  REQUIRE(grid->indices.size() == 20);
  // The file's own palette and indices, read by libpng, against the formula.
  PngPixels png;
  REQUIRE(readPngHeader(dataFile("palette.png"), png).empty());
  REQUIRE(readPngValues(dataFile("palette.png"), png).empty());
  for (int i = 0; i < 20; ++i) {
    const auto& c = png.paletteColours[png.values[i]];
    const float expected = static_cast<float>(0.297 * (c[0] / 255.0f) + 0.589 * (c[1] / 255.0f) +
                                              0.114 * (c[2] / 255.0f));
    CHECK(grid->values[i] == expected);
    CHECK(grid->indices[i] == png.values[i]);
  }
  // use_alpha on a palette PNG without tRNS: every colour opaque, so every transmit 0
  // (POV-Ray keeps a palette as an RGBA colour map, which holds transparency).
  auto alpha = readImagePatternValues(dataFile("palette.png"), true);
  for (float v : alpha->values) CHECK(v == 0.0f);
}
