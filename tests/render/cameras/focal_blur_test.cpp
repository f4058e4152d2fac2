// Focal blur (POV-Ray's): the rays of one film point start on the lens disc and meet where
// the unmoved ray meets the focus surface; the sampler averages them and stops by POV-Ray's
// confidence test, whose thresholds are the chi-square quantiles.
#include "camera_checks.h"

#include "../scene_builder.h"
#include "render/camera_frame.h"
#include "render/focal_blur.h"
#include "render/renderer.h"
#include "scenegraph/located_error.h"

#include <set>
#include <vector>

using namespace lucent;
using namespace lucent::camtest;

namespace {

Camera blurred(CameraType type, double aperture, std::optional<Vec3> focalPoint) {
  Camera cam = tiltedCamera(type);
  cam.fov = 50.0;
  Camera::FocalBlur blur;
  blur.aperture = aperture;
  blur.focalPoint = focalPoint;
  cam.focalBlur = blur;
  return cam;
}

Camera unblurred(Camera cam) {
  cam.focalBlur.reset();
  return cam;
}

// Lens points over the unit square: a 9 x 9 grid, corners and centre included.
std::vector<Vec2> lensGrid() {
  std::vector<Vec2> points;
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) points.emplace_back(i / 8.0 * 0.999, j / 8.0 * 0.999);
  return points;
}

}  // namespace

TEST_CASE(
    "focal blur: a pinhole's rays of one film point meet on the plane through the focal point",
    "[cameras][focal-blur]") {
  const Vec3 focal(-3.0, 0.0, -6.0);
  const Camera cam = blurred(CameraType::Pinhole, 0.6, focal);
  const CameraFrame f = makeCameraFrame(cam);
  // The plane through the focal point, square to the view.
  const double focus = glm::dot(focal - f.origin, f.forward);
  auto blur = makeProjection(cam, 32, 24);
  auto pin = makeProjection(unblurred(cam), 32, 24);
  for (const Vec2& film : {Vec2(16, 12), Vec2(0.5, 0.5), Vec2(31.2, 20.7)}) {
    const Ray chief = rayAt(*pin, film);
    const Vec3 target = chief.at(focus / glm::dot(chief.d, f.forward));
    // The lens centre is the unmoved ray.
    const Ray centre = rayAt(*blur, film);
    CHECK(glm::length(centre.o - chief.o) < 1e-15);
    CHECK(glm::length(centre.d - chief.d) < 1e-12);
    double farthest = 0.0;
    for (const Vec2& lens : lensGrid()) {
      const Ray r = rayAt(*blur, film, lens);
      CHECK(glm::length(r.d) == Approx(1.0).epsilon(1e-14));
      const double t =
          glm::dot(f.origin + focus * f.forward - r.o, f.forward) / glm::dot(r.d, f.forward);
      CHECK(glm::length(r.at(t) - target) < 1e-12 * focus);
      // The start lies on the lens disc (diameter = aperture) in the camera's right-up plane.
      const Vec3 offset = r.o - f.origin;
      CHECK(glm::dot(offset, f.forward) == Approx(0.0).margin(1e-15));
      CHECK(glm::length(offset) <= 0.3 * (1.0 + 1e-12));
      farthest = std::max(farthest, glm::length(offset));
    }
    CHECK(farthest > 0.99 * 0.3);  // the grid's corners reach the rim
  }
}

TEST_CASE("focal blur: without a focal point the look-at plane is in focus",
          "[cameras][focal-blur]") {
  const Camera cam = blurred(CameraType::Pinhole, 1.0, std::nullopt);
  const CameraFrame f = makeCameraFrame(cam);
  auto blur = makeProjection(cam, 20, 20);
  // The look-at point is seen at the image centre through every lens point.
  for (const Vec2& lens : lensGrid()) {
    const Ray r = rayAt(*blur, Vec2(10, 10), lens);
    const Vec3 toLookAt = cam.lookAt - r.o;
    CHECK(glm::length(glm::cross(toLookAt, r.d)) < 1e-12 * f.lookDistance);
  }
}

