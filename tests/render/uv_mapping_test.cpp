// mapping="uv" (POV-Ray's uv_mapping): patterns, normals and material maps read at
// POV-Ray's (u, v, 0) of the shape, checked against POV-Ray's (u,v) computed here.
#include "scene_builder.h"

#include "lang/parser.h"
#include "render/shading_normal.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lucent;
using namespace lucent::test;

namespace {

// A scene whose only light is the ambient 1: a material ambient="1" diffuse="0" shows its
// texture T as it is.
std::unique_ptr<Scene> sceneOf(const std::string& body) {
  ParseResult r = parseSceneString(
      R"XML(<scene version="1"><camera position="0 5 5" look-at="0 0 0"/><render ambient="1"/>)XML" +
          body + "</scene>",
      "uv.xml");
  std::string all;
  for (const Diagnostic& d : r.diagnostics.all()) all += d.str() + "\n";
  INFO(all);
  REQUIRE(r.scene);
  return std::move(r.scene);
}

// A 4 by 4 quad in y = 0 with u = x/4, v = −z/4, wearing `texture`.
std::string quad(const std::string& texture) {
  return R"XML(<mesh positions="0 0 0  4 0 0  4 0 -4  0 0 -4" uvs="0 0  1 0  1 1  0 1"
      indices="0 1 2  0 2 3"><material ambient="1" diffuse="0">)XML" +
         texture + "</material></mesh>";
}

Color down(const Scene& scene, double x, double z) {
  World world(scene);
  return traceOne(world, Ray(Vec3(x, 2, z), Vec3(0, -1, 0)));
}

}  // namespace

TEST_CASE("uv mapping: a gradient reads the mesh's (u, v, 0) through its placement",
          "[render][uv-mapping]") {
  // At x = 1.5, z = −3: u = 0.375, v = 0.75; the object point's x is 1.5 (value 0.5).
  auto uvX = sceneOf(quad(R"X(<pattern type="gradient" axis="1 0 0" mapping="uv"/>)X"));
  auto uvY = sceneOf(quad(R"X(<pattern type="gradient" axis="0 1 0" mapping="uv"/>)X"));
  auto uvScaled = sceneOf(
      quad(R"X(<pattern type="gradient" axis="1 0 0" mapping="uv" transform="scale(0.5)"/>)X"));
  auto object = sceneOf(quad(R"X(<pattern type="gradient" axis="1 0 0"/>)X"));
  CHECK(down(*uvX, 1.5, -3).r == Approx(0.375).margin(1e-6));
  CHECK(down(*uvY, 1.5, -3).r == Approx(0.75).margin(1e-6));
  // scale(0.5): the pattern point is (u, v, 0)/0.5 = (0.75, 1.5, 0).
  CHECK(down(*uvScaled, 1.5, -3).r == Approx(0.75).margin(1e-6));
  CHECK(down(*object, 1.5, -3).r == Approx(0.5).margin(1e-6));
}

TEST_CASE("uv mapping: a checker on a sphere follows the sphere's longitude and latitude",
          "[render][uv-mapping]") {
  auto scene = sceneOf(R"XML(<sphere radius="1"><material ambient="1" diffuse="0">
      <pattern type="gradient" axis="1 0 0" mapping="uv"/></material></sphere>
      <sphere radius="1" center="4 0 0"><material ambient="1" diffuse="0">
      <pattern type="gradient" axis="0 1 0" mapping="uv"/></material></sphere>)XML");
  World world(*scene);
  for (const Vec3& dir : {Vec3(0.3, 0.4, 0.866), Vec3(-0.7, -0.2, 0.5), Vec3(0.1, 0.9, -0.4)}) {
    const Vec3 n = glm::normalize(dir);
    // POV-Ray's sphere in its space (z negated): u the turn from +x towards its +z, v
    // 0.5 + the latitude over π.
    const double u = std::atan2(-n.z, n.x) / (2.0 * M_PI);
    const double v = 0.5 + std::asin(n.y) / M_PI;
    INFO("direction " << n.x << " " << n.y << " " << n.z);
    CHECK(traceOne(world, Ray(3.0 * n, -n)).r == Approx(u - std::floor(u)).margin(1e-5));
    CHECK(traceOne(world, Ray(Vec3(4, 0, 0) + 3.0 * n, -n)).r == Approx(v).margin(1e-5));
  }
}

