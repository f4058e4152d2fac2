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

TEST_CASE("frame-aspect sets the frame's shape whatever the image's: pixels need not be square",
          "[render][camera]") {
  Camera cam;
  cam.fov = 90.0;  // the horizontal half extent is 1 at distance 1
  SECTION("pinhole: the top edge is at 1/frame-aspect, on any image") {
    cam.frameAspect = 2.0;
    for (auto [w, h] : {std::pair{64, 48}, std::pair{30, 90}}) {
      auto p = makeProjection(cam, w, h);
      const Ray top = rayThrough(*p, w / 2.0, 0.0);
      CHECK(top.d.y / -top.d.z == Approx(0.5).epsilon(1e-14));
      const Ray right = rayThrough(*p, w, h / 2.0);
      CHECK(right.d.x / -right.d.z == Approx(1.0).epsilon(1e-14));
    }
  }
  SECTION("orthographic: width across, width/frame-aspect down") {
    cam.type = CameraType::Orthographic;
    cam.width = 3.0;
    cam.frameAspect = 1.5;
    auto p = makeProjection(cam, 50, 50);
    CHECK(rayThrough(*p, 25.0, 0.0).o.y == Approx(1.0).epsilon(1e-14));
    CHECK(rayThrough(*p, 50.0, 25.0).o.x == Approx(1.5).epsilon(1e-14));
  }
  SECTION("thin-lens: the same frame as the pinhole") {
    cam.type = CameraType::ThinLens;
    cam.frameAspect = 4.0;
    cam.fStop = 1e9;  // a pinhole's aperture
    auto p = makeProjection(cam, 40, 40);
    const Ray top = rayThrough(*p, 20.0, 0.0);
    CHECK(top.d.y / -top.d.z == Approx(0.25).epsilon(1e-9));
  }
  SECTION("0, the default, is the image's own aspect") {
    auto p = makeProjection(cam, 80, 40);
    const Ray top = rayThrough(*p, 40.0, 0.0);
    CHECK(top.d.y / -top.d.z == Approx(0.5).epsilon(1e-14));
  }
}

TEST_CASE("mirror flips the image left to right and nothing else", "[render][camera]") {
  Camera cam;
  cam.fov = 60.0;
  Camera mirrored = cam;
  mirrored.mirror = true;
  const CameraFrame f = makeCameraFrame(mirrored);
  CHECK(f.right == Vec3(-1, 0, 0));
  CHECK(f.up == Vec3(0, 1, 0));
  auto plain = makeProjection(cam, 64, 48);
  auto flipped = makeProjection(mirrored, 64, 48);
  for (double x : {0.5, 10.5, 40.25})
    for (double y : {0.5, 30.5}) {
      const Ray a = rayThrough(*plain, x, y), b = rayThrough(*flipped, 64.0 - x, y);
      CHECK(b.d.x == Approx(a.d.x).margin(1e-15));
      CHECK(b.d.y == Approx(a.d.y).margin(1e-15));
      CHECK(b.d.z == Approx(a.d.z).margin(1e-15));
    }
}

TEST_CASE("image-plane: the ray through (s, t) goes along forward + s·right + t·up",
          "[render][camera]") {
  // The default frame: camera space x right = world +x, y up = +y, z forward = -z.
  Camera cam;
  cam.imagePlane = Camera::ImagePlane{Vec3(2.0, 0.5, 0.0), Vec3(0.0, 1.0, -0.25)};
  SECTION("pinhole: corners and centre, on any image") {
    for (auto [w, h] : {std::pair{64, 48}, std::pair{30, 90}}) {
      auto p = makeProjection(cam, w, h);
      // The top-right corner: s = t = 1/2.
      const Vec3 corner = glm::normalize(Vec3(1.0, 0.25 + 0.5, -(1.0 - 0.125)));
      const Ray r = rayThrough(*p, w, 0.0);
      CHECK(glm::length(r.d - corner) < 1e-14);
      const Ray c = rayThrough(*p, w / 2.0, h / 2.0);
      CHECK(glm::length(c.d - Vec3(0.0, 0.0, -1.0)) < 1e-15);
    }
  }
  SECTION("orthographic: origins on the parallelogram, every ray along the view") {
    cam.type = CameraType::Orthographic;
    cam.position = Vec3(1.0, 2.0, 3.0);
    cam.lookAt = Vec3(1.0, 2.0, 2.0);
    auto p = makeProjection(cam, 50, 50);
    const Ray r = rayThrough(*p, 0.0, 50.0);  // the bottom-left corner: s = t = -1/2
    CHECK(glm::length(r.o - (Vec3(1.0, 2.0, 3.0) + Vec3(-1.0, -0.75, -0.125))) < 1e-14);
    CHECK(r.d == Vec3(0.0, 0.0, -1.0));
  }
}
