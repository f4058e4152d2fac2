// <bump-map>: POV-Ray's bump_map on a tiny image written here, checked against values
// worked out by hand (POV-Ray's triangle and frame, done in Python from the stored bytes),
// and wired into the tracer without touching hits or shadows.
#include "scene_builder.h"

#include "app/image_output.h"
#include "lang/parser.h"
#include "render/bump_map.h"
#include "render/image_map_cache.h"
#include "render/texture.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

#include <unistd.h>

using namespace lucent;
using namespace lucent::test;

namespace {

// The stored 8-bit values of the test image, row 0 at the top.
constexpr int kBytes[4][4] = {
    {0, 64, 128, 255}, {32, 96, 160, 224}, {255, 0, 255, 0}, {10, 20, 30, 40}};

// The linear value whose 8-bit sRGB code is `code` (the PNG writer encodes it back).
float linearFor(int code) {
  const double c = code / 255.0;
  return static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

// A 4x4 grey PNG with kBytes, in the temporary folder; removed at the end of the test.
struct BumpImage {
  std::string path;
  explicit BumpImage(const std::string& name) {
    path = (std::filesystem::temp_directory_path() /
            ("lucent-bump-" + std::to_string(::getpid()) + "-" + name + ".png"))
               .string();
    Image img(4, 4);
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x) img.at(x, y) = Color(linearFor(kBytes[y][x]));
    writeImageFile(img, path);
  }
  ~BumpImage() { std::filesystem::remove(path); }
};

// The (u,v) of the centre of pixel (column i, row j).
Vec2 centre(int i, int j) { return Vec2((i + 0.5) / 4.0, 1.0 - (j + 0.5) / 4.0); }

void checkNear(const Vec3& got, const Vec3& want) {
  INFO("got " << got.x << " " << got.y << " " << got.z);
  CHECK(got.x == Approx(want.x).margin(2e-7));
  CHECK(got.y == Approx(want.y).margin(2e-7));
  CHECK(got.z == Approx(want.z).margin(2e-7));
}

}  // namespace

TEST_CASE("a bump map keeps the image's stored values and POV-Ray's grey weights",
          "[render][bump-map]") {
  BumpImage image("stored");
  ImageMap map(image.path, PixelDecoding::AsStored);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      INFO("pixel " << i << " " << j);
      // Within an ulp: the decoder scales by 1/255 in single precision.
      CHECK(map.lookupPixel(i + 0.5, j + 0.5).r == Approx(kBytes[j][i] / 255.0).margin(1e-7));
    }
  CHECK(bumpGrey(Color(1, 0, 0)) == 0.297f);
  CHECK(bumpGrey(Color(0, 1, 0)) == 0.589f);
  CHECK(bumpGrey(Color(0, 0, 1)) == 0.114f);
}

TEST_CASE("bump map: the normal from three pixels and the frame of N and +y",
          "[render][bump-map]") {
  BumpImage image("normal");
  ImageMap map(image.path, PixelDecoding::AsStored);

  SECTION("N = +y, the special frame (x, y, z)") {
    // Pixel (1,1): g1 = 96/255; the row below gives g2 = g3 = 1 (pixels (0,2), (2,2)). With
    // depth 2: b ∝ (−2(g3−g2), 2, 2·2(g1−g2) − 2(g3−g2)) = (0, 2, −2.494118), and the
    // result is (b.x, b.y, −b.z) normalised.
    checkNear(bumpMapNormal(map, 2.0, centre(1, 1), Vec3(0, 1, 0)),
              Vec3(0.0, 0.625592185, 0.780150254));
  }
  SECTION("the neighbours wrap around the image") {
    // Pixel (0,3): its neighbours are (3,0) = 255 and (1,0) = 64, past both edges.
    checkNear(bumpMapNormal(map, 0.5, centre(0, 3), Vec3(0, 1, 0)),
              Vec3(0.176860798, 0.944492221, 0.276865857));
  }
  SECTION("N = −y, the frame (x, −y, −z)") {
    checkNear(bumpMapNormal(map, 1.0, centre(2, 0), Vec3(0, -1, 0)),
              Vec3(-0.241647115, -0.962812723, -0.120823557));
  }
  SECTION("any other N: X' = N × y, Z' = X' × N") {
    checkNear(bumpMapNormal(map, 2.0, centre(1, 1), glm::normalize(Vec3(1, 2, 3))),
              Vec3(0.035327083, 0.993740395, 0.105981249));
    checkNear(bumpMapNormal(map, 0.5, centre(0, 3), Vec3(0, 0, 1)),
              Vec3(-0.176860798, 0.276865857, 0.944492221));
  }
  SECTION("depth 0 leaves the normal as it is") {
    const Vec3 n = glm::normalize(Vec3(1, 2, 3));
    checkNear(bumpMapNormal(map, 0.0, centre(1, 1), n), n);
  }
}

