// crand read by the scene reader and rendered: POV-Ray draws its grain from one random
// sequence per thread, Lucent from a hash of the point, so the pixels differ one by one,
// but the grain's mean and spread are POV-Ray's.
#include "pov_meaning_support.h"
#include "scene_read_support.h"

#include <cmath>

using namespace lucent;
using namespace lucent::test;

namespace {

// A wall facing the camera, lit from the camera: without crand every pixel is about
// 0.8 · 0.6 = 0.48; crand 0.3 takes u · 0.3 · 0.8 off, u uniform in [0, 1): mean 0.12,
// spread 0.24/√12 ≈ 0.069.
const char* kScene = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> look_at 0 right x*4/3 angle 30 }
light_source { <0, 0, -1000> color rgb 1 }
plane { z, 0 pigment { color rgb 0.8 } finish { ambient 0 diffuse 0.6 crand 0.3 } }
)";

struct Grain {
  double mean = 0.0, spread = 0.0;
};

Grain grainOf(const RgbImage& image) {
  double sum = 0.0, squares = 0.0;
  const size_t n = image.rgb.size() / 3;
  for (size_t p = 0; p < n; ++p) {
    const double v = image.rgb[p * 3];  // red; the grain is grey
    sum += v;
    squares += v * v;
  }
  Grain g;
  g.mean = sum / n;
  g.spread = std::sqrt(std::max(0.0, squares / n - g.mean * g.mean));
  return g;
}

}  // namespace

TEST_CASE("crand is imported as a share of Lucent's diffuse", "[sdl][finish][crand]") {
  auto r = sdltest::readScene(kScene);
  REQUIRE(r->load.scene);
  const Material& wall = sdltest::materialOf(*r->load.scene, 0);
  // POV-Ray's crand 0.3 with diffuse 0.6 and an opaque pigment: 0.3 / 0.6 of k_d.
  CHECK(wall.crand == Approx(0.5));
  CHECK(r->out.warnings.empty());
}

TEST_CASE("crand gives POV-Ray's grain: its mean and its spread",
          "[sdl][finish][crand][image][povray]") {
  auto r = sdltest::readScene(kScene);
  REQUIRE(r->load.scene);
  r->load.scene->render.width = 80;
  r->load.scene->render.height = 60;
  const Grain lucent = grainOf(renderWithLucent(*r->load.scene));
  const Grain povray = grainOf(renderWithPovray(kScene, 80, 60));
  INFO("Lucent " << lucent.mean << " ± " << lucent.spread << ", POV-Ray " << povray.mean << " ± "
                 << povray.spread);
  // 4800 pixels: the means agree to a few thousandths, the spreads to a few per cent.
  CHECK(lucent.mean == Approx(povray.mean).margin(0.005));
  CHECK(lucent.spread == Approx(povray.spread).epsilon(0.05));
  // And both are the grain the formula gives (the light is nearly head-on everywhere).
  CHECK(povray.mean == Approx(0.48 - 0.12).margin(0.01));
  CHECK(povray.spread == Approx(0.24 / std::sqrt(12.0)).epsilon(0.05));
}
