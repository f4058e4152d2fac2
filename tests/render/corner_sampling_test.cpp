// adaptive-mode="corners" (POV-Ray's +AM2): shared pixel corners, squares split only where
// their corners differ, the same image for any number of threads.
#include "scene_builder.h"

#include "render/corner_sampling.h"
#include "render/renderer.h"

#include <catch2/catch.hpp>

#include <cstring>

using namespace lucent;
using namespace lucent::test;

namespace {

// 16 x 12 pixels: one tile, so every shared sample is traced once.
void cornerSettings(Scene& scene, double threshold, int depth) {
  scene.render.width = 16;
  scene.render.height = 12;
  scene.render.adaptive = threshold;
  scene.render.adaptiveMode = AdaptiveMode::Corners;
  scene.render.adaptiveDepth = depth;
  scene.cameras.push_back(lookingFrom(Vec3(0, 0, 0), Vec3(0, 0, -1), 90));
}

// A bright wall left of film x = 8.6 (world x = 0.375 at distance 5, fov 90 on 16 pixels:
// 8 + 0.375 / 5 * 8), black to the right.
void addWall(Scene& scene) {
  addShape(scene, BoxSpec{Vec3(-20, -20, -6), Vec3(0.375, 20, -5)},
           addMaterial(scene, emissive(Color(1.0f, 0.5f, 0.25f))));
}

RenderResult renderOn(const Scene& scene, int threads = 1) {
  World world(scene);
  Renderer renderer(world, scene.cameras[0]);
  RenderControl control;
  control.threads = threads;
  return renderer.render(control);
}

}  // namespace

TEST_CASE("POV-Ray's corner test: the sum of the channel differences at gamma 2.5",
          "[render][corners]") {
  // 0.5^0.4 = 0.7579, 0.55^0.4 = 0.7875: 0.0296 a channel, 0.0888 for three.
  CHECK_FALSE(cornersDiffer(Color(0.5f), Color(0.55f), 0.3f));
  CHECK(cornersDiffer(Color(0.5f), Color(0.55f), 0.08f));
  CHECK_FALSE(cornersDiffer(Color(0.5f), Color(0.55f), 0.09f));
  // One channel from 0 to 1 differs by 1; a linear 0.01 is already 0.158 after encoding.
  CHECK(cornersDiffer(Color(0, 0, 0), Color(0, 0, 1), 1.0f));
  CHECK(cornersDiffer(Color(0.0f), Color(0.01f, 0, 0), 0.15f));
  CHECK_FALSE(cornersDiffer(Color(0.0f), Color(0.01f, 0, 0), 0.16f));
  // Threshold 0: every pair "differs", as POV-Ray's +A0.0 splits every pixel.
  CHECK(cornersDiffer(Color(0.3f), Color(0.3f), 0.0f));
}

TEST_CASE("a flat image traces each pixel corner once and nothing else", "[render][corners]") {
  Scene scene;
  cornerSettings(scene, 0.3, 3);
  scene.render.background = Color(0.25f, 0.5f, 0.75f);
  RenderResult r = renderOn(scene);
  CHECK(r.stats.primary == 17u * 13u);
  for (const Color& p : r.image.pixels) REQUIRE(p == Color(0.25f, 0.5f, 0.75f));
}

TEST_CASE("threshold 0 splits every pixel fully, each lattice point traced once",
          "[render][corners]") {
  Scene scene;
  cornerSettings(scene, 0.0, 3);  // 4 lattice steps a pixel side
  scene.render.background = Color(0.25f, 0.5f, 0.75f);
  RenderResult r = renderOn(scene);
  // POV-Ray traces 25 - 4 = 21 samples a pixel besides the corners; shared, the 16 x 12
  // pixels need the (16*4+1) x (12*4+1) lattice once.
  CHECK(r.stats.primary == 65u * 49u);
  CHECK(r.stats.primary < 17u * 13u + 21u * 16u * 12u);
  for (const Color& p : r.image.pixels) REQUIRE(p == Color(0.25f, 0.5f, 0.75f));
}

