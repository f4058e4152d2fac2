// Generalized Panini (Sharpless, Postle, German 2010): distance 0 is the pinhole; vertical
// lines and lines through the centre stay straight; vertical compression 1 straightens
// horizontal lines too; the rays invert the paper's forward formulas.
#include "camera_checks.h"

#include "render/camera_frame.h"
#include "render/panini.h"

#include <random>

using namespace lucent;
using namespace lucent::camtest;

namespace {

Vec3 local(const CameraFrame& f, const Vec3& d) {
  return Vec3(glm::dot(d, f.right), glm::dot(d, f.up), glm::dot(d, f.forward));
}

}  // namespace

TEST_CASE("panini with distance 0 gives the pinhole directions", "[cameras][panini]") {
  Camera cam = tiltedCamera(CameraType::Panini);
  cam.distance = 0.0;
  cam.fov = 100.0;
  Camera pin = cam;
  pin.type = CameraType::Pinhole;
  for (FovAxis axis : {FovAxis::Horizontal, FovAxis::Vertical, FovAxis::Diagonal})
    for (double q : {0.0, 1.0}) {  // compression changes nothing at d = 0
      cam.fovAxis = pin.fovAxis = axis;
      cam.verticalCompression = q;
      auto p = makeProjection(cam, 70, 45);
      auto ph = makeProjection(pin, 70, 45);
      for (int j = 0; j <= 45; j += 5)
        for (int i = 0; i <= 70; i += 7) {
          Vec2 film(i, j);
          CHECK(angleBetween(rayAt(*p, film).d, rayAt(*ph, film).d) < 1e-9);
        }
    }
}

TEST_CASE("panini rays invert the published forward map h = S sin(phi), v = S tan(theta)",
          "[cameras][panini]") {
  Camera cam = tiltedCamera(CameraType::Panini);
  const CameraFrame f = makeCameraFrame(cam);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (double d : {0.0, 0.4, 1.0, 2.5}) {
    cam.distance = d;
    cam.fov = d >= 1.0 ? 200.0 : 120.0;
    if (d > 1.0) cam.fov = 2.0 * std::acos(-1.0 / d) * 180.0 / kPi - 5.0;
    auto p = makeProjection(cam, 90, 60);
    const auto& pan = as<PaniniProjection>(p);
    for (int n = 0; n < 500; ++n) {
      Vec2 film(90.0 * u(rng), 60.0 * u(rng));
      Vec3 dir = local(f, rayAt(*p, film).d);
      // The paper's formulas, evaluated independently of the projection's inverse.
      double phi = std::atan2(dir.x, dir.z), theta = std::atan2(dir.y, std::hypot(dir.x, dir.z));
      double S = (d + 1.0) / (d + std::cos(phi));
      double h = (2.0 * film.x / 90.0 - 1.0) * pan.halfWidth();
      double v = (1.0 - 2.0 * film.y / 60.0) * pan.halfHeight();
      CHECK(S * std::sin(phi) == Approx(h).margin(1e-9));
      CHECK(S * std::tan(theta) == Approx(v).margin(1e-9));
    }
    // paniniPlane() is that forward map: it takes each ray back to its plane point.
    for (const Vec2& film : {Vec2(3, 7), Vec2(45, 30), Vec2(88, 59)}) {
      Vec2 plane = paniniPlane(local(f, rayAt(*p, film).d), d);
      CHECK(plane.x == Approx((2.0 * film.x / 90.0 - 1.0) * pan.halfWidth()).margin(1e-9));
      CHECK(plane.y == Approx((1.0 - 2.0 * film.y / 60.0) * pan.halfHeight()).margin(1e-9));
    }
    // Horizontal fov: the edges are fov/2 of longitude off the axis.
    Vec3 edge = local(f, rayAt(*p, Vec2(90.0, 30.0)).d);
    CHECK(std::atan2(edge.x, edge.z) == Approx(radians(cam.fov / 2.0)).epsilon(1e-12));
  }
}

TEST_CASE("panini keeps vertical lines and lines through the centre straight",
          "[cameras][panini]") {
  Camera cam = tiltedCamera(CameraType::Panini);
  cam.distance = 1.0;
  cam.fov = 160.0;
  cam.verticalCompression = 0.0;
  const CameraFrame f = makeCameraFrame(cam);
  const int w = 120, h = 80;
  auto p = makeProjection(cam, w, h);
  // An image column sees one longitude: a vertical world line maps to a column.
  for (double x : {5.0, 31.0, 77.0, 119.0}) {
    Vec3 top = local(f, rayAt(*p, Vec2(x, 0)).d);
    for (double y : {13.0, 40.0, 71.0, 80.0}) {
      Vec3 d = local(f, rayAt(*p, Vec2(x, y)).d);
      CHECK(std::atan2(d.x, d.z) == Approx(std::atan2(top.x, top.z)).margin(1e-12));
    }
  }
  // An image line through the centre sees one plane through the view axis: the lines
  // parallel to the view axis (the "radial" lines of the paper) stay straight.
  for (const Vec2& dir : {Vec2(1.0, 0.5), Vec2(-0.7, 1.0), Vec2(1.0, -0.2)}) {
    double ratio = 0.0;
    for (double t : {0.1, 0.4, 0.8, 1.0}) {
      Vec2 film(w / 2.0 + t * dir.x * w / 2.0, h / 2.0 - t * dir.y * h / 2.0);
      if (film.y < 0.0 || film.y > h) continue;
      Vec3 d = local(f, rayAt(*p, film).d);
      if (ratio == 0.0) ratio = d.y / d.x;
      CHECK(d.y / d.x == Approx(ratio).epsilon(1e-12));
    }
  }
}

