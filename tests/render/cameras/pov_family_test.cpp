// POV-Ray 3.7's ultra_wide_angle, cylinder 1-4, panoramic and omnimax cameras: directions
// at chosen film points, worked out by hand from the cameras' documented geometry (the
// numbers below are written out, not computed by the projection's own formulas).
#include "camera_checks.h"

#include "render/camera_frame.h"

#include <cmath>

using namespace lucent;
using namespace lucent::camtest;

namespace {

Camera of(CameraType type) {
  Camera c;  // at the origin, looking down -z, +y up: right is +x
  c.type = type;
  return c;
}

void checkDirection(const Vec3& d, const Vec3& expected, double margin = 1e-14) {
  INFO("got " << d.x << " " << d.y << " " << d.z << ", expected " << expected.x << " " << expected.y
              << " " << expected.z);
  CHECK(d.x == Approx(expected.x).margin(margin));
  CHECK(d.y == Approx(expected.y).margin(margin));
  CHECK(d.z == Approx(expected.z).margin(margin));
}

void checkPoint(const Vec3& p, const Vec3& expected) { checkDirection(p, expected, 1e-13); }

const double kRoot2 = std::sqrt(0.5);  // cos 45 = sin 45

}  // namespace

TEST_CASE("ultra-wide-angle: angles grow evenly along each axis, up to looking back",
          "[cameras][ultra-wide-angle]") {
  Camera c = of(CameraType::UltraWideAngle);
  c.fov = 180.0;  // 90 degrees each side across; the 200 x 100 image: 90 degrees down
  auto p = makeProjection(c, 200, 100);
  checkDirection(rayAt(*p, Vec2(100.0, 50.0)).d, Vec3(0.0, 0.0, -1.0));
  checkDirection(rayAt(*p, Vec2(200.0, 50.0)).d, Vec3(1.0, 0.0, 0.0));
  checkDirection(rayAt(*p, Vec2(0.0, 50.0)).d, Vec3(-1.0, 0.0, 0.0));
  // A quarter of the width: 45 degrees to the right.
  checkDirection(rayAt(*p, Vec2(150.0, 50.0)).d, Vec3(kRoot2, 0.0, -kRoot2));
  // The top edge: 45 degrees up.
  checkDirection(rayAt(*p, Vec2(100.0, 0.0)).d, Vec3(0.0, kRoot2, -kRoot2));
  // The top right corner: x = 90, y = 45 degrees: (sin 90, sin 45, cos 90 cos 45) = (1,
  // 0.7071, 0), normalised (sqrt(2/3), sqrt(1/3), 0).
  checkDirection(rayAt(*p, Vec2(200.0, 0.0)).d,
                 Vec3(std::sqrt(2.0 / 3.0), std::sqrt(1.0 / 3.0), 0.0));

  // 360 across: the side edges look straight back; fov-axis vertical: fov spans the height.
  c.fov = 360.0;
  p = makeProjection(c, 200, 100);
  checkDirection(rayAt(*p, Vec2(200.0, 50.0)).d, Vec3(0.0, 0.0, 1.0));
  c.fov = 90.0;
  c.fovAxis = FovAxis::Vertical;  // 45 down the half-height, 90 across the half-width
  p = makeProjection(c, 200, 100);
  checkDirection(rayAt(*p, Vec2(100.0, 100.0)).d, Vec3(0.0, -kRoot2, -kRoot2));
  checkDirection(rayAt(*p, Vec2(200.0, 50.0)).d, Vec3(1.0, 0.0, 0.0));
  // frame-aspect 1 on the same image: 90 degrees down, 90 across (the pixels not square).
  c.frameAspect = 1.0;
  p = makeProjection(c, 200, 100);
  checkDirection(rayAt(*p, Vec2(200.0, 50.0)).d, Vec3(kRoot2, 0.0, -kRoot2));
  // Diagonal: the 4:3 map's diagonal of 100 degrees is 80 across and 60 down.
  c.frameAspect = 0.0;
  c.fovAxis = FovAxis::Diagonal;
  c.fov = 100.0;
  p = makeProjection(c, 400, 300);
  checkDirection(rayAt(*p, Vec2(200.0, 0.0)).d, Vec3(0.0, 0.5, -std::sqrt(0.75)));
}

