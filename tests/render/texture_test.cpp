// Checker cells, the boundary rule, and image textures looked up by (u,v).
#include "scene_builder.h"

#include "app/image_output.h"
#include "render/renderer.h"
#include "render/texture.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include <unistd.h>

using namespace lucent;
using namespace lucent::test;

namespace {
const Color kOne(1.0f, 0.0f, 0.0f), kTwo(0.0f, 0.0f, 1.0f);
Color cell(const Vec3& p, double scale = 1.0) {
  return checkerColor(CheckerTexture{kOne, kTwo, scale, {}}, p, Vec3(0.0));
}
}  // namespace

TEST_CASE("checker: the cube from 0 to scale is color1 and neighbours alternate",
          "[render][texture]") {
  CHECK(cell(Vec3(0.5, 0.5, 0.5)) == kOne);
  CHECK(cell(Vec3(1.5, 0.5, 0.5)) == kTwo);
  CHECK(cell(Vec3(1.5, 1.5, 0.5)) == kOne);
  CHECK(cell(Vec3(-0.5, 0.5, 0.5)) == kTwo);
  CHECK(cell(Vec3(-0.5, -0.5, -0.5)) == kTwo);
  CHECK(cell(Vec3(0.9, 0.9, 0.9), 2.0) == kOne);
  CHECK(cell(Vec3(2.1, 0.9, 0.9), 2.0) == kTwo);
}

TEST_CASE("checker: a point on a cell boundary shows the cell on the positive side",
          "[render][texture]") {
  // Exactly on the plane y = 0: the cell above.
  CHECK(cell(Vec3(0.5, 0.0, 0.5)) == kOne);
  CHECK(cell(Vec3(0.5, -0.0, 0.5)) == kOne);
  // A hair below through rounding: 0.3 / 0.1 is 2.9999999999999996 in doubles, so the
  // plane y = 0.3 under a checker of scale 0.1 lies on the boundary of cells 2 and 3.
  REQUIRE(0.3 / 0.1 < 3.0);
  CHECK(cell(Vec3(0.05, 0.3, 0.05), 0.1) == kTwo);         // cell (0, 3, 0): odd
  CHECK(cell(Vec3(0.05, 0.3 - 1e-6, 0.05), 0.1) == kOne);  // really below: cell (0, 2, 0)
  // A point within its own rounding error of a boundary counts as on it.
  CHECK(checkerColor(CheckerTexture{kOne, kTwo, 1.0, {}}, Vec3(0.5, -1e-7, 0.5),
                     Vec3(0, 1e-7, 0)) == kOne);
  // Far from the origin the tolerance grows with the coordinates' magnitude.
  CHECK(cell(Vec3(1e6 + 0.5, -1e-10, 0.5)) == cell(Vec3(1e6 + 0.5, 0.0, 0.5)));
}

TEST_CASE("checker: far from the origin a point near a boundary keeps its own cell",
          "[render][texture]") {
  // docs/accuracy.md, sphere_far: the floor hit at x = 100000.3999788, 2.1e-5 below the
  // boundary 100000.4 of cells of 0.4 (cell 250000 ends there), with a rounding bound of
  // 1e-11. The tolerance is rounding, not a share of the coordinate.
  const Vec3 err(1e-11);
  auto at = [&](double x) {
    return checkerColor(CheckerTexture{kOne, kTwo, 0.4, {}}, Vec3(x, 0.0, 0.2), err);
  };
  CHECK(at(100000.3999788) == at(100000.2));
  CHECK(at(100000.4000212) == at(100000.6));
  CHECK(at(100000.2) != at(100000.6));
}

TEST_CASE("checker is evaluated in the object space of the shape", "[render][texture]") {
  Scene scene;
  scene.render.ambient = Color(1.0f);
  Material m;
  m.ambient = Color(1.0f);
  m.texture = CheckerTexture{kOne, kTwo, 1.0, {}};
  uint32_t mat = addMaterial(scene, m);
  // The floor y = 0.3 of a plane moved up by 0.3: its object space has y = 0, the cell above.
  addShape(scene, PlaneSpec{Vec3(0, 1, 0), 0.0}, mat, translation(Vec3(0.5, 0.3, 0)));
  World world(scene);
  // World x = 0.7 is object x = 0.2 (cell 0, even); world x = 0.3 is object -0.2 (cell -1).
  CHECK(traceOne(world, Ray(Vec3(0.7, 5, 0.5), Vec3(0, -1, 0))) == kOne);
  CHECK(traceOne(world, Ray(Vec3(0.3, 5, 0.5), Vec3(0, -1, 0))) == kTwo);
}