TEST_CASE("uv mapping: on a shape without (u,v) the point is the world's x and y",
          "[render][uv-mapping]") {
  // POV-Ray's default UVCoord: the intersection point's x and y, in the world.
  auto scene = sceneOf(R"XML(<cylinder base="0 -1 0" cap="0 1 0" radius="1"
      transform="translate(0.25 0 0)"><material ambient="1" diffuse="0">
      <pattern type="gradient" axis="1 0 0" phase="0.3" mapping="uv"/></material></cylinder>
      <cylinder base="0 -1 0" cap="0 1 0" radius="1" transform="translate(0 0 -5)">
      <material ambient="1" diffuse="0">
      <pattern type="gradient" axis="0 1 0" mapping="uv"/></material></cylinder>)XML");
  World world(*scene);
  // The top cap at world x 0.45: 0.45 + 0.3.
  CHECK(traceOne(world, Ray(Vec3(0.45, 5, 0.1), Vec3(0, -1, 0))).r == Approx(0.75).margin(1e-6));
  // The side at world x 0.25 + 1 (z 0): 1.25 + 0.3 wraps to 0.55.
  CHECK(traceOne(world, Ray(Vec3(5, 0.3, 0), Vec3(-1, 0, 0))).r == Approx(0.55).margin(1e-6));
  // The second cylinder's side at world y 0.4.
  CHECK(traceOne(world, Ray(Vec3(5, 0.4, -5), Vec3(-1, 0, 0))).r == Approx(0.4).margin(1e-6));
}

TEST_CASE("uv mapping: a normal bent at (u, v, 0) equals the object mapping where they agree",
          "[render][uv-mapping]") {
  // A quad in z = 0 whose (u, v) are its (x, y): the object point and (u, v, 0) agree.
  auto wall = [&](const std::string& uvs, const std::string& mapping) {
    return sceneOf(R"XML(<light type="point" position="0.3 0.8 3"/>
      <mesh positions="0 0 0  1 0 0  1 1 0  0 1 0" uvs=")XML" +
                   uvs +
                   R"XML(" indices="0 1 2  0 2 3"><material diffuse="1">
      <normal type="bumps" depth="1" transform="scale(0.1)" )XML" +
                   mapping + "/></material></mesh>");
  };
  auto object = wall("0 0  1 0  1 1  0 1", "");
  auto uv = wall("0 0  1 0  1 1  0 1", R"X(mapping="uv")X");
  auto shifted = wall("0.37 0  1.37 0  1.37 1  0.37 1", R"X(mapping="uv")X");
  World a(*object), b(*uv), c(*shifted);
  int differ = 0;
  for (double x : {0.21, 0.48, 0.77})
    for (double y : {0.13, 0.52, 0.91}) {
      const Ray r(Vec3(x, y, 2), Vec3(0, 0, -1));
      CHECK(traceOne(a, r) == traceOne(b, r));
      if (std::abs(traceOne(a, r).r - traceOne(c, r).r) > 1e-3f) ++differ;
    }
  CHECK(differ >= 6);
}

TEST_CASE("uv mapping: a material map picks its entries at (u, v, 0)", "[render][uv-mapping]") {
  // A checker of uv cells of 0.25, moved off the plane z = 0 of its cells' boundaries.
  auto scene = sceneOf(R"XML(<mesh positions="0 0 0  4 0 0  4 0 -4  0 0 -4"
      uvs="0 0  1 0  1 1  0 1" indices="0 1 2  0 2 3"><material><material-map>
      <checker scale="0.25" mapping="uv" transform="translate(0 0 -0.1)"/>
      <entry at="0"><material ambient="1 0 0"/></entry>
      <entry at="1"><material ambient="0 0 1"/></entry></material-map></material></mesh>)XML");
  World world(*scene);
  // u = 0.375, v = 0.575: the cell (1, 2, 0) is odd; u = 0.125: the cell (0, 2, 0) is even.
  CHECK(traceOne(world, Ray(Vec3(1.5, 2, -2.3), Vec3(0, -1, 0))) == Color(0, 0, 1));
  CHECK(traceOne(world, Ray(Vec3(0.5, 2, -2.3), Vec3(0, -1, 0))) == Color(1, 0, 0));
}

namespace {

// POV-Ray's slope estimate (normal.cpp, Perturb_Normal, read as facts) of `gradient x` at a
// pattern point p with the default accuracy 0.02, written out here: the four values at p +
// 0.02·d for its tetrahedron's directions d, each pushing the normal along d by
// value·depth·−5.
Vec3 gradientXBend(const Vec3& p, double depth) {
  const Vec3 d[4] = {{0.942809041, -0.333333333, 0.0},
                     {-0.471404521, -0.333333333, 0.816496581},
                     {-0.471404521, -0.333333333, -0.816496581},
                     {0.0, 1.0, 0.0}};
  Vec3 push(0.0);
  for (const Vec3& di : d) {
    const double x = p.x + 0.02 * di.x;
    push += (x - std::floor(x)) * depth * -5.0 * di;
  }
  return push;
}

NormalSpec uvGradient(bool world, const Mat4& placement) {
  NormalSpec n;
  n.pattern.type = PatternType::gradient;
  n.pattern.axis = Vec3(1, 0, 0);
  n.depth = 0.5;
  n.keepFacingAway = true;
  n.pattern.placement.uv = true;
  n.pattern.placement.patternFromObject = placement;
  n.bendInWorld = world;
  return n;
}

}  // namespace

