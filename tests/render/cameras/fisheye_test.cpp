// Fisheye: the angle from the axis follows the mapping of the image radius; the circle
// spans the image along fov-axis; pixels outside it have no ray and render as background.
#include "camera_checks.h"

#include "../scene_builder.h"
#include "render/camera_frame.h"
#include "render/fisheye.h"
#include "render/renderer.h"

#include <random>

using namespace lucent;
using namespace lucent::camtest;

namespace {

// The image radius of a film point relative to the circle radius R (pixels).
double radiusOf(const Vec2& film, int w, int h, double R) {
  return std::hypot(film.x - w / 2.0, film.y - h / 2.0) / R;
}

}  // namespace

TEST_CASE("equidistant fisheye: angle from the axis proportional to the image radius",
          "[cameras][fisheye]") {
  Camera cam = tiltedCamera(CameraType::Fisheye);
  cam.mapping = FisheyeMapping::Equidistant;
  const CameraFrame f = makeCameraFrame(cam);
  const int w = 80, h = 50;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> ux(0.0, w), uy(0.0, h);
  for (double fov : {90.0, 180.0, 250.0, 360.0})
    for (FovAxis axis : {FovAxis::Horizontal, FovAxis::Vertical, FovAxis::Diagonal}) {
      cam.fov = fov;
      cam.fovAxis = axis;
      auto p = makeProjection(cam, w, h);
      const double R = axis == FovAxis::Horizontal ? w / 2.0
                       : axis == FovAxis::Vertical ? h / 2.0
                                                   : std::hypot(w, h) / 2.0;
      CHECK(as<FisheyeProjection>(p).circleRadius() == R);
      int inside = 0;
      for (int n = 0; n < 2000; ++n) {
        Vec2 film(ux(rng), uy(rng));
        double r = radiusOf(film, w, h, R);
        Ray ray;
        bool has = p->generateRay(film, Vec2(0.5), ray);
        REQUIRE(has == (r <= 1.0));
        if (!has) continue;
        ++inside;
        CHECK(angleBetween(ray.d, f.forward) == Approx(r * radians(fov) / 2.0).margin(1e-12));
        // The azimuth is the film point's angle about the centre (+x right, +y up).
        double px = film.x - w / 2.0, py = h / 2.0 - film.y;
        double azimuth = std::atan2(glm::dot(ray.d, f.up), glm::dot(ray.d, f.right));
        if (r > 1e-6 && r * fov < 359.0)
          CHECK(std::remainder(azimuth - std::atan2(py, px), 2.0 * kPi) ==
                Approx(0.0).margin(1e-9));
      }
      // Some samples fall inside the circle, and (but for the diagonal circle) some outside.
      CHECK(inside > 100);
      if (axis != FovAxis::Diagonal) CHECK(inside < 2000);
    }
}

TEST_CASE("equisolid fisheye: angle 2 asin(r / 2f) with the rim at fov/2", "[cameras][fisheye]") {
  Camera cam = tiltedCamera(CameraType::Fisheye);
  cam.mapping = FisheyeMapping::Equisolid;
  const CameraFrame f = makeCameraFrame(cam);
  const int w = 64, h = 64;
  for (double fov : {120.0, 180.0, 300.0, 360.0}) {
    cam.fov = fov;
    auto p = makeProjection(cam, w, h);
    const double R = 32.0;
    // Image radius = 2 f sin(theta / 2) reaches R at theta = fov/2.
    const double focal = R / (2.0 * std::sin(radians(fov) / 4.0));
    for (double rp : {0.0, 3.0, 10.0, 17.5, 25.0, 31.0, 32.0}) {
      for (double a : {0.3, 2.0, 4.0}) {
        Vec2 film(32.0 + rp * std::cos(a), 32.0 - rp * std::sin(a));
        Ray ray = rayAt(*p, film);
        CHECK(angleBetween(ray.d, f.forward) ==
              Approx(2.0 * std::asin(rp / (2.0 * focal))).margin(1e-12));
      }
    }
    // Equal areas see equal solid angles: the solid angle within image radius r is
    // 2 pi (1 - cos theta(r)) = 4 pi sin^2(theta/2), proportional to r^2.
    auto solidAngle = [&](double rp) {
      double theta = angleBetween(rayAt(*p, Vec2(32.0 + rp, 32.0)).d, f.forward);
      return 2.0 * kPi * (1.0 - std::cos(theta));
    };
    CHECK(solidAngle(16.0) / solidAngle(8.0) == Approx(4.0).epsilon(1e-12));
  }
}

TEST_CASE("square 360-degree fisheye: the inscribed disc, its rim looking straight back",
          "[cameras][fisheye]") {
  Camera cam = tiltedCamera(CameraType::Fisheye);
  cam.fov = 360.0;
  const CameraFrame f = makeCameraFrame(cam);
  for (FisheyeMapping m : {FisheyeMapping::Equidistant, FisheyeMapping::Equisolid}) {
    cam.mapping = m;
    auto p = makeProjection(cam, 40, 40);
    for (const Vec2& rim : {Vec2(40, 20), Vec2(0, 20), Vec2(20, 0), Vec2(20, 40)})
      CHECK(angleBetween(rayAt(*p, rim).d, -f.forward) < 1e-7);
    // Half way out looks sideways: 90 degrees (equidistant) or 2 asin(1/2) = 60 (equisolid).
    double halfWay = angleBetween(rayAt(*p, Vec2(30, 20)).d, f.forward);
    CHECK(halfWay ==
          Approx(m == FisheyeMapping::Equidistant ? kPi / 2.0 : kPi / 3.0).epsilon(1e-12));
    // Corners are outside the inscribed disc.
    for (const Vec2& corner : {Vec2(0, 0), Vec2(40, 0), Vec2(0, 40), Vec2(40, 40), Vec2(3, 3)})
      CHECK_FALSE(hasRay(*p, corner));
    // Pixels with their centre inside: close to pi/4 of the image.
    int inside = 0;
    for (int j = 0; j < 40; ++j)
      for (int i = 0; i < 40; ++i) inside += hasRay(*p, Vec2(i + 0.5, j + 0.5));
    CHECK(inside / 1600.0 == Approx(kPi / 4.0).margin(0.02));
  }
}

TEST_CASE("fisheye pixels outside the image circle render as the background",
          "[cameras][fisheye][render]") {
  using namespace lucent::test;
  Scene scene;
  scene.render.width = 16;
  scene.render.height = 16;
  scene.render.samples = 4;
  scene.render.background = Color(1.0f, 0.0f, 0.0f);
  // The camera sits inside a green emissive sphere: every ray that exists sees green.
  addShape(scene, SphereSpec{Vec3(0.0), 10.0},
           addMaterial(scene, emissive(Color(0.0f, 1.0f, 0.0f))));
  Camera cam;
  cam.type = CameraType::Fisheye;
  cam.fov = 360.0;
  scene.cameras.push_back(cam);
  World world(scene);
  Renderer renderer(world, scene.cameras[0]);
  Image image = renderer.render().image;
  CHECK(image.at(0, 0) == Color(1.0f, 0.0f, 0.0f));  // corner: outside the circle
  CHECK(image.at(15, 15) == Color(1.0f, 0.0f, 0.0f));
  CHECK(image.at(8, 8) == Color(0.0f, 1.0f, 0.0f));  // inside
  CHECK(image.at(8, 0) == Color(0.0f, 1.0f, 0.0f));  // the top edge's middle touches the rim
}
