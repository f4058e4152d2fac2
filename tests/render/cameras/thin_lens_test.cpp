// Thin lens: the rays of one film point meet on the focus plane; a closed aperture is the
// pinhole; lens samples are stratified per pixel, so depth of field converges with samples.
#include "camera_checks.h"

#include "../scene_builder.h"
#include "render/camera_frame.h"
#include "render/renderer.h"
#include "render/sampling.h"
#include "render/thin_lens.h"

#include <random>
#include <set>
#include <vector>

using namespace lucent;
using namespace lucent::camtest;

TEST_CASE("thin lens: all rays of one film point meet at one point on the focus plane",
          "[cameras][thinlens]") {
  Camera cam = tiltedCamera(CameraType::ThinLens);
  cam.fov = 50.0;
  cam.focalLength = 0.2;
  cam.fStop = 1.4;
  const CameraFrame f = makeCameraFrame(cam);
  for (double focus : {0.0, 2.5, 40.0}) {
    cam.focusDistance = focus;
    const double fd = focus > 0.0 ? focus : f.lookDistance;  // 0 means position to look-at
    auto p = makeProjection(cam, 32, 24);
    CHECK(as<ThinLensProjection>(p).focusDistance() == fd);
    CHECK(as<ThinLensProjection>(p).apertureRadius() == Approx(0.2 / 1.4 / 2.0));
    auto pin = makeProjection(
        [&] {
          Camera c = cam;
          c.type = CameraType::Pinhole;
          return c;
        }(),
        32, 24);
    for (const Vec2& film : {Vec2(16, 12), Vec2(0.5, 0.5), Vec2(31.2, 20.7)}) {
      // Where the pinhole ray (through the lens centre) crosses the focus plane.
      Ray chief = rayAt(*pin, film);
      Vec3 target = chief.at(fd / glm::dot(chief.d, f.forward));
      double farthest = 0.0;
      for (int k = 0; k < 64; ++k) {
        Ray r = rayAt(*p, film, lensSample(3, 5, k, 64));
        double t = glm::dot(f.origin + fd * f.forward - r.o, f.forward) / glm::dot(r.d, f.forward);
        CHECK(glm::length(r.at(t) - target) < 1e-12 * (1.0 + fd));
        // The ray starts on the aperture disc, in the plane of the position.
        Vec3 offset = r.o - f.origin;
        CHECK(glm::dot(offset, f.forward) == Approx(0.0).margin(1e-15));
        CHECK(glm::length(offset) <= 0.2 / 1.4 / 2.0 * (1.0 + 1e-12));
        farthest = std::max(farthest, glm::length(offset));
      }
      CHECK(farthest > 0.8 * 0.2 / 1.4 / 2.0);  // the samples do spread over the aperture
    }
  }
}

TEST_CASE("thin lens with f-stop towards infinity is the pinhole camera", "[cameras][thinlens]") {
  Camera cam = tiltedCamera(CameraType::ThinLens);
  Camera pin = cam;
  pin.type = CameraType::Pinhole;
  auto ph = makeProjection(pin, 40, 30);
  cam.fStop = kInf;  // closed: a zero aperture
  auto closed = makeProjection(cam, 40, 30);
  cam.fStop = 1e9;
  auto tiny = makeProjection(cam, 40, 30);
  for (const Vec2& film : {Vec2(0, 0), Vec2(20, 15), Vec2(39.5, 3.25)})
    for (const Vec2& lens : {Vec2(0.0), Vec2(0.9, 0.1), Vec2(0.5)}) {
      Ray a = rayAt(*ph, film), b = rayAt(*closed, film, lens), c = rayAt(*tiny, film, lens);
      CHECK(b.o == a.o);
      CHECK(angleBetween(b.d, a.d) < 1e-15);
      CHECK(glm::length(c.o - a.o) < 1e-10);
      CHECK(angleBetween(c.d, a.d) < 1e-10);
    }
}

