// Lenslet: an nx x ny grid of upright pinhole sub-images, lens centres pitch apart in the
// camera plane, the cell on the left seen from the left.
#include "camera_checks.h"

#include "render/camera_frame.h"
#include "render/lenslet.h"

using namespace lucent;
using namespace lucent::camtest;

TEST_CASE("lenslet cells are pinhole images from lens centres pitch apart", "[cameras][lenslet]") {
  Camera cam = tiltedCamera(CameraType::Lenslet);
  cam.lensesX = 4;
  cam.lensesY = 3;
  cam.pitch = 0.25;
  cam.fov = 50.0;
  const CameraFrame f = makeCameraFrame(cam);
  const int cw = 20, ch = 10, w = 4 * cw, h = 3 * ch;
  auto p = makeProjection(cam, w, h);
  const auto& lenslet = as<LensletProjection>(p);
  // The same sub-image geometry as a pinhole camera with the cell's size.
  Camera pin = cam;
  pin.type = CameraType::Pinhole;
  auto sub = makeProjection(pin, cw, ch);
  Vec3 mean(0.0);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) {
      Vec3 centre = f.origin + (i - 1.5) * 0.25 * f.right + (1.0 - j) * 0.25 * f.up;
      CHECK(glm::length(lenslet.lensCentre(i, j) - centre) < 1e-14);
      mean += lenslet.lensCentre(i, j) / 12.0;
      for (const Vec2& at :
           {Vec2(0.5 * cw, 0.5 * ch), Vec2(0.0), Vec2(cw - 0.25, 3.0), Vec2(7.0, ch - 0.5)}) {
        Ray r = rayAt(*p, Vec2(i * cw, j * ch) + at);
        CHECK(glm::length(r.o - centre) < 1e-14);
        CHECK(angleBetween(r.d, rayAt(*sub, at).d) < 1e-14);
      }
    }
  CHECK(glm::length(mean - f.origin) < 1e-14);  // the grid is centred on the position
  // The cell centre looks along the view; the left column sits to the left.
  CHECK(angleBetween(rayAt(*p, Vec2(cw / 2.0, ch / 2.0)).d, f.forward) < 1e-15);
  CHECK(glm::dot(rayAt(*p, Vec2(1, 1)).o - f.origin, f.right) < 0.0);
  CHECK(glm::dot(rayAt(*p, Vec2(1, 1)).o - f.origin, f.up) > 0.0);
  // Horizontal fov spans each cell: its left and right edges are 25 degrees off the axis.
  CHECK(angleBetween(rayAt(*p, Vec2(2 * cw, 1.5 * ch)).d, f.forward) ==
        Approx(radians(25.0)).epsilon(1e-13));
}

TEST_CASE("lenslet cells are framed like pinhole images of the cell for every fov-axis",
          "[cameras][lenslet]") {
  Camera cam = tiltedCamera(CameraType::Lenslet);
  cam.lensesX = 3;
  cam.lensesY = 2;
  cam.fov = 70.0;
  for (FovAxis axis : {FovAxis::Horizontal, FovAxis::Vertical, FovAxis::Diagonal}) {
    cam.fovAxis = axis;
    Camera pin = cam;
    pin.type = CameraType::Pinhole;
    auto p = makeProjection(cam, 3 * 30, 2 * 16);
    auto sub = makeProjection(pin, 30, 16);
    for (const Vec2& at : {Vec2(0.0), Vec2(30.0, 16.0), Vec2(12.5, 3.0)})
      CHECK(angleBetween(rayAt(*p, Vec2(30.0, 16.0) + glm::min(at, Vec2(29.999, 15.999))).d,
                         rayAt(*sub, glm::min(at, Vec2(29.999, 15.999))).d) < 1e-13);
  }
}

TEST_CASE("a lenslet camera needs a pixel per lens at least", "[cameras][lenslet]") {
  Camera cam;
  cam.type = CameraType::Lenslet;
  cam.lensesX = 64;
  cam.lensesY = 2;
  CHECK_THROWS_AS(makeProjection(cam, 32, 32), LocatedError);
  CHECK_NOTHROW(makeProjection(cam, 64, 32));
}
