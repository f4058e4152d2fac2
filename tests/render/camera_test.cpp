// Pinhole camera and sample positions: ray directions checked against trigonometry.
#include "render/camera_frame.h"
#include "render/pinhole.h"
#include "render/projection.h"
#include "render/sampling.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

using namespace lucent;

namespace {

double angleBetween(const Vec3& a, const Vec3& b) {
  return std::acos(glm::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0));
}

Ray rayThrough(const Projection& p, double x, double y) {
  Ray r;
  REQUIRE(p.generateRay(Vec2(x, y), Vec2(0.5), r));
  return r;
}

}  // namespace

TEST_CASE("default camera looks down -z with +x right and +y up", "[render][camera]") {
  Camera cam;
  CameraFrame f = makeCameraFrame(cam);
  CHECK(f.forward == Vec3(0, 0, -1));
  CHECK(f.right == Vec3(1, 0, 0));
  CHECK(f.up == Vec3(0, 1, 0));
  CHECK(f.origin == Vec3(0, 0, 0));
}

TEST_CASE("pinhole centre ray is the view direction and row 0 is the top", "[render][camera]") {
  Camera cam;
  cam.position = Vec3(1, 2, 3);
  cam.lookAt = Vec3(1, 2, -7);
  auto p = makeProjection(cam, 64, 48);
  Ray centre = rayThrough(*p, 32.0, 24.0);
  CHECK(centre.o == Vec3(1, 2, 3));
  CHECK(centre.d.x == Approx(0.0).margin(1e-15));
  CHECK(centre.d.y == Approx(0.0).margin(1e-15));
  CHECK(centre.d.z == Approx(-1.0));
  // Pixel (0, 0) is the top-left: its ray goes left (-x) and up (+y).
  Ray topLeft = rayThrough(*p, 0.5, 0.5);
  CHECK(topLeft.d.x < 0.0);
  CHECK(topLeft.d.y > 0.0);
  CHECK(glm::length(topLeft.d) == Approx(1.0).epsilon(1e-15));
}

TEST_CASE("pinhole fov spans the chosen axis", "[render][camera]") {
  Camera cam;
  cam.fov = 70.0;
  const int w = 80, h = 40;
  const double half = radians(35.0);
  SECTION("horizontal: the left and right edges are fov/2 off axis") {
    cam.fovAxis = FovAxis::Horizontal;
    auto p = makeProjection(cam, w, h);
    CHECK(angleBetween(rayThrough(*p, 0, h / 2.0).d, Vec3(0, 0, -1)) ==
          Approx(half).epsilon(1e-12));
    CHECK(angleBetween(rayThrough(*p, w, h / 2.0).d, Vec3(0, 0, -1)) ==
          Approx(half).epsilon(1e-12));
    // Square pixels: the top edge is atan(tan(half) * h / w) off axis.
    CHECK(angleBetween(rayThrough(*p, w / 2.0, 0).d, Vec3(0, 0, -1)) ==
          Approx(std::atan(std::tan(half) * h / w)).epsilon(1e-12));
  }
  SECTION("vertical: the top and bottom edges are fov/2 off axis") {
    cam.fovAxis = FovAxis::Vertical;
    auto p = makeProjection(cam, w, h);
    CHECK(angleBetween(rayThrough(*p, w / 2.0, 0).d, Vec3(0, 0, -1)) ==
          Approx(half).epsilon(1e-12));
    CHECK(angleBetween(rayThrough(*p, w / 2.0, h).d, Vec3(0, 0, -1)) ==
          Approx(half).epsilon(1e-12));
  }
  SECTION("diagonal: the corners are fov/2 off axis") {
    cam.fovAxis = FovAxis::Diagonal;
    auto p = makeProjection(cam, w, h);
    CHECK(angleBetween(rayThrough(*p, 0, 0).d, Vec3(0, 0, -1)) == Approx(half).epsilon(1e-12));
    CHECK(angleBetween(rayThrough(*p, w, h).d, Vec3(0, 0, -1)) == Approx(half).epsilon(1e-12));
  }
}

TEST_CASE("near and far become the primary ray's tmin and tmax", "[render][camera]") {
  Camera cam;
  cam.near = 0.5;
  cam.far = 20.0;
  auto p = makeProjection(cam, 10, 10);
  Ray r = rayThrough(*p, 3.5, 7.5);
  CHECK(r.tmin == 0.5);
  CHECK(r.tmax == 20.0);
}

TEST_CASE("camera transform applies after position, look-at and up", "[render][camera]") {
  Camera cam;
  cam.position = Vec3(0, 0, 5);
  cam.lookAt = Vec3(0, 0, 0);
  // rotate-y(90) maps +z to +x: the camera moves to (5, 0, 0) and still looks at the origin.
  cam.transform = glm::rotate(Mat4(1.0), radians(90.0), Vec3(0, 1, 0));
  CameraFrame f = makeCameraFrame(cam);
  CHECK(f.origin.x == Approx(5.0));
  CHECK(f.origin.z == Approx(0.0).margin(1e-12));
  CHECK(f.forward.x == Approx(-1.0));
  CHECK(f.right.z == Approx(-1.0));  // right = forward x up = (-1,0,0) x (0,1,0)
  CHECK(f.up.y == Approx(1.0));
  CHECK(f.lookDistance == Approx(5.0));
}

TEST_CASE("degenerate cameras are errors that name the camera's location", "[render][camera]") {
  Camera cam;
  cam.loc = SourceLoc{"scene.xml", 3, 5};
  SECTION("look-at on the position") {
    cam.lookAt = cam.position;
    CHECK_THROWS_WITH(makeCameraFrame(cam),
                      "scene.xml:3:5: error: camera look-at coincides with its position");
  }
  SECTION("up along the view direction") {
    cam.up = Vec3(0, 0, 2);
    CHECK_THROWS_WITH(makeCameraFrame(cam),
                      "scene.xml:3:5: error: camera up is parallel to the viewing direction");
  }
  SECTION("pinhole fov of 180 degrees") {
    cam.fov = 180.0;
    CHECK_THROWS_AS(makeProjection(cam, 4, 4), LocatedError);
  }
}

TEST_CASE("sub-pixel offsets: centre for one sample, Halton (2,3) from index 1",
          "[render][camera]") {
  CHECK(pixelSampleOffset(0, 1) == Vec2(0.5, 0.5));
  CHECK(pixelSampleOffset(0, 4) == Vec2(0.5, 1.0 / 3.0));
  CHECK(pixelSampleOffset(1, 4) == Vec2(0.25, 2.0 / 3.0));
  CHECK(pixelSampleOffset(2, 4) == Vec2(0.75, 1.0 / 9.0));
  CHECK(pixelSampleOffset(3, 4).x == 0.125);
  CHECK(pixelSampleOffset(3, 4).y == Approx(4.0 / 9.0).epsilon(1e-15));
  CHECK(radicalInverse(2, 6) == 0.375);  // 110b -> 0.011b
}
