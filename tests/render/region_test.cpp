// Any rectangle of the image renders to the same bits as those pixels of the whole image,
// in every sampling mode: the base of --region, checkpoint tiles and distributed tiles.
#include "scene_builder.h"

#include "render/renderer.h"

#include <catch2/catch.hpp>

#include <cstring>

using namespace lucent;
using namespace lucent::test;

namespace {

// Pixels of `part` (the rectangle `rect` of the image) that differ, bit for bit, from the
// same pixels of `whole`.
int differingPixels(const Image& whole, const Image& part, const PixelRect& rect) {
  int differ = 0;
  for (int y = rect.y0; y < rect.y1; ++y)
    for (int x = rect.x0; x < rect.x1; ++x)
      differ +=
          std::memcmp(&whole.at(x, y), &part.at(x - rect.x0, y - rect.y0), sizeof(Color)) != 0;
  return differ;
}

// Renders `rects` one by one and counts the pixels that differ from the whole image.
int differingPixels(const Scene& scene, const std::vector<PixelRect>& rects) {
  World world(scene);
  Renderer renderer(world, scene.cameras[0]);
  const Image whole = renderer.render().image;
  int differ = 0;
  for (const PixelRect& r : rects) {
    const Image part = renderer.renderRect(r).image;
    REQUIRE(part.width == r.width());
    REQUIRE(part.height == r.height());
    differ += differingPixels(whole, part, r);
  }
  return differ;
}

// Tiles of odd sizes (so that no tile edge falls on a 16-pixel thread tile's) and lone
// rectangles in the middle, at the edges and of one pixel.
std::vector<PixelRect> testRects(const Scene& scene) {
  const int w = scene.render.width, h = scene.render.height;
  std::vector<PixelRect> rects = tilesOf(wholeImage(w, h), 7);
  for (const PixelRect& r : tilesOf(wholeImage(w, h), 13)) rects.push_back(r);
  rects.push_back({11, 9, 12, 10});
  rects.push_back({0, 0, w, 1});
  rects.push_back({w - 3, 5, w, h});
  rects.push_back({5, 3, 31, 27});
  return rects;
}

}  // namespace

TEST_CASE("a rectangle renders to the bits of the whole image: one sample and supersampling",
          "[render][region]") {
  Scene scene;
  buildBusyScene(scene);
  scene.render.adaptive = 0.0;
  for (int samples : {1, 4}) {
    scene.render.samples = samples;
    CHECK(differingPixels(scene, testRects(scene)) == 0);
  }
}

TEST_CASE("a rectangle renders to the bits of the whole image: adaptive supersampling of centres",
          "[render][region]") {
  Scene scene;
  buildBusyScene(scene);
  // 16 samples: stages of 6, 12 and 16; 64: 6, 12, 24, 48, 64 (a margin of 5 pixels). A
  // low threshold refines many pixels, so refinement crosses every tile edge.
  for (int samples : {4, 16, 64}) {
    for (double threshold : {0.02, 0.2}) {
      scene.render.samples = samples;
      scene.render.adaptive = threshold;
      INFO("samples " << samples << ", threshold " << threshold);
      CHECK(differingPixels(scene, testRects(scene)) == 0);
    }
  }
}

TEST_CASE("a rectangle renders to the bits of the whole image: adaptive supersampling of corners",
          "[render][region]") {
  Scene scene;
  buildBusyScene(scene);
  scene.render.adaptiveMode = AdaptiveMode::Corners;
  scene.render.adaptive = 0.1;
  for (int depth : {1, 3}) {
    scene.render.adaptiveDepth = depth;
    INFO("depth " << depth);
    CHECK(differingPixels(scene, testRects(scene)) == 0);
  }
}

TEST_CASE("the margin of adaptive supersampling is one pixel per stage", "[render][region]") {
  Scene scene;
  buildBusyScene(scene);
  World world(scene);
  auto margin = [&](int samples, double adaptive, AdaptiveMode mode) {
    scene.render.samples = samples;
    scene.render.adaptive = adaptive;
    scene.render.adaptiveMode = mode;
    return Renderer(world, scene.cameras[0]).adaptiveMargin();
  };
  CHECK(margin(16, 0.1, AdaptiveMode::Centres) == 3);  // 6, 12, 16
  CHECK(margin(64, 0.1, AdaptiveMode::Centres) == 5);  // 6, 12, 24, 48, 64
  CHECK(margin(4, 0.1, AdaptiveMode::Centres) == 1);
  CHECK(margin(16, 0.0, AdaptiveMode::Centres) == 0);
  CHECK(margin(16, 0.1, AdaptiveMode::Corners) == 0);
}

TEST_CASE("a rectangle outside the image or empty is refused", "[render][region]") {
  Scene scene;
  buildBusyScene(scene);
  World world(scene);
  Renderer renderer(world, scene.cameras[0]);
  CHECK_THROWS_AS(renderer.renderRect({0, 0, 41, 30}), std::invalid_argument);
  CHECK_THROWS_AS(renderer.renderRect({-1, 0, 10, 10}), std::invalid_argument);
  CHECK_THROWS_AS(renderer.renderRect({5, 5, 5, 9}), std::invalid_argument);
}

TEST_CASE("tiles cover the area once, in row order", "[render][region]") {
  const std::vector<PixelRect> tiles = tilesOf({3, 2, 40, 19}, 16);
  REQUIRE(tiles.size() == 6);
  CHECK(tiles[0] == PixelRect{3, 2, 19, 18});
  CHECK(tiles[2] == PixelRect{35, 2, 40, 18});
  CHECK(tiles[3] == PixelRect{3, 18, 19, 19});
  long long covered = 0;
  for (const PixelRect& t : tiles) covered += t.pixels();
  CHECK(covered == 37 * 17);
}
