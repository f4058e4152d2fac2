// Cube map: which face is where and how each is turned (cross 4x3, strip 6x1), 90 degrees
// per face, empty cells without rays, and direction -> pixel -> direction round trips.
#include "camera_checks.h"

#include "render/camera_frame.h"
#include "render/cubemap.h"
#include "render/direction_maps.h"

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

struct FaceSpec {
  const char* name;
  int col, row;
  Vec3 forward, right, up;  // world axes the face's pinhole view must have
};

// The documented layout (docs/cameras.md), in terms of the camera frame f.
std::vector<FaceSpec> documented(CubemapLayout layout, const CameraFrame& f) {
  if (layout == CubemapLayout::Cross)
    return {{"up", 1, 0, f.up, f.right, -f.forward},    {"left", 0, 1, -f.right, f.forward, f.up},
            {"front", 1, 1, f.forward, f.right, f.up},  {"right", 2, 1, f.right, -f.forward, f.up},
            {"back", 3, 1, -f.forward, -f.right, f.up}, {"down", 1, 2, -f.up, f.right, f.forward}};
  return {{"right", 0, 0, f.right, -f.forward, f.up}, {"left", 1, 0, -f.right, f.forward, f.up},
          {"up", 2, 0, f.up, f.right, -f.forward},    {"down", 3, 0, -f.up, f.right, f.forward},
          {"back", 4, 0, -f.forward, -f.right, f.up}, {"front", 5, 0, f.forward, f.right, f.up}};
}

}  // namespace

TEST_CASE("cube map faces sit where documented, turned as documented, 90 degrees each",
          "[cameras][cubemap]") {
  Camera cam = tiltedCamera(CameraType::Cubemap);
  const CameraFrame f = makeCameraFrame(cam);
  for (CubemapLayout layout : {CubemapLayout::Cross, CubemapLayout::Strip}) {
    cam.layout = layout;
    const int cols = cubeLayoutColumns(layout), rows = cubeLayoutRows(layout), s = 20;
    auto p = makeProjection(cam, cols * s, rows * s);
    for (const FaceSpec& face : documented(layout, f)) {
      INFO(face.name);
      const double x0 = face.col * s, y0 = face.row * s;
      Vec3 centre = rayAt(*p, Vec2(x0 + s / 2.0, y0 + s / 2.0)).d;
      CHECK(angleBetween(centre, face.forward) < 1e-14);
      // The cell's right-edge midpoint is 45 degrees towards the face's right, its top-edge
      // midpoint 45 degrees towards its up: a 90-degree view, oriented as documented. (The
      // edge itself may belong to the next cell, so look from 1e-9 pixel inside.)
      const double in = 1e-9;
      Vec3 rightEdge = rayAt(*p, Vec2(x0 + s - in, y0 + s / 2.0)).d;
      Vec3 topEdge = rayAt(*p, Vec2(x0 + s / 2.0, y0 + in)).d;
      Vec3 leftEdge = rayAt(*p, Vec2(x0 + in, y0 + s / 2.0)).d;
      CHECK(angleBetween(rightEdge, glm::normalize(face.forward + face.right)) < 1e-9);
      CHECK(angleBetween(topEdge, glm::normalize(face.forward + face.up)) < 1e-9);
      CHECK(angleBetween(leftEdge, rightEdge) == Approx(kPi / 2.0).epsilon(1e-9));
      // Not mirrored: image right, image up and view have the camera's own handedness.
      CHECK(glm::dot(glm::cross(face.right, face.up), face.forward) ==
            Approx(glm::dot(glm::cross(f.right, f.up), f.forward)));
    }
  }
}