namespace {

// A small scene with objects in front of and behind the focus plane.
void depthScene(Scene& scene) {
  using namespace lucent::test;
  scene.render.width = 24;
  scene.render.height = 16;
  scene.render.samples = 16;
  scene.lights.push_back(pointLight(Vec3(2, 5, 4)));
  Material red;
  red.diffuse = Color(1.0f, 0.2f, 0.1f);
  Material checker;
  checker.diffuse = Color(1.0f);
  checker.texture = CheckerTexture{Color(1.0f), Color(0.1f), 0.5, {}};
  addShape(scene, SphereSpec{Vec3(-0.8, 0.5, 1.0), 0.5}, addMaterial(scene, red));
  addShape(scene, PlaneSpec{Vec3(0, 1, 0), 0.0}, addMaterial(scene, checker));
}

}  // namespace

TEST_CASE("thin lens render with a closed aperture equals the pinhole render",
          "[cameras][thinlens][render]") {
  using namespace lucent::test;
  Scene scene;
  depthScene(scene);
  Camera pin = lookingFrom(Vec3(0, 1.5, 5), Vec3(0, 0.3, 0), 45);
  Camera lens = pin;
  lens.type = CameraType::ThinLens;
  lens.focalLength = 0.5;
  lens.fStop = 1e12;
  World world(scene);
  Image a = Renderer(world, pin).render().image;
  Image b = Renderer(world, lens).render().image;
  double maxDiff = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    maxDiff = std::max(maxDiff, double(maxComponent(glm::abs(a.pixels[i] - b.pixels[i]))));
  CHECK(maxDiff < 1e-4);
  // An open aperture blurs the image: the same comparison then fails clearly.
  lens.fStop = 1.0;
  Image c = Renderer(world, lens).render().image;
  double openDiff = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    openDiff = std::max(openDiff, double(maxComponent(glm::abs(a.pixels[i] - c.pixels[i]))));
  CHECK(openDiff > 0.1);
}

TEST_CASE("lens samples of one pixel form a (0,m,2)-net, and pixels differ",
          "[cameras][thinlens][sampling]") {
  for (int m : {2, 4, 6, 8}) {
    const int count = 1 << m;
    for (int pixel = 0; pixel < 12; ++pixel) {
      std::vector<Vec2> pts;
      for (int k = 0; k < count; ++k) pts.push_back(lensSample(pixel, 2 * pixel + 1, k, count));
      // Every 2^a x 2^(m-a) grid has exactly one point per cell.
      for (int a = 0; a <= m; ++a) {
        std::vector<int> cells(count, 0);
        for (const Vec2& p : pts) {
          REQUIRE(p.x >= 0.0);
          REQUIRE(p.x < 1.0);
          REQUIRE(p.y >= 0.0);
          REQUIRE(p.y < 1.0);
          int i = static_cast<int>(p.x * (1 << a)), j = static_cast<int>(p.y * (1 << (m - a)));
          ++cells[i * (1 << (m - a)) + j];
        }
        CHECK(std::count(cells.begin(), cells.end(), 1) == count);
      }
    }
  }
  // Neighbouring pixels get different patterns and pairings; the same pixel the same.
  CHECK(lensSample(10, 10, 3, 16) != lensSample(11, 10, 3, 16));
  CHECK(lensSample(10, 10, 3, 16) != lensSample(10, 11, 3, 16));
  CHECK(lensSample(10, 10, 3, 16) == lensSample(10, 10, 3, 16));
  CHECK(lensSample(10, 10, 0, 1) == Vec2(0.5, 0.5));  // one sample: the lens centre
}

TEST_CASE("the pixel shuffle of lens samples is a permutation", "[cameras][thinlens][sampling]") {
  for (uint32_t count : {1u, 2u, 3u, 7u, 16u, 100u, 257u})
    for (uint32_t seed : {0u, 1u, 0xdeadbeefu, 123456789u}) {
      std::set<uint32_t> seen;
      for (uint32_t i = 0; i < count; ++i) seen.insert(permuteIndex(i, count, seed));
      CHECK(seen.size() == count);
      CHECK(*seen.rbegin() == count - 1);
    }
}

