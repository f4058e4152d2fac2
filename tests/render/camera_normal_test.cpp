// The camera's normal (POV-Ray's camera { normal { } }): primary ray directions at chosen
// pixels against the rule written out here: the unbent direction from the camera's own
// formula, bent by one wave source (POV-Ray's waves normal, normal.cpp) at the image
// point (x0, y0, 0) carried into the normal's space (tracepixel.cpp, CreateCameraRay).
#include "render/camera_normal.h"
#include "primitives/noise.h"
#include "render/projection.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>

using namespace lucent;

namespace {

// The normal of these tests: waves from one source, depth 0.375, frequency 3, placed by
// scale(0.5 1 1) (its pattern space is the image's stretched twice along x).
NormalSpec oneWave() {
  NormalSpec n;
  n.pattern.type = PatternType::waves;
  n.pattern.frequency = 3.0;
  n.pattern.waveSources = 1;
  n.pattern.placement.patternFromObject = Mat4(1.0);
  n.pattern.placement.patternFromObject[0][0] = 2.0;
  n.depth = 0.375;
  return n;
}

// POV-Ray's first wave source and its frequency (texture.cpp, Initialize_Waves).
Vec3 sourceAt() { return glm::normalize(dnoise(Vec3(0.0))); }
double sourceFrequency() {
  const int32_t next = static_cast<int32_t>(-560851967LL * 1812433253LL + 12345LL);
  return ((next >> 16) & 0x7FFF) * 0.000030518509476 + 0.01;
}

// `d` bent at the image point (x0, y0): into the normal's space by the inverse transpose of
// diag(2, 1, 1), pushed along q − s by the wave, back by diag(2, 1, 1)'s transpose.
Vec3 bent(const Vec3& d, double x0, double y0) {
  const Vec3 q(2.0 * x0, y0, 0.0);
  Vec3 n = glm::normalize(Vec3(0.5 * d.x, d.y, d.z));
  const Vec3 toQ = q - sourceAt();
  const double l = glm::length(toQ), f = sourceFrequency();
  const double v = l * 3.0 * f;
  n += std::sin(2.0 * kPi * (v - std::floor(v))) * 0.375 / f / l * toQ;
  return glm::normalize(Vec3(2.0 * n.x, n.y, n.z));
}

Vec3 direction(const Projection& p, double x, double y) {
  Ray r;
  REQUIRE(p.generateRay(Vec2(x, y), Vec2(0.5), r));
  return r.d;
}

void checkNear(const Vec3& a, const Vec3& b) {
  for (int k = 0; k < 3; ++k) CHECK(a[k] == Approx(b[k]).margin(1e-12));
}

const Vec2 kFilm[] = {Vec2(0.5, 0.5), Vec2(17.5, 9.5), Vec2(39.5, 29.5), Vec2(12.25, 20.75)};

}  // namespace

TEST_CASE("camera normal bends a pinhole camera's rays at the image point", "[render][camera]") {
  Camera cam;
  cam.fov = 60.0;
  cam.normal = oneWave();
  const auto p = makeProjection(cam, 40, 30);
  const double w = 2.0 * std::tan(radians(30.0)), h = w * 30.0 / 40.0;
  for (const Vec2& film : kFilm) {
    const double x0 = film.x / 40.0 - 0.5, y0 = 0.5 - film.y / 30.0;
    const Vec3 unbent = glm::normalize(Vec3(x0 * w, y0 * h, -1.0));
    INFO("film " << film.x << " " << film.y);
    checkNear(direction(*p, film.x, film.y), bent(unbent, x0, y0));
  }
}

TEST_CASE("camera normal bends an orthographic camera's one direction per image point",
          "[render][camera]") {
  Camera cam;
  cam.type = CameraType::Orthographic;
  cam.normal = oneWave();
  const auto p = makeProjection(cam, 40, 30);
  for (const Vec2& film : kFilm) {
    const double x0 = film.x / 40.0 - 0.5, y0 = 0.5 - film.y / 30.0;
    INFO("film " << film.x << " " << film.y);
    checkNear(direction(*p, film.x, film.y), bent(Vec3(0, 0, -1), x0, y0));
  }
}

TEST_CASE("camera normal's image point follows POV-Ray's camera types", "[render][camera]") {
  const CameraFrame frame = makeCameraFrame(Camera{});
  Camera spherical;
  spherical.type = CameraType::Spherical;
  spherical.hAngle = 180.0;
  spherical.vAngle = 90.0;
  // (x0, y0) scaled to the longitude and latitude, in radians.
  const Vec3 s = cameraNormalPoint(spherical, frame, Vec2(30, 10), Vec3(0, 0, -1), 40, 40);
  CHECK(s.x == Approx(0.25 * kPi));        // x0 = 1/4 of 180 degrees
  CHECK(s.y == Approx(0.25 * kPi * 0.5));  // y0 = 1/4 of 90 degrees
  CHECK(s.z == 0.0);
  Camera panoramic;
  panoramic.type = CameraType::Panoramic;
  const Vec3 pan = cameraNormalPoint(panoramic, frame, Vec2(10, 10), Vec3(0, 0, -1), 40, 40);
  CHECK(pan.x == Approx(0.75 * kPi));  // (1 − x/width)·π
  CHECK(pan.y == Approx(0.25 * kPi));  // (1 − 2y/height)·π/2
  // Fisheye: the angle about the view (POV-Ray's asin(y/r) right of the centre, π − asin
  // on the left) and the angle from it.
  Camera fisheye;
  fisheye.type = CameraType::Fisheye;
  const Vec3 up = glm::normalize(Vec3(0.0, std::sin(0.3), -std::cos(0.3)));
  const Vec3 f1 = cameraNormalPoint(fisheye, frame, Vec2(20, 5), up, 40, 40);
  CHECK(f1.x == Approx(0.5 * kPi));
  CHECK(f1.y == Approx(0.3));
  const Vec3 leftDown = glm::normalize(Vec3(-0.2, -0.1, -1.0));
  const Vec3 f2 = cameraNormalPoint(fisheye, frame, Vec2(5, 30), leftDown, 40, 40);
  CHECK(f2.x == Approx(kPi - std::asin(-0.1 / std::sqrt(0.05))));
  CHECK(f2.y == Approx(std::acos(1.0 / std::sqrt(1.05))));
  // Lucent's own types: the image point.
  Camera panini;
  panini.type = CameraType::Panini;
  const Vec3 pn = cameraNormalPoint(panini, frame, Vec2(30, 10), Vec3(0, 0, -1), 40, 40);
  CHECK(pn.x == Approx(0.25));
  CHECK(pn.y == Approx(0.25));
}

TEST_CASE("a camera without a normal keeps its rays", "[render][camera]") {
  Camera plain, bumped;
  bumped.normal = oneWave();
  const auto a = makeProjection(plain, 40, 30), b = makeProjection(bumped, 40, 30);
  // The bend is not nothing: it moves the ray by more than a thousandth of a radian.
  const Vec3 da = direction(*a, 17.5, 9.5), db = direction(*b, 17.5, 9.5);
  CHECK(std::acos(glm::dot(da, db)) > 1e-3);
}