TEST_CASE("panini vertical compression: 0 curves horizontal lines, 1 keeps them straight",
          "[cameras][panini]") {
  Camera cam = tiltedCamera(CameraType::Panini);
  cam.distance = 1.0;
  cam.fov = 150.0;
  const CameraFrame f = makeCameraFrame(cam);
  const int w = 120, h = 80;
  // A horizontal world line in front of the camera, parallel to the image plane, has
  // constant up / forward: an image row shows it straight only if it sees constant y/z.
  auto rowSpread = [&](double q) {
    cam.verticalCompression = q;
    auto p = makeProjection(cam, w, h);
    double lo = kInf, hi = -kInf;
    for (double x = 0.0; x <= w; x += 10.0) {
      Vec3 d = local(f, rayAt(*p, Vec2(x, 15.0)).d);
      lo = std::min(lo, d.y / d.z);
      hi = std::max(hi, d.y / d.z);
    }
    return hi - lo;
  };
  CHECK(rowSpread(1.0) < 1e-12);
  CHECK(rowSpread(0.0) > 0.2);  // the Panini projection bends them (S grows to the sides)
  double half = rowSpread(0.5);
  CHECK(half > 1e-3);
  CHECK(half < rowSpread(0.0));
  // Vertical lines stay straight at any compression.
  cam.verticalCompression = 0.7;
  auto p = makeProjection(cam, w, h);
  Vec3 a = local(f, rayAt(*p, Vec2(100.0, 3.0)).d), b = local(f, rayAt(*p, Vec2(100.0, 70.0)).d);
  CHECK(std::atan2(a.x, a.z) == Approx(std::atan2(b.x, b.z)).margin(1e-12));
  // The centre column is rectilinear in both: vertical fov spans the latitude.
  cam.fovAxis = FovAxis::Vertical;
  cam.fov = 80.0;
  auto pv = makeProjection(cam, w, h);
  Vec3 top = local(f, rayAt(*pv, Vec2(w / 2.0, 0.0)).d);
  CHECK(std::atan2(top.y, top.z) == Approx(radians(40.0)).epsilon(1e-12));
}

TEST_CASE("panini diagonal fov puts the corners fov/2 off the axis", "[cameras][panini]") {
  Camera cam = tiltedCamera(CameraType::Panini);
  cam.fovAxis = FovAxis::Diagonal;
  const CameraFrame f = makeCameraFrame(cam);
  for (double d : {0.0, 0.5, 1.0, 3.0})
    for (double fov : {60.0, 140.0}) {
      cam.distance = d;
      cam.fov = fov;
      auto p = makeProjection(cam, 64, 36);
      for (const Vec2& corner : {Vec2(0, 0), Vec2(64, 36), Vec2(64, 0)})
        CHECK(angleBetween(rayAt(*p, corner).d, f.forward) ==
              Approx(radians(fov / 2.0)).epsilon(1e-9));
    }
}

TEST_CASE("panini views it cannot form are camera errors", "[cameras][panini]") {
  Camera cam;
  cam.type = CameraType::Panini;
  cam.loc = SourceLoc{"scene.xml", 4, 3};
  SECTION("distance 2 reaches at most 2 acos(-1/2) = 240 degrees across") {
    cam.distance = 2.0;
    cam.fov = 245.0;
    CHECK_THROWS_WITH(makeProjection(cam, 40, 30),
                      Catch::StartsWith("scene.xml:4:3: error: a panini camera with distance 2 "
                                        "cannot show more than 240 degrees across"));
    cam.fov = 235.0;
    CHECK_NOTHROW(makeProjection(cam, 40, 30));
  }
  SECTION("vertical compression beyond 90 degrees off the axis") {
    cam.distance = 1.0;
    cam.fov = 200.0;
    cam.verticalCompression = 0.5;
    CHECK_THROWS_AS(makeProjection(cam, 40, 30), LocatedError);
    cam.verticalCompression = 0.0;
    CHECK_NOTHROW(makeProjection(cam, 40, 30));
  }
}
