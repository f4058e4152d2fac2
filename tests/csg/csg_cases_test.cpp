// The bounding cases of CSG through real scenes: which child's material and normal a hit
// carries (outer surface, carved surface, nested twice), a lens made as an intersection
// refracting as the analytic lens does, and shadows through transparent CSG filtered once
// per crossing (union keeps the inner walls, merge removes them).
#include "../render/scene_builder.h"

#include "../support/scene_text.h"
#include "app/image_output.h"
#include "csg/csg_node.h"
#include "lang/parser.h"

#include <catch2/catch.hpp>

#include <filesystem>

#include <unistd.h>

using namespace lucent;
using namespace lucent::test;

namespace {

std::unique_ptr<Scene> parse(const std::string& body) {
  return parseValid(body, "cases.xml", R"XML(<camera/>
      <material id="red" diffuse="1 0 0"/>
      <material id="green" diffuse="0 1 0"/>
      <material id="blue" diffuse="0 0 1"/>
      <material id="white" diffuse="1"/>)XML");
}

struct Seen {
  bool found = false;
  double t = 0;
  Vec3 ng{0.0};
  std::string material;  // the id of the hit's material ("" for the default)
};

Seen look(const Scene& scene, const World& world, const Ray& ray) {
  Seen s;
  Hit h;
  if (!world.intersect(ray, h)) return s;
  s.found = true;
  s.t = h.t;
  s.ng = h.shape->surface(ray, h).ng;
  const Material& m = world.material(h);
  for (size_t i = 0; i < scene.materials.size(); ++i)
    if (&scene.materials[i] == &m) s.material = scene.materials[i].id;
  return s;
}

}  // namespace

TEST_CASE("CSG hit materials: the child's own wins, else the CSG node's, nested too", "[csg]") {
  // outer = box [-1,1]^3 minus inner; inner = box C (inherits blue) minus box D (green):
  // the cavity x in [0, 0.5] inside the box, bounded by D at x = 0.5 (subtracted twice,
  // so its own normal -x is flipped twice) and by C at x = 0 (subtracted once).
  auto scene = parse(R"XML(
    <difference material="red">
      <box min="-1 -1 -1" max="1 1 1"/>
      <difference material="blue">
        <box min="0 -0.5 -0.5" max="2 0.5 0.5"/>
        <box min="0.5 -2 -2" max="2 2 2" material="green"/>
      </difference>
    </difference>)XML");
  World world(*scene);

  // The outer surface: the first child's face x = 1, the node's material.
  Seen outer = look(*scene, world, Ray(Vec3(3, 0.1, 0.1), Vec3(-1, 0, 0)));
  REQUIRE(outer.found);
  CHECK(outer.t == Approx(2.0));
  CHECK(outer.ng == Vec3(1, 0, 0));
  CHECK(outer.material == "red");

  // From inside the solid towards -x: leaving it into the cavity at x = 0.5, on D's face;
  // the result's outward normal there points into the cavity, -x.
  Seen carved = look(*scene, world, Ray(Vec3(0.8, 0.1, 0.1), Vec3(-1, 0, 0)));
  REQUIRE(carved.found);
  CHECK(carved.t == Approx(0.3));
  CHECK(carved.ng.x == Approx(-1.0));
  CHECK(carved.material == "green");

  // From inside the cavity towards -x: the cavity's far wall x = 0 is C's face, inherited
  // blue from the inner node; its normal faces into the cavity, +x.
  Seen wall = look(*scene, world, Ray(Vec3(0.25, 0.1, 0.1), Vec3(-1, 0, 0)));
  REQUIRE(wall.found);
  CHECK(wall.t == Approx(0.25));
  CHECK(wall.ng.x == Approx(1.0));
  CHECK(wall.material == "blue");

  // From the solid down into the cavity through its top, C's face y = 0.5 (+y for C,
  // flipped once as inner is subtracted): the result's outward normal points down, -y.
  Seen top = look(*scene, world, Ray(Vec3(0.25, 0.8, 0.1), Vec3(0, -1, 0)));
  REQUIRE(top.found);
  CHECK(top.t == Approx(0.3));
  CHECK(top.ng.y == Approx(-1.0));
  CHECK(top.material == "blue");
}

TEST_CASE("CSG hit materials in an intersection and a union of own and inherited", "[csg]") {
  auto scene = parse(R"XML(
    <intersection material="red" transform="translate(-3 0 0)">
      <sphere radius="1"/>
      <box min="-2 -2 -2" max="0.5 2 2" material="green"/>
    </intersection>
    <union material="blue" transform="translate(3 0 0)">
      <sphere radius="1" material="white"/>
      <box min="0.5 -0.5 -0.5" max="1.5 0.5 0.5"/>
    </union>)XML");
  World world(*scene);
  // The intersection's flat side x = -2.5 is the box's (green), its round side the
  // sphere's (inherited red).
  Seen flat = look(*scene, world, Ray(Vec3(0, 0, 0), Vec3(-1, 0, 0)));
  CHECK(flat.material == "green");
  CHECK(flat.ng.x == Approx(1.0));
  Seen round = look(*scene, world, Ray(Vec3(-3, 0, 5), Vec3(0, 0, -1)));
  CHECK(round.material == "red");
  CHECK(round.ng.z == Approx(1.0));
  // The union: the box pokes out of the sphere on the right (inherited blue).
  Seen box = look(*scene, world, Ray(Vec3(8, 0, 0), Vec3(-1, 0, 0)));
  CHECK(box.material == "blue");
  CHECK(box.t == Approx(3.5));
  Seen sphere = look(*scene, world, Ray(Vec3(3, 5, 0), Vec3(0, -1, 0)));
  CHECK(sphere.material == "white");
}

