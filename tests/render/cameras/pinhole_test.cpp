// Pinhole: every image corner's ray makes the analytic angle with the view axis for each
// fov-axis, and the centre ray is the view direction.
#include "camera_checks.h"

#include "render/camera_frame.h"

using namespace lucent;
using namespace lucent::camtest;

TEST_CASE("pinhole corner rays make the analytic angle with the axis for every fov-axis",
          "[cameras][pinhole]") {
  Camera cam = tiltedCamera(CameraType::Pinhole);
  cam.fov = 75.0;
  const int w = 96, h = 40;
  const CameraFrame f = makeCameraFrame(cam);
  const double t = std::tan(radians(cam.fov) / 2.0);
  struct Case {
    FovAxis axis;
    double halfW, halfH;  // image plane half extents at distance 1, worked out by hand
  } cases[] = {
      {FovAxis::Horizontal, t, t * h / w},
      {FovAxis::Vertical, t * w / h, t},
      {FovAxis::Diagonal, t * w / std::hypot(w, h), t * h / std::hypot(w, h)},
  };
  for (const Case& c : cases) {
    cam.fovAxis = c.axis;
    auto p = makeProjection(cam, w, h);
    const double corner = std::atan(std::hypot(c.halfW, c.halfH));
    const Vec2 corners[] = {{0, 0}, {w, 0}, {0, h}, {w, h}};
    for (const Vec2& film : corners) {
      Ray r = rayAt(*p, film);
      CHECK(angleBetween(r.d, f.forward) == Approx(corner).epsilon(1e-13));
      CHECK(glm::length(r.d) == Approx(1.0).epsilon(1e-15));
      CHECK(r.o == f.origin);
      // Left corners go left, top corners go up.
      CHECK((glm::dot(r.d, f.right) < 0.0) == (film.x == 0));
      CHECK((glm::dot(r.d, f.up) > 0.0) == (film.y == 0));
    }
    // The edge midpoints along the chosen axis are exactly fov/2 off the axis.
    if (c.axis == FovAxis::Horizontal)
      CHECK(angleBetween(rayAt(*p, Vec2(w, h / 2.0)).d, f.forward) ==
            Approx(radians(37.5)).epsilon(1e-13));
    if (c.axis == FovAxis::Vertical)
      CHECK(angleBetween(rayAt(*p, Vec2(w / 2.0, 0)).d, f.forward) ==
            Approx(radians(37.5)).epsilon(1e-13));
    if (c.axis == FovAxis::Diagonal) CHECK(corner == Approx(radians(37.5)).epsilon(1e-13));
    // The centre ray is the view direction.
    Ray centre = rayAt(*p, Vec2(w / 2.0, h / 2.0));
    CHECK(angleBetween(centre.d, f.forward) < 1e-15);
  }
}