TEST_CASE("only the pixels an edge crosses are split, and only where it is", "[render][corners]") {
  Scene scene;
  cornerSettings(scene, 0.3, 3);
  addWall(scene);
  RenderResult r = renderOn(scene);
  const Color wall(1.0f, 0.5f, 0.25f), black(0.0f);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 16; ++x) {
      INFO("pixel " << x << ", " << y);
      const Color& p = r.image.at(x, y);
      if (x < 8) REQUIRE(p == wall);
      if (x > 8) REQUIRE(p == black);
      if (x == 8) {
        // Lattice columns at 8, 8.25, 8.5 see the wall, 8.75 and 9 do not. The left half
        // agrees (the wall); the right half splits once more: columns 8.5-8.75 are half
        // wall, 8.75-9 black. (1 + 1 + 1/4 + 1/4) / 4 = 0.625 of the wall.
        REQUIRE(p.r == Approx(0.625f * wall.r));
        REQUIRE(p.g == Approx(0.625f * wall.g));
        REQUIRE(p.b == Approx(0.625f * wall.b));
      }
    }
  // The corners, then per edge pixel 5 samples for the first split and 9 for the two right
  // quarters; each pixel below the first shares 2 of them with the pixel above.
  CHECK(r.stats.primary == 17u * 13u + 14u + 11u * 12u);
  // Far below what 25 samples a pixel everywhere would cost.
  CHECK(r.stats.primary < 25u * 16u * 12u);
}

TEST_CASE("depth 1 is the mean of the four corners, never split", "[render][corners]") {
  Scene scene;
  cornerSettings(scene, 0.0, 1);
  addWall(scene);
  RenderResult r = renderOn(scene);
  CHECK(r.stats.primary == 17u * 13u);
  // Edge pixel: corners at x = 8 (wall) and x = 9 (black).
  CHECK(r.image.at(8, 5).r == Approx(0.5f));
  CHECK(r.image.at(7, 5) == Color(1.0f, 0.5f, 0.25f));
}

TEST_CASE("corner sampling gives the same image bit for bit with 1 and 2 threads",
          "[render][corners][determinism]") {
  Scene scene;
  scene.render.width = 53;  // several tiles, a ragged last one
  scene.render.height = 37;
  scene.render.adaptive = 0.1;
  scene.render.adaptiveMode = AdaptiveMode::Corners;
  scene.render.adaptiveDepth = 4;
  scene.render.background = Color(0.3f, 0.4f, 0.6f);
  scene.cameras.push_back(lookingFrom(Vec3(0, 2, 6), Vec3(0, 0.5, 0), 50));
  Material floor;
  floor.diffuse = Color(1.0f);
  floor.texture = CheckerTexture{Color(1.0f), Color(0.1f), 0.5, {}};
  floor.ambient = Color(0.1f);
  addShape(scene, PlaneSpec{Vec3(0, 1, 0), 0.0}, addMaterial(scene, floor));
  Material red;
  red.diffuse = Color(0.9f, 0.2f, 0.1f);
  red.specular = Color(0.5f);
  red.shininess = 40;
  addShape(scene, SphereSpec{Vec3(0.5, 0.8, 0), 0.8}, addMaterial(scene, red));
  scene.lights.push_back(areaLight(Vec3(3, 6, 4), Vec3(1.5, 0, 0), Vec3(0, 0, 1.5), 3, 3, true));

  RenderResult a = renderOn(scene, 1);
  RenderResult b = renderOn(scene, 2);
  RenderResult c = renderOn(scene, 2);
  CHECK(sameBits(a.image, b.image));
  CHECK(sameBits(b.image, c.image));
  CHECK(a.stats.primary == b.stats.primary);
  // Something was split (more than the corners), but not everything: the full lattice of
  // 8 x 8 squares a pixel has (53*8+1) x (37*8+1) points.
  CHECK(a.stats.primary > 54u * 38u);
  CHECK(a.stats.primary < 425u * 297u);
}
