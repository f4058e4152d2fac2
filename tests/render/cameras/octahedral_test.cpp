// Octahedral map: the whole sphere on a square image with no empty pixel; direction ->
// pixel -> direction round trips within one pixel; every direction has exactly one pixel.
#include "camera_checks.h"

#include "render/camera_frame.h"
#include "render/direction_maps.h"
#include "render/octahedral.h"

#include <random>
#include <vector>

using namespace lucent;
using namespace lucent::camtest;

namespace {

Vec3 randomDirection(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Vec3 d;
  do d = Vec3(g(rng), g(rng), g(rng));
  while (glm::length(d) < 1e-6);
  return glm::normalize(d);
}

}  // namespace

TEST_CASE("octahedral map: centre forward, edge midpoints right/up/left/down, corners back",
          "[cameras][octahedral]") {
  Camera cam = tiltedCamera(CameraType::Octahedral);
  const CameraFrame f = makeCameraFrame(cam);
  auto p = makeProjection(cam, 64, 64);
  CHECK(angleBetween(rayAt(*p, Vec2(32, 32)).d, f.forward) < 1e-15);
  CHECK(angleBetween(rayAt(*p, Vec2(64, 32)).d, f.right) < 1e-15);
  CHECK(angleBetween(rayAt(*p, Vec2(0, 32)).d, -f.right) < 1e-15);
  CHECK(angleBetween(rayAt(*p, Vec2(32, 0)).d, f.up) < 1e-15);
  CHECK(angleBetween(rayAt(*p, Vec2(32, 64)).d, -f.up) < 1e-15);
  for (const Vec2& corner : {Vec2(0, 0), Vec2(64, 0), Vec2(0, 64), Vec2(64, 64)})
    CHECK(angleBetween(rayAt(*p, corner).d, -f.forward) < 1e-15);
  // The inner diamond's edge is the equator (perpendicular to forward).
  CHECK(glm::dot(rayAt(*p, Vec2(48, 16)).d, f.forward) == Approx(0.0).margin(1e-15));
  // Mirror images across the square's edges meet: the map wraps around behind.
  CHECK(angleBetween(rayAt(*p, Vec2(10, 0)).d, rayAt(*p, Vec2(54, 0)).d) < 1e-15);
}

TEST_CASE("octahedral map covers the whole sphere with no empty pixel", "[cameras][octahedral]") {
  Camera cam = tiltedCamera(CameraType::Octahedral);
  const CameraFrame f = makeCameraFrame(cam);
  const int n = 32;
  auto p = makeProjection(cam, n, n);
  const auto& oct = as<OctahedralProjection>(p);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      for (const Vec2& at : {Vec2(0.5), Vec2(0.0), Vec2(0.999)}) CHECK(hasRay(*p, Vec2(i, j) + at));
  // Uniformly random directions reach every pixel (10^5 over 1024 pixels: about 100 each;
  // the octahedral map's largest pixel has 4.9 times the solid angle of its smallest).
  std::mt19937_64 rng(5);
  std::vector<int> hits(n * n, 0);
  for (int k = 0; k < 100000; ++k) {
    glm::ivec2 px = oct.pixel(randomDirection(rng));
    ++hits[px.y * n + px.x];
  }
  CHECK(*std::min_element(hits.begin(), hits.end()) > 20);
  (void)f;
}

TEST_CASE("octahedral direction -> pixel -> direction round trips within one pixel",
          "[cameras][octahedral]") {
  Camera cam = tiltedCamera(CameraType::Octahedral);
  const int n = 64;
  auto p = makeProjection(cam, n, n);
  const auto& oct = as<OctahedralProjection>(p);
  std::mt19937_64 rng(17);
  for (int k = 0; k < 100000; ++k) {
    Vec3 d = randomDirection(rng);
    Vec2 film = oct.filmPosition(d);
    glm::ivec2 px = oct.pixel(d);
    // The inverse is exact, and the pixel is the one whose square holds the film point.
    REQUIRE(angleBetween(oct.direction(film), d) < 1e-12);
    REQUIRE(px.x >= 0);
    REQUIRE(px.x < n);
    REQUIRE(px.y >= 0);
    REQUIRE(px.y < n);
    REQUIRE(film.x >= px.x);
    REQUIRE(film.x <= px.x + 1);
    REQUIRE(film.y >= px.y);
    REQUIRE(film.y <= px.y + 1);
    // Back to a direction through the pixel's centre: no farther from d than the pixel's
    // farthest corner (on a square image with an even size the map's creases run along
    // pixel edges and diagonals, so each pixel is one or two geodesic triangles).
    Vec3 centre = rayAt(*p, Vec2(px) + Vec2(0.5)).d;
    double reach = 0.0;
    for (const Vec2& c : {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1), Vec2(1, 1)})
      reach = std::max(reach, angleBetween(centre, rayAt(*p, Vec2(px) + c).d));
    REQUIRE(angleBetween(d, centre) <= reach * (1.0 + 1e-9));
    REQUIRE(reach < 3.0 * kPi / n);  // and a pixel is small: at most 3 pi / n across
  }
}

TEST_CASE("every direction lands on exactly one octahedral pixel", "[cameras][octahedral]") {
  Camera cam = tiltedCamera(CameraType::Octahedral);
  const CameraFrame f = makeCameraFrame(cam);
  const int n = 16;
  auto p = makeProjection(cam, n, n);
  const auto& oct = as<OctahedralProjection>(p);
  // Each pixel's centre direction maps back to that pixel, so no two pixels share one.
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      CHECK(oct.pixel(rayAt(*p, Vec2(i + 0.5, j + 0.5)).d) == glm::ivec2(i, j));
  // Directions on the map's seams and folds (axes, the equator, octant borders, signed
  // zeros) still land on one valid pixel.
  std::vector<Vec3> special;
  for (double x : {-1.0, -0.0, 0.0, 1.0})
    for (double y : {-1.0, -0.0, 0.0, 1.0})
      for (double z : {-1.0, -0.0, 0.0, 1.0})
        if (x != 0.0 || y != 0.0 || z != 0.0) special.push_back(Vec3(x, y, z));
  for (const Vec3& l : special) {
    Vec3 d = glm::normalize(f.toWorld(l));
    glm::ivec2 px = oct.pixel(d);
    CHECK((px.x >= 0 && px.x < n && px.y >= 0 && px.y < n));
    CHECK(angleBetween(oct.direction(oct.filmPosition(d)), d) < 1e-12);
  }
}

TEST_CASE("octahedral free functions invert each other on the unit square",
          "[cameras][octahedral]") {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 10000; ++k) {
    Vec2 uv(u(rng), u(rng));
    Vec2 back = octahedralUV(octahedralDirection(uv));
    CHECK(glm::length(back - uv) < 1e-12);
  }
}