TEST_CASE("a bump-mapped mesh shades with the bent normal, its hits and shadows unchanged",
          "[render][bump-map]") {
  BumpImage image("scene");
  const std::string folder = std::filesystem::path(image.path).parent_path().string();
  const std::string src = std::filesystem::path(image.path).filename().string();
  // A unit quad in y = 0 with (u,v) = (x, −z), a light above it and a small blocker.
  auto scene = [&](const std::string& normal) {
    ParseResult r = parseSceneString(
        R"XML(<scene version="1"><camera position="0 5 5" look-at="0 0 0"/><render ambient="0"/>
        <light type="point" position="0.5 4 -0.5"/>
        <mesh positions="0 0 0  1 0 0  1 0 -1  0 0 -1" uvs="0 0  1 0  1 1  0 1"
              indices="0 1 2  0 2 3"><material diffuse="1">)XML" +
            normal +
            R"XML(</material></mesh>
        <sphere center="0.275 1 -0.725" radius="0.05"/></scene>)XML",
        folder + "/bump.xml");
    std::string all;
    for (const Diagnostic& d : r.diagnostics.all()) all += d.str() + "\n";
    INFO(all);
    REQUIRE(r.scene);
    return std::move(r.scene);
  };
  auto flat = scene("");
  auto bumpy = scene("<bump-map src=\"" + src + "\" depth=\"2\"/>");
  World a(*flat), b(*bumpy);

  // At the centre of pixel (1,1), u = 0.375, v = 0.625: the bent normal of the test above.
  const Vec3 p(0.375, 0.0, -0.625);
  const Ray down(p + Vec3(0, 2, 0), Vec3(0, -1, 0));
  Hit ha, hb;
  REQUIRE(a.intersect(down, ha));
  REQUIRE(b.intersect(down, hb));
  CHECK(ha.t == hb.t);
  const Vec3 n(0.0, 0.625592185, 0.780150254);
  const Vec3 l = glm::normalize(Vec3(0.5, 4, -0.5) - p);
  const Color flatColour = traceOne(a, down), bumpyColour = traceOne(b, down);
  // Lit with N·L: the flat quad by l.y, the bumped one by n·l (no distance fall-off).
  CHECK(flatColour.r == Approx(l.y).margin(1e-5));
  CHECK(bumpyColour.r == Approx(glm::dot(n, l)).margin(1e-5));
  CHECK(bumpyColour.r < flatColour.r - 0.1f);

  // (0.2, 0, −0.8) lies in the blocker's shadow (the blocker is 3/4 of the way from the
  // light to it): black on both, as shadow rays see the same geometry.
  const Ray toShadow(Vec3(0.2, 1, -0.8), Vec3(0, -1, 0));
  CHECK(traceOne(a, toShadow).r == 0.0f);
  CHECK(traceOne(b, toShadow).r == 0.0f);
  REQUIRE(a.intersect(toShadow, ha));
  REQUIRE(b.intersect(toShadow, hb));
  CHECK(ha.t == hb.t);
}

TEST_CASE("<bump-map> parses: src resolved, depth, one normal perturbation per material",
          "[lang][bump-map]") {
  BumpImage image("parse");
  const std::string folder = std::filesystem::path(image.path).parent_path().string();
  const std::string src = std::filesystem::path(image.path).filename().string();
  ParseResult r = parseSceneString(
      R"XML(<scene version="1"><camera position="0 5 5" look-at="0 0 0"/>
      <material id="a"><normal type="bumps"/></material>
      <material id="b" base="a"><bump-map src=")XML" +
          src + R"XML(" depth="-0.25"/></material>
      <material id="c" base="b"><normal type="dents" depth="0.3"/></material>
      <material id="d" base="b" diffuse="0.5"/>
      <sphere material="a"/><sphere material="b"/><sphere material="c"/><sphere material="d"/></scene>)XML",
      folder + "/bump.xml");
  REQUIRE(r.scene);
  auto material = [&](const std::string& id) -> const Material& {
    for (const Material& m : r.scene->materials)
      if (m.id == id) return m;
    FAIL("no material " << id);
    return r.scene->materials[0];
  };
  CHECK(material("a").normal);
  CHECK_FALSE(material("a").bumpMap);
  // A bump map replaces the base's <normal>, and a <normal> the base's bump map.
  REQUIRE(material("b").bumpMap);
  CHECK_FALSE(material("b").normal);
  CHECK(material("b").bumpMap->depth == -0.25);
  CHECK(std::filesystem::equivalent(material("b").bumpMap->path, image.path));
  CHECK(material("c").normal);
  CHECK_FALSE(material("c").bumpMap);
  REQUIRE(material("d").bumpMap);
  CHECK(material("d").bumpMap->depth == -0.25);
}

TEST_CASE("the image cache keeps a file as an <image> and as a <bump-map> apart",
          "[render][bump-map]") {
  BumpImage image("cache");
  ImageMapCache cache;
  auto stored = cache.get(image.path, PixelDecoding::AsStored);
  auto linear = cache.get(image.path);
  CHECK(cache.loads() == 2);
  CHECK(cache.get(image.path, PixelDecoding::AsStored) == stored);
  CHECK(cache.get(image.path) == linear);
  CHECK(cache.loads() == 2);
  // Pixel (1,0) stores 64: 64/255 as stored, its sRGB decoding as an <image>.
  CHECK(stored->lookupPixel(1.5, 0.5).r == Approx(64 / 255.0).margin(1e-7));
  CHECK(linear->lookupPixel(1.5, 0.5).r == Approx(linearFor(64)).margin(1e-6));
}