TEST_CASE("cylinder 1 and 2: the angle about up or right, the axis-length along it",
          "[cameras][cylinder]") {
  Camera c = of(CameraType::Cylinder);
  c.sweep = 180.0;
  c.axisLength = 2.0;  // the image's height on the unit cylinder
  auto p = makeProjection(c, 200, 100);
  checkDirection(rayAt(*p, Vec2(100.0, 50.0)).d, Vec3(0.0, 0.0, -1.0));
  checkDirection(rayAt(*p, Vec2(200.0, 50.0)).d, Vec3(1.0, 0.0, 0.0));
  // The top of the centre column: 1 unit up at distance 1, 45 degrees.
  checkDirection(rayAt(*p, Vec2(100.0, 0.0)).d, Vec3(0.0, kRoot2, -kRoot2));
  // A quarter of the width to the left and the bottom: (-sin 45, -1, -cos 45) / sqrt(2).
  checkDirection(rayAt(*p, Vec2(50.0, 100.0)).d, Vec3(-0.5, -kRoot2, -0.5));
  checkPoint(rayAt(*p, Vec2(50.0, 100.0)).o, Vec3(0.0));

  // Type 2: the axis along right, 180 degrees down the height, 2 units across.
  c.cylinderType = 2;
  p = makeProjection(c, 200, 100);
  checkDirection(rayAt(*p, Vec2(100.0, 0.0)).d, Vec3(0.0, 1.0, 0.0));
  checkDirection(rayAt(*p, Vec2(200.0, 50.0)).d, Vec3(kRoot2, 0.0, -kRoot2));
  checkDirection(rayAt(*p, Vec2(100.0, 75.0)).d, Vec3(0.0, -kRoot2, -kRoot2));

  // axis-length 0: square pixels at the centre. Type 1, 90 degrees across 200 pixels:
  // pi/2 * 100/200 = pi/4 high, so the top centre is pi/8 up at distance 1.
  c.cylinderType = 1;
  c.sweep = 90.0;
  c.axisLength = 0.0;
  p = makeProjection(c, 200, 100);
  const double rise = kPi / 8.0;
  checkDirection(rayAt(*p, Vec2(100.0, 0.0)).d,
                 Vec3(0.0, rise, -1.0) / std::sqrt(1.0 + rise * rise));
}

TEST_CASE("cylinder 3 and 4: the rays start along the axis, parallel along it",
          "[cameras][cylinder]") {
  Camera c = of(CameraType::Cylinder);
  c.position = Vec3(1.0, 2.0, 3.0);
  c.lookAt = Vec3(1.0, 2.0, 2.0);
  c.cylinderType = 3;
  c.sweep = 120.0;
  c.axisLength = 4.0;
  auto p = makeProjection(c, 120, 80);
  // The top row starts 2 units up; the right edge looks 60 degrees right.
  Ray r = rayAt(*p, Vec2(120.0, 0.0));
  checkPoint(r.o, Vec3(1.0, 4.0, 3.0));
  checkDirection(r.d, Vec3(std::sqrt(0.75), 0.0, -0.5));
  r = rayAt(*p, Vec2(60.0, 60.0));  // a quarter of the height below the centre: 1 unit down
  checkPoint(r.o, Vec3(1.0, 1.0, 3.0));
  checkDirection(r.d, Vec3(0.0, 0.0, -1.0));

  c.cylinderType = 4;  // 120 degrees down the height, 4 units across
  p = makeProjection(c, 120, 80);
  r = rayAt(*p, Vec2(0.0, 0.0));
  checkPoint(r.o, Vec3(-1.0, 2.0, 3.0));
  checkDirection(r.d, Vec3(0.0, std::sqrt(0.75), -0.5));
  // Mirrored: the left edge starts on the other side.
  c.mirror = true;
  p = makeProjection(c, 120, 80);
  checkPoint(rayAt(*p, Vec2(0.0, 40.0)).o, Vec3(3.0, 2.0, 3.0));
}

