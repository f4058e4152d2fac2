// Projected image maps (render/image_projection.h): where POV-Ray's four projections put
// chosen points on the image, worked out by hand from its formulas, and the colours its
// interpolations blend from a 2 x 2 image.
#include "render/image_projection.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lucent;

namespace {

constexpr double kEps = 1e-10;  // POV-Ray's nudge of every image coordinate

void checkAt(const std::optional<Vec2>& got, double x, double y) {
  REQUIRE(got);
  CHECK(got->x == Approx(x).margin(1e-9));
  CHECK(got->y == Approx(y).margin(1e-9));
}

// Columns red | green over blue | white (row 0 the top).
Image twoByTwo() {
  Image im(2, 2);
  im.at(0, 0) = Color(1, 0, 0);
  im.at(1, 0) = Color(0, 1, 0);
  im.at(0, 1) = Color(0, 0, 1);
  im.at(1, 1) = Color(1, 1, 1);
  return im;
}

void checkColour(const Color& got, const Color& want) {
  for (int i = 0; i < 3; ++i) CHECK(got[i] == Approx(want[i]).margin(1e-6));
}

}  // namespace

TEST_CASE("image projection: planar puts [0,1]² of z = 0 on the image, bottom-left at the origin",
          "[render][texture][image-map]") {
  // x = 0.25 of 8 columns: 2; y = 0.75 of 4 rows up is 1 row down from the top.
  checkAt(projectToImage(ImageProjection::planar, Vec3(0.25, 0.75, 5.0), 8, 4, false), 2.0 + kEps,
          1.0 - kEps);
  // Repeated: x = −0.25 is x = 0.75.
  checkAt(projectToImage(ImageProjection::planar, Vec3(-0.25, 0.75, 0.0), 8, 4, false), 6.0 + kEps,
          1.0 - kEps);
  // Once: nothing off the square, the square's edge included.
  CHECK_FALSE(projectToImage(ImageProjection::planar, Vec3(-0.25, 0.5, 0.0), 8, 4, true));
  CHECK_FALSE(projectToImage(ImageProjection::planar, Vec3(0.5, 1.01, 0.0), 8, 4, true));
  checkAt(projectToImage(ImageProjection::planar, Vec3(0.5, 0.5, 0.0), 8, 4, true), 4.0 + kEps,
          2.0 - kEps);
}

TEST_CASE("image projection: spherical longitude from +x towards +z, latitude up +y",
          "[render][texture][image-map]") {
  // +z is a quarter turn; the equator is half way down. The radius does not matter.
  checkAt(projectToImage(ImageProjection::spherical, Vec3(0.0, 0.0, 3.0), 8, 4, false), 2.0 + kEps,
          2.0 - kEps);
  // 30° above the equator at −x: half a turn; latitude 0.5 + 1/6 of the height up.
  const double up = (0.5 + 1.0 / 6.0) * 4.0;
  checkAt(projectToImage(ImageProjection::spherical,
                         Vec3(-std::cos(M_PI / 6), std::sin(M_PI / 6), 0.0), 8, 4, false),
          4.0 + kEps, 4.0 - up - kEps);
  CHECK_FALSE(projectToImage(ImageProjection::spherical, Vec3(0.0), 8, 4, false));
}

TEST_CASE("image projection: cylindrical takes y up the image and the longitude across",
          "[render][texture][image-map]") {
  // −z: three quarters of a turn; y = 0.25: a quarter up (one row above the bottom).
  checkAt(projectToImage(ImageProjection::cylindrical, Vec3(0.0, 0.25, -2.0), 8, 4, false),
          6.0 + kEps, 3.0 - kEps);
  CHECK_FALSE(projectToImage(ImageProjection::cylindrical, Vec3(1.0, 1.5, 0.0), 8, 4, true));
  CHECK(projectToImage(ImageProjection::cylindrical, Vec3(1.0, 1.5, 0.0), 8, 4, false));
}

TEST_CASE("image projection: torus round the ring and round its tube of major radius 1",
          "[render][texture][image-map]") {
  // The outer equator at +x: longitude 0, half way round the tube.
  checkAt(projectToImage(ImageProjection::torus, Vec3(2.0, 0.0, 0.0), 8, 4, false), kEps,
          2.0 - kEps);
  // The top of the tube over +z: a quarter turn round the ring, three quarters round the
  // tube (its angle counted from the inner equator, downwards first).
  checkAt(projectToImage(ImageProjection::torus, Vec3(0.0, 1.0, 1.0), 8, 4, false), 2.0 + kEps,
          1.0 - kEps);
}