TEST_CASE("focal blur: an orthographic camera focuses on a plane and a fisheye on a sphere",
          "[cameras][focal-blur]") {
  const Vec3 focal(-2.0, 1.0, -2.0);
  SECTION("orthographic") {
    Camera cam = blurred(CameraType::Orthographic, 0.4, focal);
    cam.width = 3.0;
    const CameraFrame f = makeCameraFrame(cam);
    const double focus = glm::dot(focal - f.origin, f.forward);
    auto blur = makeProjection(cam, 16, 12);
    auto plain = makeProjection(unblurred(cam), 16, 12);
    for (const Vec2& film : {Vec2(1, 1), Vec2(8, 6), Vec2(15.5, 2)}) {
      const Ray chief = rayAt(*plain, film);
      const Vec3 target = chief.at(focus);
      for (const Vec2& lens : lensGrid()) {
        const Ray r = rayAt(*blur, film, lens);
        const double t = glm::dot(target - r.o, f.forward) / glm::dot(r.d, f.forward);
        CHECK(glm::length(r.at(t) - target) < 1e-12 * focus);
        CHECK(glm::length(r.o - chief.o) <= 0.2 * (1.0 + 1e-12));
      }
    }
  }
  SECTION("fisheye") {
    Camera cam = blurred(CameraType::Fisheye, 0.4, focal);
    cam.fov = 180.0;
    const CameraFrame f = makeCameraFrame(cam);
    const double radius = glm::length(focal - f.origin);
    auto blur = makeProjection(cam, 16, 16);
    auto plain = makeProjection(unblurred(cam), 16, 16);
    for (const Vec2& film : {Vec2(8, 8), Vec2(2, 8), Vec2(8, 14)}) {
      const Vec3 target = rayAt(*plain, film).at(radius);
      for (const Vec2& lens : lensGrid()) {
        const Ray r = rayAt(*blur, film, lens);
        // The ray passes through the target at distance ~radius from its start.
        CHECK(glm::length(glm::cross(target - r.o, r.d)) < 1e-12 * radius);
        CHECK(glm::dot(target - r.o, r.d) > 0.0);
      }
    }
  }
}

TEST_CASE("focal blur: a focal point behind the camera is an error at the focal blur",
          "[cameras][focal-blur]") {
  Camera cam = blurred(CameraType::Pinhole, 0.5, Vec3(10.0, 5.0, 20.0));  // behind
  cam.focalBlur->loc = SourceLoc{"scene.xml", 7, 5};
  try {
    makeProjection(cam, 8, 8);
    FAIL("no error");
  } catch (const LocatedError& e) {
    CHECK(e.loc().line == 7);
    CHECK_THAT(e.message(), Catch::Contains("in front of the camera"));
  }
  Camera fish = blurred(CameraType::Fisheye, 0.5, tiltedCamera(CameraType::Fisheye).position);
  CHECK_THROWS_AS(makeProjection(fish, 8, 8), LocatedError);
}

TEST_CASE("focal blur: the confidence thresholds are POV-Ray's chi-square quantiles",
          "[cameras][focal-blur]") {
  Camera::FocalBlur blur;
  blur.samples = 11;
  blur.confidence = 0.9;
  blur.variance = 0.01;
  const FocalBlurSampler s(blur);
  // The value a chi-square variable exceeds with probability 0.9 (its 10th percentile),
  // from the standard tables: 1 degree 0.01579, 2: 0.2107, 10: 4.865.
  CHECK(s.threshold(10) == Approx(0.01).epsilon(1e-12));  // n = samples - 1
  CHECK(s.threshold(1) == Approx(0.01 * 0.01579 / 4.865).epsilon(1e-3));
  CHECK(s.threshold(2) == Approx(0.01 * 0.2107 / 4.865).epsilon(1e-3));
  for (int n = 2; n <= 11; ++n) CHECK(s.threshold(n) > s.threshold(n - 1));
  blur.samples = 1;
  CHECK(FocalBlurSampler(blur).threshold(1) == 0.0);
}

TEST_CASE("focal blur: the sampler stops when the mean is good enough, never before min-samples",
          "[cameras][focal-blur]") {
  Camera::FocalBlur blur;
  blur.samples = 37;
  int calls = 0;
  std::set<int> indices;
  const auto constant = [&](const Vec2&, const Vec2&, int index) {
    ++calls;
    indices.insert(index);
    return Color(0.25f, 0.5f, 0.75f);
  };
  SECTION("one colour: the first four rays settle it") {
    const Color c = FocalBlurSampler(blur).average(Vec2(3.5, 4.5), 1, constant);
    CHECK(calls == 4);
    CHECK(c == Color(0.25f, 0.5f, 0.75f));
    CHECK(indices == std::set<int>{0, 1, 2, 3});
  }
  SECTION("min-samples 10: the test waits for the fourth ray after it") {
    blur.minSamples = 10;
    FocalBlurSampler(blur).average(Vec2(3.5, 4.5), 1, constant);
    CHECK(calls == 12);
  }
  SECTION("variance 0: every ray is taken") {
    blur.variance = 0.0;
    FocalBlurSampler(blur).average(Vec2(3.5, 4.5), 1, constant);
    CHECK(calls == 37);
  }
  SECTION("black and white: every ray is taken, and the mean is theirs") {
    double sum = 0.0;
    const auto noisy = [&](const Vec2&, const Vec2&, int index) {
      ++calls;
      const float v = index % 2 == 0 ? 1.0f : 0.0f;
      sum += v;
      return Color(v);
    };
    const Color c = FocalBlurSampler(blur).average(Vec2(3.5, 4.5), 1, noisy);
    CHECK(calls == 37);
    CHECK(c.x == Approx(sum / 37.0));
  }
}