TEST_CASE("uv mapping: bend-space world bends the world normal, object the object's",
          "[render][uv-mapping][normal]") {
  SurfaceInfo s;
  s.hasMappedUV = true;
  s.mappedUV = Vec2(0.3, 0.55);
  const Vec3 q(0.3, 0.55, 0.0);  // the pattern point (u, v, 0)
  const Vec3 view(0.0, 0.0, 1.0);
  // A shape turned 40 degrees about y: its world normal (0, 0, 1) is (sin 40, 0, cos 40) in
  // its object space.
  const double a = glm::radians(40.0);
  const Transform turned = *Transform::fromMatrix(glm::rotate(Mat4(1.0), a, Vec3(0, 1, 0)));
  const Vec3 n(0.0, 0.0, 1.0);

  // World: the world normal bent in the pattern's axes, whatever the shape's transform.
  const Vec3 world = perturbedShadingNormal(uvGradient(true, Mat4(1.0)), turned, s, n, view);
  const Vec3 wantWorld = glm::normalize(n + gradientXBend(q, 0.5));
  CHECK(glm::length(world - wantWorld) < 1e-9);

  // Object: bent in the object space, then turned back into the world.
  const Vec3 object = perturbedShadingNormal(uvGradient(false, Mat4(1.0)), turned, s, n, view);
  const Vec3 nObject(-std::sin(a), 0.0, std::cos(a));  // R^T n
  const Vec3 wantObject = Mat3(glm::rotate(Mat4(1.0), a, Vec3(0, 1, 0))) *
                          glm::normalize(nObject + gradientXBend(q, 0.5));
  CHECK(glm::length(object - wantObject) < 1e-9);
  CHECK(glm::length(world - object) > 1e-3);

  // The placement carries the world normal into pattern space (its inverse transpose) and
  // back: with the mirror S, the bend's z follows the mirrored axis, (u, v, 0) unmoved.
  Mat4 mirror(1.0);
  mirror[2][2] = -1.0;
  const Vec3 tilted = glm::normalize(Vec3(0.2, 0.1, 1.0));
  const Vec3 mirrored =
      perturbedShadingNormal(uvGradient(true, mirror), Transform(), s, tilted, view);
  const Vec3 inPattern = glm::normalize(Vec3(tilted.x, tilted.y, -tilted.z));
  const Vec3 bent = glm::normalize(inPattern + gradientXBend(q, 0.5));
  CHECK(glm::length(mirrored - glm::normalize(Vec3(bent.x, bent.y, -bent.z))) < 1e-9);
}

TEST_CASE("uv mapping: an entry of a pigment map reads (u, v, 0), not its map's point",
          "[render][uv-mapping][pigment-map]") {
  // The map's gradient along x (scale 8) hands its entries the point (x/8, 0, z/8); its
  // value x/8 blends a uv-mapped gradient along x of (u, v, 0) = (x/4, −z/4, 0) (first
  // entry) with red. At x = 1.5, z = −3: u = 0.375, v = 0.75, the map's value 0.1875.
  auto scene = sceneOf(quad(R"X(<pattern type="gradient" axis="1 0 0" transform="scale(8)">
    <pigment-map><entry at="0"><pattern type="gradient" axis="0 1 0" mapping="uv"/></entry>
    <entry at="1" color="1 0 0"/></pigment-map></pattern>)X"));
  const double value = 1.5 / 8.0;
  const Color c = down(*scene, 1.5, -3);
  // The first entry's grey is v = 0.75; the map's point would have given y = 0.
  CHECK(c.g == Approx((1.0 - value) * 0.75).margin(1e-6));
  CHECK(c.r == Approx((1.0 - value) * 0.75 + value).margin(1e-6));
  // A checker's listed pigment, uv-mapped and scaled: the cell of (u, v) / 0.25. (The quad
  // lies in the big checker's cell [0, 100) x [0, 100) x [-100, 0), its second entry's.)
  auto listed = sceneOf(quad(R"X(<checker scale="100"><pigment-list><entry color="0 0 1"/>
    <entry><checker mapping="uv" transform="scale(0.25)" color1="1 1 1" color2="0 0 0"/></entry>
    </pigment-list></checker>)X"));
  for (double x : {0.3, 1.3, 2.7})
    for (double z : {-0.4, -1.6, -3.1}) {
      const double u = x / 4.0, v = -z / 4.0;
      const int cell =
          (static_cast<int>(std::floor(u / 0.25)) + static_cast<int>(std::floor(v / 0.25))) & 1;
      CHECK(down(*listed, x, z).r == (cell == 0 ? 1.0f : 0.0f));
    }
}