TEST_CASE("cube cross: neighbouring cells share their edge, empty cells have no ray",
          "[cameras][cubemap]") {
  Camera cam = tiltedCamera(CameraType::Cubemap);
  cam.layout = CubemapLayout::Cross;
  const int s = 16;
  auto p = makeProjection(cam, 4 * s, 3 * s);
  // Horizontal neighbours in the middle row, and the up/down faces above/below the front,
  // see the same direction on both sides of their shared edge.
  for (double t : {0.1, 0.5, 0.93}) {
    for (int col = 0; col < 3; ++col) {
      double x = (col + 1) * s, y = s + t * s;
      CHECK(angleBetween(rayAt(*p, Vec2(x - 1e-9, y)).d, rayAt(*p, Vec2(x + 1e-9, y)).d) < 1e-9);
    }
    double x = s + t * s;
    CHECK(angleBetween(rayAt(*p, Vec2(x, s - 1e-9)).d, rayAt(*p, Vec2(x, s + 1e-9)).d) < 1e-9);
    CHECK(angleBetween(rayAt(*p, Vec2(x, 2 * s - 1e-9)).d, rayAt(*p, Vec2(x, 2 * s + 1e-9)).d) <
          1e-9);
  }
  // The back face's right edge wraps around to the left face's left edge.
  CHECK(angleBetween(rayAt(*p, Vec2(4 * s, 1.5 * s)).d, rayAt(*p, Vec2(0, 1.5 * s)).d) < 1e-14);
  for (const Vec2& cell : {Vec2(0, 0), Vec2(2, 0), Vec2(3, 0), Vec2(0, 2), Vec2(2, 2), Vec2(3, 2)})
    for (const Vec2& at : {Vec2(0.5), Vec2(0.01), Vec2(0.99)})
      CHECK_FALSE(hasRay(*p, (cell + at) * double(s)));
}

TEST_CASE("cube map direction -> pixel -> direction round trips within one pixel",
          "[cameras][cubemap]") {
  Camera cam = tiltedCamera(CameraType::Cubemap);
  const CameraFrame f = makeCameraFrame(cam);
  for (CubemapLayout layout : {CubemapLayout::Cross, CubemapLayout::Strip}) {
    cam.layout = layout;
    const int cols = cubeLayoutColumns(layout), rows = cubeLayoutRows(layout), s = 24;
    const int w = cols * s, h = rows * s;
    auto p = makeProjection(cam, w, h);
    const auto& cube = as<CubemapProjection>(p);
    std::mt19937_64 rng(29);
    std::vector<int> hits(w * h, 0);
    for (int k = 0; k < 100000; ++k) {
      Vec3 d = randomDirection(rng);
      glm::ivec2 px = cube.pixel(d);
      REQUIRE(px.x >= 0);
      REQUIRE(px.x < w);
      REQUIRE(px.y >= 0);
      REQUIRE(px.y < h);
      ++hits[px.y * w + px.x];
      // Never on an empty cell; the inverse is exact.
      Vec3 back;
      REQUIRE(cube.direction(cube.filmPosition(d), back));
      REQUIRE(angleBetween(back, d) < 1e-12);
      // The pixel centre's direction is no farther than the pixel's farthest corner (each
      // face is a central projection: pixels are convex geodesic quadrilaterals).
      Vec3 centre = rayAt(*p, Vec2(px) + Vec2(0.5)).d;
      double reach = 0.0;
      for (const Vec2& c : {Vec2(0.0), Vec2(1.0, 0.0), Vec2(0.0, 1.0), Vec2(1.0)}) {
        Vec2 corner = glm::min(Vec2(px) + c, Vec2(px) + Vec2(1.0 - 1e-12));  // stay on the face
        corner = glm::max(corner, Vec2(px));
        reach = std::max(reach, angleBetween(centre, rayAt(*p, corner).d));
      }
      REQUIRE(angleBetween(d, centre) <= reach * (1.0 + 1e-9));
    }
    // Every pixel of the six faces is reached, none of the empty cells.
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        CubeFace face;
        bool onFace = cubeFaceAt(layout, x / s, y / s, face);
        CHECK((hits[y * w + x] > 0) == onFace);
      }
    (void)f;
  }
}