TEST_CASE("lens samples integrate the aperture much better than random sampling",
          "[cameras][thinlens][sampling]") {
  // The fraction of the aperture disc on one side of a line: what a pixel sees of an
  // out-of-focus edge. Exact: the disc area with x > c is (acos c - c sqrt(1 - c^2)) / pi.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto meanError = [&](int count) {
    double sum = 0.0;
    const int trials = 400;
    for (int t = 0; t < trials; ++t) {
      double angle = 2.0 * kPi * u(rng), c = 1.8 * u(rng) - 0.9;
      Vec2 normal(std::cos(angle), std::sin(angle));
      int inside = 0;
      for (int k = 0; k < count; ++k)
        inside += glm::dot(concentricDisc(lensSample(t % 23, t / 23, k, count)), normal) > c;
      double exact = (std::acos(c) - c * std::sqrt(1.0 - c * c)) / kPi;
      sum += std::abs(double(inside) / count - exact);
    }
    return sum / trials;
  };
  double e64 = meanError(64), e1024 = meanError(1024);
  // Independent random points: mean error about 0.8 sqrt(p(1-p)/n), 0.01 at n = 1024, and
  // 16 times the samples only quarter it. Stratified points do far better on both counts.
  CHECK(e1024 < 0.003);
  CHECK(e64 / e1024 > 5.0);
}

TEST_CASE("a thin-lens pixel converges to the analytic blur of an edge with samples",
          "[cameras][thinlens][render]") {
  using namespace lucent::test;
  // An emissive half-space x > 0 at depth 6, the lens focused at 2: the pixel next to the
  // edge sees the emitter through the part of the aperture with lens x < 1.5 P.x, where
  // P is the film point's focus-plane point (the ray from lens point L to P reaches depth
  // 6 at x = 3 P.x - 2 L.x).
  Scene scene;
  scene.render.width = 4;
  scene.render.height = 4;
  addShape(scene, BoxSpec{Vec3(0, -100, -7), Vec3(100, 100, -6)},
           addMaterial(scene, emissive(Color(1.0f))));
  Camera cam;
  cam.type = CameraType::ThinLens;
  cam.fov = 2.0 * std::atan(0.1) * 180.0 / kPi;  // image plane half width 0.1 at distance 1
  cam.focalLength = 1.0;
  cam.fStop = 2.0;  // aperture radius 0.25
  cam.focusDistance = 2.0;
  // Reference: the pixel (2, 1) spans film x in [2, 3], i.e. P.x = 2 * 0.1 * s, s in [0, 0.5].
  auto discLeftOf = [](double c) {  // fraction of the unit disc with x < c
    c = std::clamp(c, -1.0, 1.0);
    return 1.0 - (std::acos(c) - c * std::sqrt(1.0 - c * c)) / kPi;
  };
  double reference = 0.0;
  const int steps = 20000;
  for (int i = 0; i < steps; ++i) {
    double s = 0.5 * (i + 0.5) / steps;
    reference += discLeftOf(1.5 * 0.2 * s / 0.25) / steps;
  }
  auto pixelError = [&](int samples) {
    scene.render.samples = samples;
    World w(scene);
    Renderer renderer(w, cam);
    TraceContext context;
    return std::abs(double(renderer.renderPixel(2, 1, context).r) - reference);
  };
  double e16 = pixelError(16), e256 = pixelError(256), e4096 = pixelError(4096);
  CAPTURE(reference, e16, e256, e4096);
  CHECK(reference > 0.55);
  CHECK(reference < 0.75);
  CHECK(e256 < 0.01);
  CHECK(e4096 < 0.002);
  CHECK(e4096 < e16);
}
