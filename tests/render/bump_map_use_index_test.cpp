// POV-Ray 3.7's bump_map with use_index on a palette image (imageutil.cpp, bump_map, as
// facts): the three points' palette indices themselves, times bump_size, are the heights.
// Checked against the triangle's normal worked out here from those heights.
#include "images/image_values_file.h"
#include "render/bump_map.h"

#include <catch2/catch.hpp>

using namespace lucent;

namespace {

// A 3 x 3 palette image: its indices, and colours whose grey levels are something else.
ImageValueGrid indexGrid() {
  ImageValueGrid g;
  g.width = 3;
  g.height = 3;
  g.indices = {0, 5, 9, 2, 7, 15, 4, 1, 12};
  g.values.assign(9, 0.0f);
  return g;
}

Image colours() {
  Image im(3, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) im.at(x, y) = Color(0.1f * x, 0.2f * y, 0.3f);
  return im;
}

// The bent normal for a surface facing +y (POV-Ray's frame there is x, y and z themselves,
// the result (b.x, b.y, −b.z)) from the heights a·i1, a·i2, a·i3 in single precision.
Vec3 expectedUp(float a, int i1, int i2, int i3) {
  const Vec3 p1(0.0, double(a * float(i1)), 0.0);
  const Vec3 p2(-1.0, double(a * float(i2)), 1.0);
  const Vec3 p3(1.0, double(a * float(i3)), 1.0);
  const Vec3 b = glm::normalize(glm::cross(p3 - p2, p1 - p2));
  return Vec3(b.x, b.y, -b.z);
}

}  // namespace

TEST_CASE("bump_map use_index: the palette indices, unscaled, are the heights",
          "[render][bump][image-pattern]") {
  const ImageValueGrid grid = indexGrid();
  const Image pixels = colours();
  const Vec3 up(0.0, 1.0, 0.0);
  const float depth = 0.02f;
  // At pixel (1, 0): its own index 5, then (0, 1) and (2, 1) on the row below: 2 and 15.
  const Vec3 n =
      bumpMapNormalAt(pixels, depth, Vec2(1.5, 0.5), ImageInterpolation::none, false, up, &grid);
  const Vec3 e = expectedUp(depth, 5, 2, 15);
  CHECK(n.x == Approx(e.x).margin(1e-12));
  CHECK(n.y == Approx(e.y).margin(1e-12));
  CHECK(n.z == Approx(e.z).margin(1e-12));
  // At (0, 2) the neighbours wrap: (2, 0) and (1, 0), indices 9 and 5.
  const Vec3 w =
      bumpMapNormalAt(pixels, depth, Vec2(0.5, 2.5), ImageInterpolation::none, false, up, &grid);
  const Vec3 we = expectedUp(depth, 4, 9, 5);
  CHECK(w.x == Approx(we.x).margin(1e-12));
  CHECK(w.z == Approx(we.z).margin(1e-12));
  // Bilinear (POV-Ray's corners: the pixels whose centres surround the point): at (1.0, 0.5)
  // the index is (0 + 5) / 2 = 2.5, truncated to 2; its neighbours at (0.0, 1.5) and
  // (2.0, 1.5) blend pixels (2, 1) wrapped round and (0, 1), (15 + 2) / 2 = 8.5 to 8, and
  // (1, 1) and (2, 1), (7 + 15) / 2 = 11.
  const Vec3 b = bumpMapNormalAt(pixels, depth, Vec2(1.0, 0.5), ImageInterpolation::bilinear, false,
                                 up, &grid);
  const Vec3 be = expectedUp(depth, 2, 8, 11);
  CHECK(b.x == Approx(be.x).margin(1e-12));
  CHECK(b.z == Approx(be.z).margin(1e-12));
  // Without the indices the colours' grey levels bend it, much less.
  const Vec3 grey =
      bumpMapNormalAt(pixels, depth, Vec2(1.5, 0.5), ImageInterpolation::none, false, up);
  CHECK(std::abs(grey.x - n.x) > 0.05);
}