TEST_CASE("panoramic: 180 degrees across, tan(latitude) up, right and up lengths",
          "[cameras][panoramic]") {
  Camera c = of(CameraType::Panoramic);
  auto p = makeProjection(c, 200, 100);
  checkDirection(rayAt(*p, Vec2(100.0, 50.0)).d, Vec3(0.0, 0.0, -1.0));
  checkDirection(rayAt(*p, Vec2(0.0, 50.0)).d, Vec3(-1.0, 0.0, 0.0));
  checkDirection(rayAt(*p, Vec2(200.0, 50.0)).d, Vec3(1.0, 0.0, 0.0));
  // 3/4 of the width: longitude 45 degrees. A quarter of the height up: latitude 45
  // degrees, tan 1: the centre column's ray 45 degrees up.
  checkDirection(rayAt(*p, Vec2(150.0, 50.0)).d, Vec3(kRoot2, 0.0, -kRoot2));
  checkDirection(rayAt(*p, Vec2(100.0, 25.0)).d, Vec3(0.0, kRoot2, -kRoot2));
  // The top row looks straight up, the bottom row down.
  checkDirection(rayAt(*p, Vec2(30.0, 0.0)).d, Vec3(0.0, 1.0, 0.0));
  checkDirection(rayAt(*p, Vec2(170.0, 100.0)).d, Vec3(0.0, -1.0, 0.0));
  // Lengths: right 2 at longitude 45: (2 cos 45, 0, sin 45) -> (2, 0, 1)/sqrt(5); up 0.5 at
  // latitude 45: (0, 0.5, 1)/sqrt(1.25).
  c.rightLength = 2.0;
  c.upLength = 0.5;
  p = makeProjection(c, 200, 100);
  checkDirection(rayAt(*p, Vec2(150.0, 50.0)).d, Vec3(2.0, 0.0, -1.0) / std::sqrt(5.0));
  checkDirection(rayAt(*p, Vec2(100.0, 25.0)).d, Vec3(0.0, 0.5, -1.0) / std::sqrt(1.25));
}

TEST_CASE("omnimax: the lens's angle polynomial, the frame rule, the missing pixels",
          "[cameras][omnimax]") {
  // theta(r) = 1.411269 r - 0.09439 r^3 + 0.25674 r^5; theta(1) = 1.573619, theta(0.5) =
  // 0.7056345 - 0.01179875 + 0.00802313 = 0.70185888 (to 8 places).
  const double rim = 1.573619, half = 0.7056345 - 0.01179875 + 0.0080231250;
  Camera c = of(CameraType::Omnimax);
  auto p = makeProjection(c, 100, 100);  // square: the circle fills the image
  checkDirection(rayAt(*p, Vec2(50.0, 50.0)).d, Vec3(0.0, 0.0, -1.0));
  // The rim is 90.16 degrees off the axis: beside it (up component 0) that is behind the
  // plane the lens cuts at (up + forward components below 0), so no ray.
  CHECK_FALSE(hasRay(*p, Vec2(100.0, 50.0)));
  // r = 0.98: theta = 1.411269 * 0.98 - 0.09439 * 0.98^3 + 0.25674 * 0.98^5 = 1.5262771325.
  checkDirection(rayAt(*p, Vec2(99.0, 50.0)).d,
                 Vec3(std::sin(1.5262771325), 0.0, -std::cos(1.5262771325)), 1e-9);
  checkDirection(rayAt(*p, Vec2(75.0, 50.0)).d, Vec3(std::sin(half), 0.0, -std::cos(half)));
  checkDirection(rayAt(*p, Vec2(50.0, 0.0)).d, Vec3(0.0, std::sin(rim), -std::cos(rim)));
  // Outside the circle (the corners), and straight below beyond 45 degrees under the axis.
  CHECK_FALSE(hasRay(*p, Vec2(2.0, 2.0)));
  CHECK_FALSE(hasRay(*p, Vec2(50.0, 100.0)));
  CHECK(hasRay(*p, Vec2(50.0, 75.0)));  // 40 degrees below: seen
  // A frame 2:1, wider than 1.283458: the circle stands on the top edge; the top centre is
  // the rim, the image centre (v = 1 - 1/1.283458) looks up by theta(v).
  p = makeProjection(c, 200, 100);
  checkDirection(rayAt(*p, Vec2(100.0, 0.0)).d, Vec3(0.0, std::sin(rim), -std::cos(rim)));
  const double v = 1.0 - 1.0 / 1.283458;
  const double theta = 1.411269 * v - 0.09439 * v * v * v + 0.25674 * v * v * v * v * v;
  checkDirection(rayAt(*p, Vec2(100.0, 50.0)).d, Vec3(0.0, std::sin(theta), -std::cos(theta)));
  // A narrow frame (1:2): v is divided by the aspect, so a quarter of the height up is
  // v = 0.5 / 0.5 = 1, the rim.
  p = makeProjection(c, 100, 200);
  checkDirection(rayAt(*p, Vec2(50.0, 50.0)).d, Vec3(0.0, std::sin(rim), -std::cos(rim)));
  CHECK_FALSE(hasRay(*p, Vec2(50.0, 10.0)));
}