TEST_CASE("every direction lands on exactly one cube-map pixel", "[cameras][cubemap]") {
  Camera cam = tiltedCamera(CameraType::Cubemap);
  const CameraFrame f = makeCameraFrame(cam);
  const int s = 8;
  auto p = makeProjection(cam, 4 * s, 3 * s);
  const auto& cube = as<CubemapProjection>(p);
  // Pixel centres map back to their own pixel.
  for (int y = 0; y < 3 * s; ++y)
    for (int x = 0; x < 4 * s; ++x) {
      Ray r;
      if (!p->generateRay(Vec2(x + 0.5, y + 0.5), Vec2(0.5), r)) continue;
      CHECK(cube.pixel(r.d) == glm::ivec2(x, y));
    }
  // Cube edges and corners (ties between faces) go to one face, inside its own cell.
  for (double a : {-1.0, 0.0, 1.0})
    for (double b : {-1.0, 0.0, 1.0})
      for (double c : {-1.0, 0.0, 1.0}) {
        if (a == 0.0 && b == 0.0 && c == 0.0) continue;
        Vec3 d = glm::normalize(f.toWorld(Vec3(a, b, c)));
        glm::ivec2 px = cube.pixel(d);
        CubeFace face;
        CHECK(cubeFaceAt(CubemapLayout::Cross, px.x / s, px.y / s, face));
        // (Rounding in the frame decides the tie, so ask which face the local direction
        // picks rather than assuming one.)
        CHECK(face == cubeFaceOf(frameLocal(f, d)));
      }
}

TEST_CASE("a cube map needs whole-pixel faces", "[cameras][cubemap]") {
  Camera cam;
  cam.type = CameraType::Cubemap;
  cam.loc = SourceLoc{"probe.xml", 2, 3};
  CHECK_THROWS_WITH(makeProjection(cam, 330, 240),
                    "probe.xml:2:3: error: a cubemap camera with layout=\"cross\" needs a width "
                    "divisible by 4 and a height divisible by 3 (got 330x240; for square faces "
                    "use e.g. 512x384)");
  CHECK_NOTHROW(makeProjection(cam, 320, 240));
  cam.layout = CubemapLayout::Strip;
  CHECK_THROWS_AS(makeProjection(cam, 320, 80), LocatedError);
  CHECK_NOTHROW(makeProjection(cam, 480, 80));
}

TEST_CASE("cube-map cells that are whole but not square still hold 90-degree faces",
          "[cameras][cubemap]") {
  // docs/cameras.md: a 512 x 192 cross (cells of 128 x 64 pixels) and a strip of any height
  // are accepted; each face still spans 90 degrees both ways, with stretched pixels.
  Camera cam = tiltedCamera(CameraType::Cubemap);
  const CameraFrame f = makeCameraFrame(cam);
  struct Case {
    CubemapLayout layout;
    int w, h;
    Vec2 front0, front1;
  };
  for (const Case& c : {Case{CubemapLayout::Cross, 512, 192, Vec2(128, 64), Vec2(256, 128)},
                        Case{CubemapLayout::Strip, 48, 5, Vec2(40, 0), Vec2(48, 5)}}) {
    cam.layout = c.layout;
    auto p = makeProjection(cam, c.w, c.h);
    const Vec2 mid = 0.5 * (c.front0 + c.front1);
    const double q = kPi / 4.0;
    // The front face's edge midpoints look 45 degrees left, right, up and down.
    CHECK(angleBetween(rayAt(*p, mid).d, f.forward) < 1e-12);
    CHECK(angleBetween(rayAt(*p, Vec2(c.front0.x, mid.y)).d, f.forward - f.right) < 1e-12);
    CHECK(angleBetween(rayAt(*p, Vec2(c.front1.x, mid.y)).d, f.forward + f.right) < 1e-12);
    CHECK(angleBetween(rayAt(*p, Vec2(mid.x, c.front0.y)).d, f.forward) ==
          Approx(q).epsilon(1e-12));
    CHECK(angleBetween(rayAt(*p, Vec2(mid.x, c.front0.y)).d, f.forward + f.up) < 1e-12);
    CHECK(angleBetween(rayAt(*p, Vec2(mid.x, c.front1.y)).d, f.forward - f.up) < 1e-12);
  }
}
