// Spherical (latitude-longitude): film x is longitude, film y latitude, about the camera's
// frame; the directions POV-Ray 3.7's spherical camera gives (docs/povray-semantics.md).
#include "camera_checks.h"

#include "render/camera_frame.h"

#include <random>

using namespace lucent;
using namespace lucent::camtest;

namespace {

Camera spherical(double hAngle = 360.0, double vAngle = 180.0) {
  Camera c;
  c.type = CameraType::Spherical;
  c.hAngle = hAngle;
  c.vAngle = vAngle;
  return c;
}

// Pixel (i, j)'s centre.
Vec2 centre(int i, int j) { return Vec2(i + 0.5, j + 0.5); }

void checkDirection(const Vec3& d, const Vec3& expected, double margin = 1e-15) {
  INFO("got " << d.x << " " << d.y << " " << d.z << ", expected " << expected.x << " " << expected.y
              << " " << expected.z);
  CHECK(d.x == Approx(expected.x).margin(margin));
  CHECK(d.y == Approx(expected.y).margin(margin));
  CHECK(d.z == Approx(expected.z).margin(margin));
}

}  // namespace

TEST_CASE("spherical: the image centre looks forward, 3/4 of the width right, the top up",
          "[cameras][spherical]") {
  // The default camera looks down -z with +y up, so right is +x.
  auto p = makeProjection(spherical(), 16, 8);
  checkDirection(rayAt(*p, Vec2(8.0, 4.0)).d, Vec3(0.0, 0.0, -1.0));
  checkDirection(rayAt(*p, Vec2(12.0, 4.0)).d, Vec3(1.0, 0.0, 0.0));
  checkDirection(rayAt(*p, Vec2(4.0, 4.0)).d, Vec3(-1.0, 0.0, 0.0));
  // Both side edges look straight back, the top edge straight up, the bottom down.
  checkDirection(rayAt(*p, Vec2(0.0, 4.0)).d, Vec3(0.0, 0.0, 1.0));
  checkDirection(rayAt(*p, Vec2(16.0, 4.0)).d, Vec3(0.0, 0.0, 1.0));
  checkDirection(rayAt(*p, Vec2(3.0, 0.0)).d, Vec3(0.0, 1.0, 0.0));
  checkDirection(rayAt(*p, Vec2(11.0, 8.0)).d, Vec3(0.0, -1.0, 0.0));
}

TEST_CASE("spherical: pixel centres of a 16 x 8 image give POV-Ray's measured directions",
          "[cameras][spherical]") {
  // POV-Ray 3.7's default spherical camera on a 16 x 8 image (docs/povray-semantics.md,
  // read back from 16-bit renders): pixel (0, 0) looks along (-.0381, .9808, -.1913) with
  // direction +z, right +x, up +y. Lucent's camera with forward -z, right +x, up +y is that
  // frame with forward reversed, so the z components change sign.
  auto p = makeProjection(spherical(), 16, 8);
  checkDirection(rayAt(*p, centre(0, 0)).d, Vec3(-0.0381, 0.9808, 0.1913), 1e-4);
  checkDirection(rayAt(*p, centre(8, 0)).d, Vec3(0.0381, 0.9808, -0.1913), 1e-4);
  checkDirection(rayAt(*p, centre(0, 4)).d, Vec3(-0.1913, -0.1951, 0.9619), 1e-4);
  checkDirection(rayAt(*p, centre(8, 4)).d, Vec3(0.1913, -0.1951, -0.9619), 1e-4);
  // Exactly: pixel (0, 0) is at longitude -168.75 and latitude 78.75 degrees.
  const double lon = radians(-168.75), lat = radians(78.75);
  checkDirection(rayAt(*p, centre(0, 0)).d,
                 Vec3(std::cos(lat) * std::sin(lon), std::sin(lat), -std::cos(lat) * std::cos(lon)),
                 1e-15);
}

TEST_CASE("spherical: longitude and latitude are linear in film x and y for any angles",
          "[cameras][spherical]") {
  Camera cam = tiltedCamera(CameraType::Spherical);
  const CameraFrame f = makeCameraFrame(cam);
  const int w = 60, h = 35;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> ux(0.0, w), uy(0.0, h);
  for (auto [hAngle, vAngle] : {std::pair{360.0, 180.0}, {120.0, 60.0}, {200.0, 45.0}}) {
    cam.hAngle = hAngle;
    cam.vAngle = vAngle;
    auto p = makeProjection(cam, w, h);
    for (int n = 0; n < 500; ++n) {
      const Vec2 film(ux(rng), uy(rng));
      const Ray ray = rayAt(*p, film);
      CHECK(ray.o == f.origin);
      CHECK(glm::length(ray.d) == Approx(1.0).margin(1e-15));
      const double lon = radians(hAngle) * (film.x / w - 0.5);
      const double lat = radians(vAngle) * (0.5 - film.y / h);
      const Vec3 expected = std::cos(lat) * (std::cos(lon) * f.forward + std::sin(lon) * f.right) +
                            std::sin(lat) * f.up;
      CHECK(angleBetween(ray.d, expected) == Approx(0.0).margin(1e-14));
      // The latitude is the angle above the plane of forward and right.
      CHECK(std::asin(glm::dot(ray.d, f.up)) == Approx(lat).margin(1e-12));
    }
  }
}

TEST_CASE("spherical: the aspect ratio plays no part, and near/far bound every ray",
          "[cameras][spherical]") {
  Camera cam = spherical(90.0, 90.0);
  cam.near = 0.5;
  cam.far = 7.0;
  auto square = makeProjection(cam, 10, 10);
  auto wide = makeProjection(cam, 40, 10);
  // The same fraction of the width and height looks the same way.
  for (double u : {0.0, 0.3, 0.5, 0.9, 1.0})
    for (double v : {0.0, 0.25, 1.0}) {
      const Ray a = rayAt(*square, Vec2(10.0 * u, 10.0 * v));
      const Ray b = rayAt(*wide, Vec2(40.0 * u, 10.0 * v));
      CHECK(angleBetween(a.d, b.d) == Approx(0.0).margin(1e-15));
      CHECK(a.tmin == 0.5);
      CHECK(a.tmax == 7.0);
    }
  // The corner of a 90 x 90 image is 45 degrees to the left and 45 up.
  const Ray corner = rayAt(*square, Vec2(0.0, 0.0));
  const double c = std::cos(radians(45.0));
  checkDirection(corner.d, Vec3(-c * c, c, -c * c));
}
