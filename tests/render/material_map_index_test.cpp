// POV-Ray 3.7's material_map choice (imageutil.cpp, material_map, as facts): the material
// number from the image (a palette index, blended and truncated; red x 255 without a
// palette) and the entry it picks among the map's, each against an evaluation written out
// here in POV-Ray's own steps.
#include "images/image_values_file.h"
#include "render/image_projection.h"
#include "scenegraph/map_blend.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lucent;

namespace {

// POV-Ray's walk: a number above the count is taken modulo it, then the list is followed
// while there is a next texture and fewer steps than the number were taken.
size_t povrayWalk(int number, int count) {
  if (number > count) number %= count;
  size_t at = 0;
  for (int step = 0; at + 1 < static_cast<size_t>(count) && step < number; ++step) ++at;
  return at;
}

// A 3 x 2 grid: palette indices (or none) and red channels.
ImageValueGrid grid(bool palette) {
  ImageValueGrid g;
  g.width = 3;
  g.height = 2;
  g.indices = {3, 6, 11, 0, 9, 14};
  if (!palette) g.indices.clear();
  for (int v : {12, 1, 200, 255, 0, 7}) g.values.push_back(static_cast<float>(v) / 255.0f);
  return g;
}

}  // namespace

TEST_CASE("material_map's entry for a number: modulo above the count, the count itself the last",
          "[render][material-map][image-pattern]") {
  for (int count = 1; count <= 6; ++count)
    for (int number = -3; number <= 40; ++number) {
      INFO("count " << count << ", number " << number);
      const MapBlend b = mapIndexEntry(number, static_cast<size_t>(count));
      CHECK(b.a == povrayWalk(number, count));
      CHECK(b.b == b.a);
      CHECK(b.wa == 1.0f);
    }
  // The quirks written out: with 5 textures, 5 is the last, 6 the second, 10 the first.
  CHECK(mapIndexEntry(5, 5).a == 4);
  CHECK(mapIndexEntry(6, 5).a == 1);
  CHECK(mapIndexEntry(10, 5).a == 0);
  CHECK(mapIndexEntry(-2, 5).a == 0);
}

TEST_CASE("material_map's number: the palette index under the point, or red x 255",
          "[render][material-map][image-pattern]") {
  const ImageValueGrid palette = grid(true), rgb = grid(false);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) {
      const Vec2 centre(x + 0.5, y + 0.5);
      const size_t i = static_cast<size_t>(y) * 3 + x;
      CHECK(sampleImageIndex(palette, centre, ImageInterpolation::none, false) ==
            palette.indices[i]);
      CHECK(samplePaletteIndex(rgb, centre, ImageInterpolation::none, false) == -1);
      // v / 255 in single precision times 255 truncates back to v for every byte.
      CHECK(sampleImageIndex(rgb, centre, ImageInterpolation::none, false) ==
            std::lround(rgb.values[i] * 255.0f));
    }
  // Bilinear: at (2.0, 0.5) POV-Ray's corners are pixels (2, 0) and (1, 0) at weight 1/2
  // each: (11 + 6) / 2 = 8.5, truncated to 8. At (1.0, 1.0) the four of (0..1, 0..1) by a
  // quarter: (3 + 6 + 0 + 9) / 4 = 4.5, so 4.
  CHECK(sampleImageIndex(palette, Vec2(2.0, 0.5), ImageInterpolation::bilinear, false) == 8);
  CHECK(sampleImageIndex(palette, Vec2(1.0, 1.0), ImageInterpolation::bilinear, false) == 4);
  // Without a palette the -1s blend to exactly -1 there, and the red does: (200 + 1) / 2 over
  // 255, times 255, truncated: 100.
  CHECK(sampleImageIndex(rgb, Vec2(2.0, 0.5), ImageInterpolation::bilinear, false) == 100);
  // Nearest pixel at the edge of a `once` image; wrapped round a repeated one.
  CHECK(sampleImageIndex(palette, Vec2(2.9, 1.9), ImageInterpolation::none, true) == 14);
  CHECK(sampleImageIndex(palette, Vec2(3.5, 0.5), ImageInterpolation::none, false) == 3);
}

TEST_CASE("material_map's image: 16-bit reds give the number v / 257 truncated",
          "[render][material-map][image-pattern]") {
  ImageValueGrid g;
  g.width = 1;
  g.height = 1;
  for (int v : {0, 256, 257, 514, 1000, 12345, 65534, 65535}) {
    g.values = {static_cast<float>(v) / 65535.0f};
    INFO("red " << v);
    CHECK(sampleImageIndex(g, Vec2(0.5), ImageInterpolation::none, false) == v / 257);
  }
}