TEST_CASE("focal blur: film offsets span the pixel about the centre and lens points are stratified",
          "[cameras][focal-blur]") {
  Camera::FocalBlur blur;
  blur.samples = 64;
  blur.variance = 0.0;
  std::vector<Vec2> films, lenses;
  const auto record = [&](const Vec2& film, const Vec2& lens, int) {
    films.push_back(film);
    lenses.push_back(lens);
    return Color(0.0f);
  };
  const FocalBlurSampler sampler(blur);
  sampler.average(Vec2(10.5, 20.5), 42, record);
  REQUIRE(films.size() == 64);
  Vec2 mean(0.0);
  for (const Vec2& f : films) {
    CHECK(f.x >= 10.0);
    CHECK(f.x < 11.0);
    CHECK(f.y >= 20.0);
    CHECK(f.y < 21.0);
    mean += f / 64.0;
  }
  CHECK(mean.x == Approx(10.5).margin(0.05));
  CHECK(mean.y == Approx(20.5).margin(0.05));
  // The first 4 lens points: one in each quarter; the first 64: one in each cell of 8 x 8.
  std::set<int> quarters, cells;
  for (int k = 0; k < 4; ++k) quarters.insert(int(lenses[k].x * 2) * 2 + int(lenses[k].y * 2));
  for (const Vec2& l : lenses) cells.insert(int(l.x * 8) * 8 + int(l.y * 8));
  CHECK(quarters.size() == 4);
  CHECK(cells.size() == 64);
  // The same seed gives the same rays; another seed others.
  std::vector<Vec2> first = lenses;
  lenses.clear();
  sampler.average(Vec2(10.5, 20.5), 42, record);
  CHECK(std::equal(first.begin(), first.end(), lenses.begin() + 0));
  lenses.clear();
  sampler.average(Vec2(10.5, 20.5), 43, record);
  CHECK(lenses[0] != first[0]);
}

TEST_CASE("focal blur: a ball on the focus plane stays sharp, one off it spreads by the lens",
          "[cameras][focal-blur][render]") {
  using namespace lucent::test;
  // A white ball 0.3 across, alone on black, at distance 5 (in focus) or 2.5, seen by a
  // 64 x 64 pinhole camera with an aperture of 0.8.
  const auto render = [](double ballDistance, bool withBlur) {
    Scene scene;
    scene.render.width = 64;
    scene.render.height = 64;
    addShape(scene, SphereSpec{Vec3(0.0, 0.0, -ballDistance), 0.15},
             addMaterial(scene, emissive(Color(1.0f))));
    Camera cam = lookingFrom(Vec3(0.0), Vec3(0.0, 0.0, -5.0), 20.0);
    if (withBlur) {
      Camera::FocalBlur blur;
      blur.aperture = 0.8;
      blur.samples = 64;
      blur.variance = 0.0;
      cam.focalBlur = blur;
    }
    World world(scene);
    return Renderer(world, cam).render().image;
  };
  const auto lit = [](const Image& img) {  // pixels brighter than half: the ball's disc
    int n = 0;
    for (const Color& c : img.pixels) n += c.x > 0.5f ? 1 : 0;
    return n;
  };
  const auto light = [](const Image& img) {
    double s = 0.0;
    for (const Color& c : img.pixels) s += c.x;
    return s;
  };
  const Image sharp = render(5.0, false), focused = render(5.0, true);
  const Image nearSharp = render(2.5, false), nearBlurred = render(2.5, true);
  // In focus: the same disc (the blur only anti-aliases its rim).
  CHECK(std::abs(lit(focused) - lit(sharp)) <= 0.15 * lit(sharp));
  CHECK(light(focused) == Approx(light(sharp)).epsilon(0.1));
  // Off the plane the light spreads but is not lost: the rays of the central pixel cross
  // distance 2.5 on a disc aperture × (5 − 2.5) / 5 = 0.4 across, wider than the ball
  // (0.3), so only about (0.3 / 0.4)^2 of them meet it.
  CHECK(light(nearBlurred) == Approx(light(nearSharp)).epsilon(0.1));
  CHECK(nearSharp.at(32, 32).x > 0.99f);
  CHECK(nearBlurred.at(32, 32).x == Approx(0.5625).margin(0.12));
  int wider = 0;
  for (size_t i = 0; i < nearSharp.pixels.size(); ++i)
    if (nearBlurred.pixels[i].x > 0.02f && nearSharp.pixels[i].x == 0.0f) ++wider;
  CHECK(wider > 50);
}