TEST_CASE("a box top on a cell boundary shows the cell above it in every pixel",
          "[render][texture]") {
  // The top face y = 0.3 under a checker of scale 0.1 is the boundary between cell rows
  // 2 and 3, and 0.3 / 0.1 rounds to just below 3: every pixel must show row 3.
  Scene scene;
  scene.render.width = 48;
  scene.render.height = 32;
  scene.render.ambient = Color(1.0f);
  Material m;
  m.ambient = Color(1.0f);
  m.texture = CheckerTexture{Color(1.0f, 0.0f, 0.0f), Color(0.0f, 1.0f, 0.0f), 0.1, {}};
  addShape(scene, BoxSpec{Vec3(-50, -1, -50), Vec3(50, 0.3, 50)}, addMaterial(scene, m));
  scene.cameras.push_back(lookingFrom(Vec3(0.013, 1.3, 10), Vec3(0, 0.3, 0), 40));
  World world(scene);
  Renderer renderer(world, scene.cameras[0]);
  RenderResult r = renderer.render();
  int checked = 0;
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 48; ++i) {
      Ray ray;
      renderer.projection().generateRay(Vec2(i + 0.5, j + 0.5), Vec2(0.5), ray);
      if (ray.d.y >= 0) continue;
      const Vec3 p = ray.at((0.3 - ray.o.y) / ray.d.y);
      if (std::abs(p.x) > 49 || std::abs(p.z) > 49) continue;  // beyond the box top
      const double qx = p.x / 0.1, qz = p.z / 0.1;
      // Points within 1e-6 of a vertical cell wall are not this test's concern.
      if (std::abs(qx - std::round(qx)) < 1e-6 || std::abs(qz - std::round(qz)) < 1e-6) continue;
      const long sum = static_cast<long>(std::floor(qx)) + 3 + static_cast<long>(std::floor(qz));
      const Color expected = (sum & 1) == 0 ? Color(1, 0, 0) : Color(0, 1, 0);
      INFO("pixel " << i << "," << j);
      CHECK(r.image.at(i, j) == expected);
      ++checked;
    }
  CHECK(checked > 1000);
}

TEST_CASE("image texture: bilinear lookup at (u,v), v = 1 at the top row, repeating",
          "[render][texture]") {
  auto path = (std::filesystem::temp_directory_path() /
               ("lucent-tex-" + std::to_string(::getpid()) + ".exr"))
                  .string();
  Image img(2, 2);
  img.at(0, 0) = Color(1, 0, 0);  // top left
  img.at(1, 0) = Color(0, 1, 0);  // top right
  img.at(0, 1) = Color(0, 0, 1);  // bottom left
  img.at(1, 1) = Color(1, 1, 1);  // bottom right
  writeImageFile(img, path);
  ImageMap map(path);
  CHECK(map.width() == 2);
  // Pixel centres: (u, v) = (0.25, 0.75) is the top-left pixel.
  CHECK(map.lookup(Vec2(0.25, 0.75), Vec2(1.0)) == Color(1, 0, 0));
  CHECK(map.lookup(Vec2(0.75, 0.75), Vec2(1.0)) == Color(0, 1, 0));
  CHECK(map.lookup(Vec2(0.25, 0.25), Vec2(1.0)) == Color(0, 0, 1));
  // Half way between the top two centres.
  Color mid = map.lookup(Vec2(0.5, 0.75), Vec2(1.0));
  CHECK(mid.r == Approx(0.5));
  CHECK(mid.g == Approx(0.5));
  // Repeats with period 1, and scale enlarges: (u,v)/scale.
  CHECK(map.lookup(Vec2(1.25, -0.25), Vec2(1.0)) == Color(1, 0, 0));
  CHECK(map.lookup(Vec2(0.5, 1.5), Vec2(2.0)) == Color(1, 0, 0));
  std::filesystem::remove(path);
  CHECK_THROWS_AS(ImageMap(path), ImageIOError);
}

TEST_CASE("8-bit sRGB image textures are decoded to linear", "[render][texture]") {
  // A 1x1 PNG made outside Lucent (Python's zlib and struct: IHDR 8-bit RGB, one IDAT, IEND;
  // no colour chunk, so sRGB) holding the codes 188, 124 and 3. The expected values are the
  // IEC 61966-2-1 decoding ((c/255 + 0.055) / 1.055)^2.4, worked out by hand: 0.502886,
  // 0.201556, and 3/255/12.92 = 0.000911 on the linear segment.
  static const unsigned char kPng[] = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
      0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x02, 0x00, 0x00,
      0x00, 0x90, 0x77, 0x53, 0xde, 0x00, 0x00, 0x00, 0x0c, 0x49, 0x44, 0x41, 0x54, 0x78,
      0x9c, 0x63, 0xd8, 0x53, 0xc3, 0x0c, 0x00, 0x03, 0x33, 0x01, 0x3c, 0x7d, 0x8a, 0x26,
      0x6d, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  auto path = (std::filesystem::temp_directory_path() /
               ("lucent-tex-" + std::to_string(::getpid()) + ".png"))
                  .string();
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(kPng), sizeof kPng);
  ImageMap map(path);
  Color c = map.lookup(Vec2(0.5), Vec2(1.0));
  CHECK(c.r == Approx(0.502886).margin(1e-5));
  CHECK(c.g == Approx(0.201556).margin(1e-5));
  CHECK(c.b == Approx(0.000911).margin(1e-6));
  std::filesystem::remove(path);
}

TEST_CASE("8-bit PPM image textures are decoded to linear like sRGB PNGs", "[render][texture]") {
  // OpenImageIO labels a PPM "Rec709"; its codes 188, 124 and 3 must decode as the PNG's
  // above (IEC 61966-2-1, worked out by hand), not be taken as linear values.
  const std::string ppm = std::string("P6\n1 1\n255\n") + char(188) + char(124) + char(3);
  auto path = (std::filesystem::temp_directory_path() /
               ("lucent-tex-" + std::to_string(::getpid()) + ".ppm"))
                  .string();
  std::ofstream(path, std::ios::binary) << ppm;
  ImageMap map(path);
  Color c = map.lookup(Vec2(0.5), Vec2(1.0));
  CHECK(c.r == Approx(0.502886).margin(1e-5));
  CHECK(c.g == Approx(0.201556).margin(1e-5));
  CHECK(c.b == Approx(0.000911).margin(1e-6));
  std::filesystem::remove(path);
}