TEST_CASE("image projection: (u,v) with scale, repeated or once", "[render][texture][image-map]") {
  checkAt(uvToImage(Vec2(0.5, 0.5), Vec2(2.0, 1.0), 8, 4, false), 2.0 + kEps, 2.0 - kEps);
  CHECK_FALSE(uvToImage(Vec2(2.5, 0.5), Vec2(2.0, 1.0), 8, 4, true));
}

TEST_CASE("image interpolation: none, bilinear, normalized distance and bicubic",
          "[render][texture][image-map]") {
  const Image im = twoByTwo();
  const Color mean(0.5f, 0.5f, 0.5f);
  // Inside pixel (1, 0): that pixel, unblended.
  checkColour(sampleImage(im, Vec2(1.3, 0.6), ImageInterpolation::none, false, {}).rgb,
              Color(0, 1, 0));
  // Pixel centres give the pixel itself with every filter.
  for (auto i :
       {ImageInterpolation::bilinear, ImageInterpolation::normalized, ImageInterpolation::bicubic})
    checkColour(sampleImage(im, Vec2(0.5, 1.5), i, false, {}).rgb, Color(0, 0, 1));
  // The corner the four pixels share: their mean, for bilinear and normalized alike.
  checkColour(sampleImage(im, Vec2(1.0, 1.0), ImageInterpolation::bilinear, false, {}).rgb, mean);
  checkColour(sampleImage(im, Vec2(1.0, 1.0), ImageInterpolation::normalized, false, {}).rgb, mean);
  // A quarter of the way from red's centre to green's: bilinear 3:1; normalized by inverse
  // squared distances to the four centres (0.25² + 0² and so on).
  const PigmentColor b = sampleImage(im, Vec2(0.75, 0.5), ImageInterpolation::bilinear, false, {});
  checkColour(b.rgb, Color(0.75f, 0.25f, 0.0f));
  const double w[4] = {1 / (0.75 * 0.75), 1 / (0.25 * 0.25), 1 / (0.75 * 0.75 + 1),
                       1 / (0.25 * 0.25 + 1)};  // green, red, white, blue
  const double total = w[0] + w[1] + w[2] + w[3];
  checkColour(
      sampleImage(im, Vec2(0.75, 0.5), ImageInterpolation::normalized, false, {}).rgb,
      Color(static_cast<float>((w[1] + w[2]) / total), static_cast<float>((w[0] + w[2]) / total),
            static_cast<float>((w[2] + w[3]) / total)));
  // The left edge of red: repeated, half red and half green (the column wraps round);
  // once, red alone (the edge pixel repeats).
  checkColour(sampleImage(im, Vec2(0.0, 0.5), ImageInterpolation::bilinear, false, {}).rgb,
              Color(0.5f, 0.5f, 0.0f));
  checkColour(sampleImage(im, Vec2(0.0, 0.5), ImageInterpolation::bilinear, true, {}).rgb,
              Color(1, 0, 0));
  // filter all and transmit all go with every pixel.
  const PigmentColor ft =
      sampleImage(im, Vec2(0.5, 0.5), ImageInterpolation::none, false, {0.25f, 0.5f});
  CHECK(ft.ft.filter == 0.25f);
  CHECK(ft.ft.transmit == 0.5f);
}