namespace {

// A 2 x 1 float image (0 and 1): bilinear interpolation makes its value a linear ramp
// between the pixel centres, so a texture lookup measures where a ray landed (as in
// tests/render/transmission_test.cpp).
std::string writeRamp() {
  auto path = std::filesystem::temp_directory_path() /
              ("lucent-csg-ramp-" + std::to_string(::getpid()) + ".exr");
  Image ramp(2, 1);
  ramp.at(0, 0) = Color(0.0f);
  ramp.at(1, 0) = Color(1.0f);
  writeImageFile(ramp, path.string());
  return path.string();
}
constexpr double kRampScale = 60.0;
double landingX(const Color& c) { return kRampScale * (c.r + 0.5) / 2.0; }

// Snell's law in vector form (Heckbert), n facing the incoming direction d (unit).
Vec3 refract(const Vec3& d, const Vec3& n, double eta) {
  double c = -glm::dot(d, n);
  double k = 1.0 - eta * eta * (1.0 - c * c);
  REQUIRE(k >= 0.0);
  return glm::normalize(eta * d + (eta * c - std::sqrt(k)) * n);
}

// The far (second) or near root of |o + t d - c| = r for unit d.
double sphereRoot(const Vec3& o, const Vec3& d, const Vec3& c, double r, bool far) {
  Vec3 oc = o - c;
  double b = glm::dot(oc, d), q = glm::dot(oc, oc) - r * r;
  double disc = b * b - q;
  REQUIRE(disc > 0.0);
  return far ? -b + std::sqrt(disc) : -b - std::sqrt(disc);
}

}  // namespace

TEST_CASE("a lens made as the intersection of two spheres refracts as the analytic lens",
          "[csg][refraction]") {
  // Biconvex lens: spheres of radius 2 centred 1.6 behind and in front of (30, 0, 0);
  // rays parallel to the axis from z = 5 land on a ramp wall at z = -10.
  const std::string ramp = writeRamp();
  const double n = 1.5, R = 2.0;
  const Vec3 cFront(30, 0, -1.6), cBack(30, 0, 1.6);
  Scene scene;
  scene.render.ambient = Color(1.0f);
  Material wall;
  wall.ambient = Color(1.0f);
  wall.ambientIsScalar = true;
  ImageTexture image;
  image.path = ramp;
  image.scale = Vec2(kRampScale, 1.0);
  wall.texture = image;
  addShape(scene, PlaneSpec{Vec3(0, 0, 1), -10.0}, addMaterial(scene, wall));
  Material glass;
  glass.transmissive = Color(1.0f);
  glass.ior = n;
  auto lens = std::make_unique<Node>();
  lens->kind = NodeKind::Intersection;
  lens->element = "intersection";
  lens->material = addMaterial(scene, glass);
  lens->children.push_back(shapeNode(SphereSpec{cFront, R}, std::nullopt));
  lens->children.push_back(shapeNode(SphereSpec{cBack, R}, std::nullopt));
  scene.root->children.push_back(std::move(lens));
  World world(scene);

  for (double h : {0.0, 0.2, 0.5, -0.7}) {
    // The reference path: in through the front cap (sphere around cFront), out through
    // the back cap (sphere around cBack, from inside it).
    Vec3 o(30 + h, 0, 5), d(0, 0, -1);
    Vec3 p1 = o + sphereRoot(o, d, cFront, R, false) * d;
    Vec3 d1 = refract(d, glm::normalize(p1 - cFront), 1.0 / n);
    Vec3 p2 = p1 + sphereRoot(p1, d1, cBack, R, true) * d1;
    Vec3 d2 = refract(d1, -glm::normalize(p2 - cBack), n);
    double x = p2.x + (-10.0 - p2.z) / d2.z * d2.x;
    INFO("h = " << h);
    CHECK(landingX(traceOne(world, Ray(o, d))) == Approx(x).margin(1e-4));
    // Not the wall straight behind: the lens bends every ray off the axis but the axis.
    if (h != 0.0) CHECK(std::abs(x - (30 + h)) > 0.1);
  }
  std::filesystem::remove(ramp);
}

TEST_CASE("shadows through transparent CSG: one filter per crossing, union 4 and merge 2",
          "[csg][shadow]") {
  // Two overlapping clear spheres straight between a floor point and a light above it:
  // the shadow ray crosses the union's four surfaces but the merge's two.
  for (std::string op : {"union", "merge", "intersection", "difference"}) {
    auto scene = parse(R"XML(
      <material id="clear" transmissive="0.5" ior="1.5"/>
      <light position="0 10 0"/>
      <plane normal="0 1 0" offset="0" material="white"/>
      <)XML" + op + R"XML( material="clear">
        <sphere center="0 3 0" radius="1"/>
        <sphere center="0 4 0" radius="1"/>
      </)XML" + op + ">");
    World world(*scene);
    Color c = traceOne(world, Ray(Vec3(0, 1, 3), glm::normalize(Vec3(0, -1, -3))));
    // union: 4 crossings; merge: 2; intersection (the lens y in [3, 4]): 2; difference
    // (the lower sphere minus the upper: y in [2, 3]): 2.
    const int crossings = op == "union" ? 4 : 2;
    INFO(op);
    CHECK(c.r == Approx(std::pow(0.5, crossings)).epsilon(1e-6));
  }
}
