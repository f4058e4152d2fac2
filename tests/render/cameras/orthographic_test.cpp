// Orthographic: every ray has the view direction; the origins span exactly `width` across
// the image (and width * height / image width down it) in the plane through the position.
#include "camera_checks.h"

#include "render/camera_frame.h"

using namespace lucent;
using namespace lucent::camtest;

TEST_CASE("orthographic rays are parallel and their origins span exactly width",
          "[cameras][orthographic]") {
  Camera cam = tiltedCamera(CameraType::Orthographic);
  cam.width = 7.5;
  const int w = 60, h = 24;
  const CameraFrame f = makeCameraFrame(cam);
  auto p = makeProjection(cam, w, h);
  for (int j = 0; j <= h; j += 3)
    for (int i = 0; i <= w; i += 5) {
      Ray r = rayAt(*p, Vec2(i, j));
      CHECK(r.d == f.forward);
      // Origins lie in the plane through the position perpendicular to the view.
      CHECK(glm::dot(r.o - f.origin, f.forward) == Approx(0.0).margin(1e-14));
    }
  Ray left = rayAt(*p, Vec2(0, h / 2.0)), right = rayAt(*p, Vec2(w, h / 2.0));
  Ray top = rayAt(*p, Vec2(w / 2.0, 0)), bottom = rayAt(*p, Vec2(w / 2.0, h));
  CHECK(glm::length(right.o - left.o) == Approx(7.5).epsilon(1e-14));
  CHECK(glm::dot(right.o - left.o, f.right) == Approx(7.5).epsilon(1e-14));
  CHECK(glm::dot(top.o - bottom.o, f.up) == Approx(7.5 * h / w).epsilon(1e-14));
  // The image centre is the camera position.
  Ray centre = rayAt(*p, Vec2(w / 2.0, h / 2.0));
  CHECK(glm::length(centre.o - f.origin) < 1e-14);
  // Neighbouring pixel centres are width / image width apart.
  CHECK(glm::length(rayAt(*p, Vec2(10.5, 3.5)).o - rayAt(*p, Vec2(11.5, 3.5)).o) ==
        Approx(7.5 / w).epsilon(1e-12));
}