TEST_CASE("image interpolation: a palette entry's own filter and transmit, blended as colours",
          "[render][texture][image-map][palette]") {
  // 2 x 2 pixels of palette indices 0 1 / 2 3 (rows top first); entry 1 filters 0.8, entry 2
  // transmits 0.6, entry 3 has both of its own; the image's `all` filter 0.1 is entry 0's
  // and entry 2's filter.
  Image im(2, 2);
  auto grid = std::make_shared<ImageValueGrid>();
  grid->width = grid->height = 2;
  grid->values.assign(4, 0.0f);
  grid->indices = {0, 1, 2, 3};
  grid->paletteSize = 4;
  ImageTexture t;
  t.all = {0.1f, 0.0f};
  t.palette = {{1, 0.8f, std::nullopt}, {2, std::nullopt, 0.6f}, {3, 0.3f, 0.2f}};
  t.paletteIndices = grid;
  t.interpolation = ImageInterpolation::none;
  const FilterTransmit expected[4] = {{0.1f, 0.0f}, {0.8f, 0.0f}, {0.1f, 0.6f}, {0.3f, 0.2f}};
  for (int i = 0; i < 4; ++i) {
    const PigmentColor c = sampleImageTexture(im, t, Vec2(0.5 + i % 2, 0.5 + i / 2));
    CHECK(c.ft.filter == expected[i].filter);
    CHECK(c.ft.transmit == expected[i].transmit);
  }
  // Bilinear a quarter of the way from pixel 0's centre towards pixel 1's, on the top row:
  // 3:1 of their values.
  t.interpolation = ImageInterpolation::bilinear;
  const PigmentColor b = sampleImageTexture(im, t, Vec2(0.75, 0.5));
  CHECK(b.ft.filter == Approx(0.75 * 0.1 + 0.25 * 0.8).epsilon(1e-6));
  CHECK(b.ft.transmit == Approx(0.0).margin(1e-7));
  // The corner the four share: their mean.
  const PigmentColor m = sampleImageTexture(im, t, Vec2(1.0, 1.0));
  CHECK(m.ft.filter == Approx((0.1 + 0.8 + 0.1 + 0.3) / 4).epsilon(1e-6));
  CHECK(m.ft.transmit == Approx((0.6 + 0.2) / 4).epsilon(1e-6));
  // Without entries of its own, `all` is added to every pixel as before.
  t.palette.clear();
  CHECK(sampleImageTexture(im, t, Vec2(0.5, 0.5)).ft == FilterTransmit{0.1f, 0.0f});
}

TEST_CASE("image interpolation: an image's own alpha as transmit, blended as colours",
          "[render][texture][image-map][alpha]") {
  // 2 x 2 pixels whose alphas give transmits 0, 0.5 / 1, 0.25 (rows top first).
  Image im(2, 2);
  auto alpha = std::make_shared<ImageValueGrid>();
  alpha->width = alpha->height = 2;
  alpha->values = {0.0f, 0.5f, 1.0f, 0.25f};
  ImageTexture t;
  t.useAlpha = true;
  t.alphaTransmit = alpha;
  t.interpolation = ImageInterpolation::none;
  CHECK(t.seeThrough());
  CHECK(!t.plainUV());
  for (int i = 0; i < 4; ++i) {
    const PigmentColor c = sampleImageTexture(im, t, Vec2(0.5 + i % 2, 0.5 + i / 2));
    CHECK(c.ft.filter == 0.0f);
    CHECK(c.ft.transmit == alpha->values[i]);
  }
  // `all` adds to it (POV-Ray's transmit all supplements the alpha).
  t.all = {0.2f, 0.125f};
  const PigmentColor added = sampleImageTexture(im, t, Vec2(1.5, 0.5));
  CHECK(added.ft.filter == 0.2f);
  CHECK(added.ft.transmit == 0.625f);
  // Bilinear at the corner the four share: the mean of their transmits.
  t.interpolation = ImageInterpolation::bilinear;
  const PigmentColor m = sampleImageTexture(im, t, Vec2(1.0, 1.0));
  CHECK(m.ft.transmit == Approx(0.125 + (0.0 + 0.5 + 1.0 + 0.25) / 4).epsilon(1e-6));
}

TEST_CASE("image interpolation: a palette entry's own transmit replaces its alpha",
          "[render][texture][image-map][alpha][palette]") {
  Image im(2, 1);
  auto indices = std::make_shared<ImageValueGrid>();
  indices->width = 2;
  indices->height = 1;
  indices->values.assign(2, 0.0f);
  indices->indices = {0, 1};
  indices->paletteSize = 2;
  auto alpha = std::make_shared<ImageValueGrid>();
  alpha->width = 2;
  alpha->height = 1;
  alpha->values = {0.75f, 0.5f};
  ImageTexture t;
  t.interpolation = ImageInterpolation::none;
  t.paletteIndices = indices;
  t.palette = {{1, std::nullopt, 0.1f}};
  t.useAlpha = true;
  t.alphaTransmit = alpha;
  CHECK(sampleImageTexture(im, t, Vec2(0.5, 0.5)).ft.transmit == 0.75f);  // its alpha
  CHECK(sampleImageTexture(im, t, Vec2(1.5, 0.5)).ft.transmit == 0.1f);   // its own
}
