// Valid scenes (tests/lang/valid/) parse into the graph they describe: node kinds and
// counts, every attribute's value, parameters, includes, defs/use, inherited materials
// (through the World's instances) and world transforms against hand-computed matrices.
#include "lang/parser.h"
#include "scenegraph/scene_summary.h"
#include "scenegraph/world.h"
#include "valid_scene_loading.h"

#include <catch2/catch.hpp>

#include <filesystem>

namespace fs = std::filesystem;
using namespace lucent;

namespace {

using testing::load;
using testing::messages;
using testing::validDir;

bool close(const Vec3& a, const Vec3& b, double tol = 1e-12) { return glm::length(a - b) <= tol; }
bool close(const Mat4& a, const Mat4& b, double tol = 1e-12) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (std::abs(a[c][r] - b[c][r]) > tol) return false;
  return true;
}
bool close(const Mat3& a, const Mat3& b, double tol = 1e-12) {
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      if (std::abs(a[c][r] - b[c][r]) > tol) return false;
  return true;
}

// A matrix written row by row as on paper (glm stores columns).
Mat4 rows(std::initializer_list<double> v) {
  Mat4 m(0.0);
  auto it = v.begin();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[c][r] = *it++;
  return m;
}
Mat3 rows3(std::initializer_list<double> v) {
  Mat3 m(0.0);
  auto it = v.begin();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m[c][r] = *it++;
  return m;
}

const Node& child(const Node& n, size_t i) {
  REQUIRE(i < n.children.size());
  return *n.children[i];
}

template <class T>
const T& spec(const Node& n) {
  REQUIRE(n.kind == NodeKind::Shape);
  REQUIRE(n.shape);
  REQUIRE(std::holds_alternative<T>(*n.shape));
  return std::get<T>(*n.shape);
}

uint32_t materialIndex(const Scene& s, const std::string& id) {
  for (uint32_t i = 0; i < s.materials.size(); ++i)
    if (s.materials[i].id == id) return i;
  FAIL("no material " << id);
  return 0;
}

}  // namespace

TEST_CASE("lang: the contract's example scene parses into its graph", "[lang][valid]") {
  auto s = load("basic.xml");
  CHECK(s->render.width == 640);
  CHECK(s->render.height == 480);
  CHECK(s->render.samples == 4);
  CHECK(s->render.maxDepth == 5);
  CHECK(s->render.minWeight == 0.0039);
  REQUIRE(s->cameras.size() == 1);
  CHECK(s->cameras[0].position == Vec3(0, 2, 6));
  CHECK(s->cameras[0].lookAt == Vec3(0, 0.5, 0));
  CHECK(s->cameras[0].fov == 50.0);
  REQUIRE(s->lights.size() == 1);
  CHECK(s->lights[0].type == LightType::Point);
  CHECK(s->lights[0].position == Vec3(5, 8, 5));

  // default, brick, glass, the plane's inline material
  REQUIRE(s->materials.size() == 4);
  CHECK(s->materials[0].diffuse == Color(0.8f));
  const Material& brick = s->materials[materialIndex(*s, "brick")];
  CHECK(brick.ambient == Color(0.1f, 0.03f, 0.02f));
  CHECK_FALSE(brick.ambientIsScalar);
  CHECK(brick.shininess == 50.0);

  const Node& root = *s->root;
  REQUIRE(root.children.size() == 3);
  const Node& plane = child(root, 0);
  CHECK(spec<PlaneSpec>(plane).normal == Vec3(0, 1, 0));
  REQUIRE(plane.material);
  const Material& floor = s->materials[*plane.material];
  REQUIRE(std::holds_alternative<CheckerTexture>(floor.texture));
  CHECK(std::get<CheckerTexture>(floor.texture).color2 == Color(0.2f));
  CHECK(floor.diffuse == Color(1.0f));

  const Node& diff = child(root, 1);
  CHECK(diff.kind == NodeKind::Difference);
  CHECK(diff.material == materialIndex(*s, "brick"));
  CHECK(spec<BoxSpec>(child(diff, 0)).max == Vec3(1.0));
  CHECK(spec<SphereSpec>(child(diff, 1)).radius == 1.3);
  CHECK_FALSE(child(diff, 0).material);  // inherited, resolved by World

  SceneCounts c = countScene(*s);
  CHECK(c.nodes ==
        std::map<std::string, int>{{"box", 1}, {"difference", 1}, {"plane", 1}, {"sphere", 2}});
  CHECK(c.instances == 4);
  CHECK(c.csgDepth == 1);
  CHECK(sceneSummary(*s) == "scene: " + (validDir() / "basic.xml").string() +
                                "\n"
                                "image: 640x480, 4 samples per pixel, max depth 5\n"
                                "cameras: 1 (pinhole: 1)\n"
                                "lights: 1 (point: 1)\n"
                                "materials: 3\n"
                                "nodes: 5 (box: 1, difference: 1, plane: 1, sphere: 2)\n"
                                "instances: 4\n"
                                "triangles: 0\n"
                                "csg depth: 1\n");
}

TEST_CASE("lang: every camera type keeps its own attributes and the common defaults",
          "[lang][valid]") {
  auto s = load("cameras.xml");
  REQUIRE(s->cameras.size() == 15);
  const Camera& main = *s->findCamera("main");
  CHECK(main.type == CameraType::Pinhole);
  CHECK(main.fov == 50.0);
  CHECK(main.fovAxis == FovAxis::Vertical);
  CHECK(main.near == 0.1);
  CHECK(main.far == 100.0);

  const Camera& dof = *s->findCamera("dof");
  CHECK(dof.type == CameraType::ThinLens);
  CHECK(dof.focalLength == 0.035);
  CHECK(dof.fStop == 1.4);
  CHECK(dof.focusDistance == 4.0);
  CHECK(dof.fov == 60.0);
  CHECK(dof.far == kInf);

  const Camera& top = *s->findCamera("top");
  CHECK(top.type == CameraType::Orthographic);
  CHECK(top.width == 12.0);
  CHECK(top.up == Vec3(0, 0, -1));

  const Camera& sky = *s->findCamera("sky");
  CHECK(sky.mapping == FisheyeMapping::Equisolid);
  CHECK(sky.fov == 360.0);

  const Camera& pan = *s->findCamera("pan");
  CHECK(pan.distance == 0.5);
  CHECK(pan.verticalCompression == 0.25);
  CHECK(pan.fov == 170.0);

  const Camera& lf = *s->findCamera("lf");
  CHECK(lf.lensesX == 8);
  CHECK(lf.lensesY == 6);
  CHECK(lf.pitch == 0.05);

  CHECK(s->findCamera("oct")->type == CameraType::Octahedral);
  CHECK(s->findCamera("cube")->layout == CubemapLayout::Strip);
  const Camera& fib = *s->findCamera("fib");
  CHECK(fib.type == CameraType::Fibonacci);
  CHECK(fib.position == Vec3(0.0));
  CHECK(fib.lookAt == Vec3(0, 0, -1));
  CHECK(fib.transform == rows({1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 0, 0, 0, 0, 1}));
  // v-angle is half of h-angle unless given.
  const Camera& pano = *s->findCamera("pano");
  CHECK(pano.type == CameraType::Spherical);
  CHECK(pano.hAngle == 200.0);
  CHECK(pano.vAngle == 100.0);
  const Camera& band = *s->findCamera("band");
  CHECK(band.hAngle == 360.0);
  CHECK(band.vAngle == 60.0);
  const Camera& uwa = *s->findCamera("uwa");
  CHECK(uwa.type == CameraType::UltraWideAngle);
  CHECK(uwa.fov == 220.0);
  CHECK(uwa.frameAspect == 1.5);
  const Camera& cyl = *s->findCamera("cyl");
  CHECK(cyl.type == CameraType::Cylinder);
  CHECK(cyl.cylinderType == 3);
  CHECK(cyl.sweep == 200.0);
  CHECK(cyl.axisLength == 4.0);
  const Camera& gg3 = *s->findCamera("gg3");
  CHECK(gg3.type == CameraType::Panoramic);
  CHECK(gg3.rightLength == 1.33);
  CHECK(gg3.upLength == 0.75);
  CHECK(s->findCamera("dome")->type == CameraType::Omnimax);
  CHECK(s->findCamera("") == &s->cameras[0]);
}

TEST_CASE("lang: lights: types, defaults, normalised directions, spot look-at, area grids",
          "[lang][valid]") {
  auto s = load("lights.xml");
  REQUIRE(s->lights.size() == 6);
  const Light& point = s->lights[0];
  CHECK(point.type == LightType::Point);
  CHECK(point.position == Vec3(1, 2, 3));
  CHECK(point.color == Color(1.0f));
  CHECK(point.intensity == 1.0);
  CHECK(point.attenuation == Vec3(1, 0, 0));
  CHECK(point.shadows);

  const Light& sun = s->lights[1];
  CHECK(sun.type == LightType::Directional);
  CHECK(sun.direction == Vec3(0, -1, 0));
  CHECK(sun.color == Color(1.0f));  // #ffffff decodes to exactly 1
  CHECK(sun.radiance() == Color(0.5f));
  CHECK_FALSE(sun.shadows);

  const Light& spot = s->lights[2];
  CHECK(spot.type == LightType::Spot);
  CHECK(close(spot.direction, glm::normalize(Vec3(0, -6, 3))));
  CHECK(spot.angle == 25.0);
  CHECK(spot.inner == 25.0);  // defaults to angle
  CHECK(spot.attenuation == Vec3(1, 0, 0.02));

  const Light& spot2 = s->lights[3];
  CHECK(spot2.direction == Vec3(1, 0, 0));
  CHECK(spot2.inner == 10.0);

  const Light& area = s->lights[4];
  CHECK(area.type == LightType::Area);
  CHECK(area.u == Vec3(2, 0, 0));
  CHECK(area.v == Vec3(0, 0, 1));
  CHECK(area.samplesU == 3);  // one number sets both
  CHECK(area.samplesV == 3);
  CHECK(area.jitter);
  CHECK_FALSE(area.adaptive);  // absent: every grid point, plainly averaged
  CHECK(s->lights[5].adaptive == 3);
  CHECK(s->lights[5].samplesU == 5);
  CHECK(s->lights[5].samplesV == 2);
  CHECK(s->lights[5].color == Color(0.5f));

  SceneCounts c = countScene(*s);
  CHECK(c.lights ==
        std::map<std::string, int>{{"area", 2}, {"directional", 1}, {"point", 1}, {"spot", 2}});
}

TEST_CASE("lang: materials: every attribute, textures and the texture defaults", "[lang][valid]") {
  auto s = load("materials.xml");
  REQUIRE(s->materials.size() == 7);
  const Material& all = s->materials[materialIndex(*s, "all")];
  CHECK(all.emissive == Color(0.1f, 0.2f, 0.3f));
  CHECK(all.ambient == Color(0.05f));
  CHECK(all.ambientIsScalar);
  CHECK(all.diffuse == Color(0.5f, 0.6f, 0.7f));
  // #80 = 128/255 through the sRGB curve.
  CHECK(all.specular.r == Approx(0.2158605).epsilon(1e-6));
  CHECK(all.shininess == 120.0);
  CHECK(all.reflective == Color(0.25f));
  CHECK(all.transmissive == Color(0.5f, 0.5f, 0.0f));
  CHECK(all.ior == 1.33);
  CHECK(all.fresnel);
  CHECK(all.absorption == Color(0.2f, 1.8f, 1.4f));
  CHECK(all.phong == Color(0.5f, 0.4f, 0.3f));
  CHECK(all.phongSize == 12.5);
  CHECK(all.brilliance == 2.5);
  CHECK(all.metallic);
  CHECK_FALSE(all.hasTexture());

  const Material& checker = s->materials[materialIndex(*s, "checker")];
  REQUIRE(std::holds_alternative<CheckerTexture>(checker.texture));
  CHECK(std::get<CheckerTexture>(checker.texture).color1 == Color(1, 0, 0));
  CHECK(std::get<CheckerTexture>(checker.texture).scale == 0.5);
  CHECK(checker.diffuse == Color(1.0f));  // a texture with no diffuse shows as it is
  CHECK(checker.ambientIsScalar);

  const Material& dim = s->materials[materialIndex(*s, "checker-dim")];
  CHECK(dim.diffuse == Color(0.5f));
  CHECK_FALSE(dim.ambientIsScalar);
  CHECK(std::get<CheckerTexture>(dim.texture).color1 == Color(1.0f));
  CHECK(std::get<CheckerTexture>(dim.texture).color2 == Color(0.0f));

  const Material& image = s->materials[materialIndex(*s, "image")];
  REQUIRE(std::holds_alternative<ImageTexture>(image.texture));
  const ImageTexture& tex = std::get<ImageTexture>(image.texture);
  CHECK(tex.path == fs::canonical(validDir() / "textures" / "dot.png").string());
  CHECK(tex.scale == Vec2(2, 3));
  CHECK(std::get<ImageTexture>(s->materials[materialIndex(*s, "image1")].texture).scale ==
        Vec2(4, 4));

  const Material& empty = s->materials[materialIndex(*s, "empty")];
  CHECK(empty.diffuse == Color(0.0f));
  CHECK(empty.shininess == 64.0);
  CHECK(empty.ior == 1.0);
  // The finish defaults: no Phong highlight, size 40, brilliance 1, not metallic.
  CHECK(empty.phong == Color(0.0f));
  CHECK(empty.phongSize == 40.0);
  CHECK(empty.brilliance == 1.0);
  CHECK_FALSE(empty.metallic);
  CHECK_FALSE(empty.hasHighlight());
}

TEST_CASE("lang: shapes: every attribute, with normals normalised on load", "[lang][valid]") {
  auto s = load("shapes.xml");
  const Node& root = *s->root;
  REQUIRE(root.children.size() == 9);
  CHECK(spec<SphereSpec>(child(root, 0)).center == Vec3(1, 2, 3));
  CHECK(spec<SphereSpec>(child(root, 0)).radius == 0.5);
  CHECK(spec<BoxSpec>(child(root, 1)).min == Vec3(-1, 0, -2));
  const auto& cyl = spec<CylinderSpec>(child(root, 2));
  CHECK(cyl.cap == Vec3(0, 2, 0));
  CHECK(cyl.radius == 0.3);
  CHECK(cyl.open);
  CHECK_FALSE(child(root, 2).isSolid());
  const auto& cone = spec<ConeSpec>(child(root, 3));
  CHECK(cone.baseRadius == 0.8);
  CHECK(cone.capRadius == 0.4);
  CHECK_FALSE(cone.open);
  // A spindle torus (minor > major) is accepted, as POV-Ray accepts it.
  CHECK(spec<TorusSpec>(child(root, 4)).minor == 1.5);
  CHECK(spec<PlaneSpec>(child(root, 5)).normal == Vec3(0, 0, 1));
  CHECK(spec<PlaneSpec>(child(root, 5)).offset == -10.0);
  const auto& disc = spec<DiscSpec>(child(root, 6));
  CHECK(close(disc.normal, Vec3(0.6, 0, 0.8)));
  CHECK(disc.innerRadius == 0.5);
  const auto& tri = spec<TriangleSpec>(child(root, 7));
  CHECK(tri.c == Vec3(0, 1.5, 0));
  REQUIRE(tri.normals);
  CHECK((*tri.normals)[0] == Vec3(0, 0, 1));
  CHECK(close((*tri.normals)[1], Vec3(0, 0.6, 0.8)));
  CHECK(close((*tri.normals)[2], Vec3(std::sqrt(0.5), std::sqrt(0.5), 0)));
  const auto& tri2 = spec<TriangleSpec>(child(root, 8));
  CHECK(tri2.b == Vec3(1, 0, 0));  // commas and spaces mixed
  CHECK(tri2.c == Vec3(0, 1, 0));
  CHECK_FALSE(tri2.normals);
}

TEST_CASE("lang: parameters: $name, ${name}, nested values, use before declaration, -D wins",
          "[lang][valid]") {
  auto s = load("params.xml");
  CHECK(s->cameras[0].fov == 90.0);
  const Node& root = *s->root;
  const Node& ball = child(root, 0);
  CHECK(ball.id == "price$");  // $$ is a literal '$'
  CHECK(spec<SphereSpec>(ball).radius == 0.75);
  CHECK(spec<SphereSpec>(ball).center == Vec3(0, 0.75, 0));
  CHECK(s->materials[*ball.material].diffuse == Color(0.9f, 0.3f, 0.1f));
  CHECK(spec<BoxSpec>(child(root, 1)).max == Vec3(0.75));
  CHECK(spec<TorusSpec>(child(root, 2)).major == 0.755);  // "${r}5"
  CHECK(spec<TorusSpec>(child(root, 2)).minor == 0.25);
  CHECK(close(child(root, 2).parentFromNode,
              rows({0, 0, 1, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 0, 1})));

  ParseOptions d;
  d.defines = {{"r", "2"}, {"turn", "45"}};
  auto t = load("params.xml", d);
  CHECK(t->cameras[0].fov == 45.0);
  CHECK(spec<SphereSpec>(child(*t->root, 0)).radius == 2.0);
  CHECK(spec<BoxSpec>(child(*t->root, 1)).max == Vec3(2.0));  // d uses the -D value of r

  // A -D the scene never uses is a warning, not an error.
  ParseOptions unused;
  unused.defines = {{"radius", "3"}};
  ParseResult r = parseSceneFile((validDir() / "params.xml").string(), unused);
  REQUIRE(r.scene);
  REQUIRE(r.diagnostics.all().size() == 1);
  CHECK(r.diagnostics.all()[0].severity == Severity::Warning);
  CHECK(r.diagnostics.all()[0].message == "-D radius is not used by the scene");
}

TEST_CASE(
    "lang: includes: parameters, materials, lights and defs of included files, a diamond is "
    "inserted once",
    "[lang][valid]") {
  auto s = load("include_main.xml");
  REQUIRE(s->materials.size() == 3);  // default, gold, silver: materials.xml once
  REQUIRE(s->lights.size() == 1);
  const Node& root = *s->root;
  REQUIRE(root.children.size() == 2);
  CHECK(spec<SphereSpec>(child(root, 0)).radius == 0.5);
  CHECK(child(root, 0).material == materialIndex(*s, "gold"));
  const Node& use = child(root, 1);
  REQUIRE(use.target);
  CHECK(use.target->id == "pawn");
  CHECK(use.target->material == materialIndex(*s, "silver"));
  CHECK(spec<ConeSpec>(child(*use.target, 1)).baseRadius == 0.5);
  // Locations name the included file.
  CHECK(use.target->loc.file == (validDir() / "parts" / "pieces.xml").string());
  CHECK(use.target->loc.line == 5);
  CHECK(use.target->loc.col == 5);
}

TEST_CASE("lang: defs and use: targets, forward references, chains, world placement",
          "[lang][valid]") {
  auto s = load("defs_use.xml");
  const Node& root = *s->root;
  REQUIRE(root.children.size() == 7);
  REQUIRE(s->defs.size() == 1);
  const Node& column = *s->defs[0];
  CHECK(child(root, 1).target == &column);
  CHECK(child(root, 2).target == &child(root, 0));  // an ordinary node with an id
  CHECK(child(root, 3).target == &child(root, 4));  // declared after its use
  CHECK(child(root, 5).id == "again");
  CHECK(child(root, 5).target == &column);
  CHECK(child(root, 6).target == &child(root, 5));  // a use of a use

  World world(*s);
  const auto& leaves = world.leaves();
  REQUIRE(leaves.size() == 7);
  auto origin = [&](size_t i) { return leaves[i].instance->transform().pointToWorld(Vec3(0.0)); };
  CHECK(origin(0) == Vec3(0, 0, 0));  // ball
  CHECK(origin(1) == Vec3(5, 1, 0));  // column: its own translate, then the use's
  CHECK(origin(2) == Vec3(0, 0, 3));  // ball again
  CHECK(origin(3) == Vec3(0, 0, 0));  // later, through the forward use
  CHECK(origin(4) == Vec3(0, 0, 0));  // later itself
  CHECK(origin(5) == Vec3(0, 1, 0));  // again
  CHECK(origin(6) == Vec3(0, 2, 0));  // again, scaled by 2 after its translate
  CHECK(leaves[6].instance->transform().worldFromObject() ==
        rows({2, 0, 0, 0, 0, 2, 0, 2, 0, 0, 2, 0, 0, 0, 0, 1}));
  // one shape for every use of a node
  CHECK(&leaves[1].instance->shape() == &leaves[5].instance->shape());
}

TEST_CASE("lang: base= chains copy and override, default= replaces the default material",
          "[lang][valid]") {
  auto s = load("material_bases.xml");
  auto get = [&](const char* id) -> const Material& { return s->materials[materialIndex(*s, id)]; };
  const Material& red = get("red");
  // A forward reference: shiny-red comes before red in the file.
  const Material& shiny = get("shiny-red");
  CHECK(shiny.diffuse == Color(0.8f, 0.1f, 0.1f));
  CHECK(shiny.ambient == red.ambient);
  CHECK(shiny.phong == Color(0.3f));
  CHECK(shiny.specular == Color(0.5f));
  CHECK(shiny.shininess == 20.0);
  CHECK(shiny.id == "shiny-red");
  // Two steps: dull-red is shiny-red with specular 0, shininess still 20.
  const Material& dull = get("dull-red");
  CHECK(dull.specular == Color(0.0f));
  CHECK(dull.shininess == 20.0);
  CHECK(dull.diffuse == red.diffuse);
  // A texture added to a base whose diffuse was written keeps that diffuse ...
  const Material& checked = get("checked");
  REQUIRE(std::holds_alternative<CheckerTexture>(checked.texture));
  CHECK(std::get<CheckerTexture>(checked.texture).scale == 2.0);
  CHECK(checked.diffuse == red.diffuse);
  CHECK_FALSE(red.hasTexture());  // the base is unchanged
  // ... and to one whose diffuse was never written shows as it is.
  CHECK(get("tiled").diffuse == Color(1.0f));
  CHECK(get("tiled-dim").diffuse == Color(0.5f));
  CHECK(std::holds_alternative<CheckerTexture>(get("tiled-dim").texture));
  // A texture of its own replaces the base's; the diffuse written along the chain stays.
  const Material& other = get("tiled-other");
  CHECK(std::get<CheckerTexture>(other.texture).color1 == Color(0, 1, 0));
  CHECK(other.diffuse == Color(0.5f));
  // The default material: what shapes without a material get.
  const Material& def = s->materials[0];
  CHECK(def.diffuse == Color(0.3f));
  CHECK(def.phong == Color(0.3f));
  CHECK(def.ambient == red.ambient);
  const Node& root = *s->root;
  REQUIRE(root.children.size() == 3);
  CHECK_FALSE(child(root, 0).material.has_value());  // takes index 0, the default
  CHECK(child(root, 1).material == materialIndex(*s, "dull-red"));
  // An inline material with a base.
  const Material& inl = s->materials[*child(root, 2).material];
  CHECK(inl.ior == 1.5);
  CHECK(inl.diffuse == red.diffuse);
  CHECK(inl.id.empty());
}

TEST_CASE("lang: materials are inherited from the nearest group, CSG node or use",
          "[lang][valid]") {
  auto s = load("inheritance.xml");
  uint32_t brass = materialIndex(*s, "brass"), glass = materialIndex(*s, "glass"),
           stone = materialIndex(*s, "stone");
  // Named materials come first (declared after their uses here), then inline ones.
  REQUIRE(s->materials.size() == 6);
  CHECK(brass == 1);
  CHECK(glass == 2);
  CHECK(stone == 3);
  CHECK(s->materials[4].diffuse == Color(1, 0, 0));  // the cylinder's
  CHECK(s->materials[5].diffuse == Color(0, 1, 0));  // the last use's

  World world(*s);
  std::vector<uint32_t> tags;
  for (const WorldLeaf& leaf : world.leaves()) {
    tags.push_back(leaf.materialIndex);
    CHECK(leaf.material == &s->materials[leaf.materialIndex]);
  }
  CHECK(tags == std::vector<uint32_t>{0,  // bare sphere: the default
                                      brass, glass, 4,
                                      brass,         // group: sphere, box, cylinder, torus
                                      stone, glass,  // difference: box, sphere
                                      stone, glass,  // use with material
                                      0, glass,      // use without
                                      5, glass});    // use with inline material
}

TEST_CASE("lang: world transforms and normal matrices match hand-computed matrices",
          "[lang][valid]") {
  auto s = load("transforms.xml");
  // The graph keeps each node's own transform, in the order written.
  const Node& root = *s->root;
  CHECK(child(root, 0).parentFromNode == rows({0, 0, 1, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 0, 1}));
  CHECK(child(child(root, 0), 0).parentFromNode ==
        rows({1, 0, 0, 3, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}));

  World world(*s);
  std::vector<const Instance*> inst;
  for (const WorldLeaf& leaf : world.leaves()) inst.push_back(leaf.instance);
  REQUIRE(inst.size() == 8);
  auto world_ = [&](size_t i) { return inst[i]->transform().worldFromObject(); };
  auto normal = [&](size_t i) { return inst[i]->transform().normalToWorld(); };

  // translate(3 0 0) inside rotate-y(90): (3,0,0) turns to (0,0,-3); +x to -z, exactly.
  CHECK(world_(0) == rows({0, 0, 1, 0, 0, 1, 0, 0, -1, 0, 0, -3, 0, 0, 0, 1}));
  CHECK(normal(0) == rows3({0, 0, 1, 0, 1, 0, -1, 0, 0}));
  // scale(2) translate(0 1 0): centre (0,1,0), radius 2; normals scale by 1/2.
  CHECK(world_(1) == rows({2, 0, 0, 0, 0, 2, 0, 1, 0, 0, 2, 0, 0, 0, 0, 1}));
  CHECK(normal(1) == rows3({0.5, 0, 0, 0, 0.5, 0, 0, 0, 0.5}));
  // translate(0 1 0) scale(2): centre (0,2,0).
  CHECK(world_(2) == rows({2, 0, 0, 0, 0, 2, 0, 2, 0, 0, 2, 0, 0, 0, 0, 1}));
  // The shear x' = x + 0.5 y, y' = y + 1 with 12 and with 16 numbers; the normal matrix
  // is the inverse-transpose: rows (1 0 0), (-0.5 1 0), (0 0 1).
  Mat4 shear = rows({1, 0.5, 0, 0, 0, 1, 0, 1, 0, 0, 1, 0, 0, 0, 0, 1});
  CHECK(world_(3) == shear);
  CHECK(world_(4) == shear);
  CHECK(close(normal(3), rows3({1, 0, 0, -0.5, 1, 0, 0, 0, 1})));
  // scale(1 2 4) ∘ rotate-z(90) ∘ translate(1 0 0): columns x->(0,2,0), y->(-1,0,0),
  // z->(0,0,4), origin->(0,2,0); normal matrix S^-1 R: rows (0 -1 0), (0.5 0 0), (0 0 0.25).
  CHECK(world_(5) == rows({0, -1, 0, 0, 2, 0, 0, 2, 0, 0, 4, 0, 0, 0, 0, 1}));
  CHECK(close(normal(5), rows3({0, -1, 0, 0.5, 0, 0, 0, 0, 0.25})));
  CHECK(close(inst[5]->transform().objectFromWorld() * world_(5), Mat4(1.0)));
  // A 45° turn about the vertical axis through (2, 0, 1) keeps that point and carries the
  // origin to (2 - 3/√2, 0, 1 + 1/√2).
  const Transform& pivot = inst[6]->transform();
  CHECK(close(pivot.pointToWorld(Vec3(2, 0, 1)), Vec3(2, 0, 1)));
  double h = std::sqrt(0.5);
  CHECK(close(pivot.pointToWorld(Vec3(0, 0, 0)), Vec3(2 - 3 * h, 0, 1 + h)));
  // rotate(120, 1 1 1) permutes the axes: x -> y -> z -> x.
  CHECK(close(world_(7), rows({0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1})));
}

TEST_CASE("lang: meshes: inline closed meshes are solids, normals and uvs kept, files read once",
          "[lang][valid]") {
  auto s = load("meshes.xml");
  const Node& root = *s->root;
  const Node& oct = child(child(root, 0), 1);
  const auto& octMesh = spec<MeshSpec>(oct);
  REQUIRE(octMesh.data);
  CHECK(octMesh.data->positions.size() == 6);
  CHECK(octMesh.data->triangles.size() == 8);
  CHECK(octMesh.data->closed);
  CHECK(oct.isSolid());

  const auto& quad = spec<MeshSpec>(child(root, 1));
  REQUIRE(quad.data);
  CHECK(quad.smooth == SmoothMode::False);
  CHECK_FALSE(quad.data->closed);
  REQUIRE(quad.data->normals.size() == 4);
  CHECK(quad.data->normals[0] == Vec3(0, 0, 1));  // normalised
  REQUIRE(quad.data->uvs.size() == 4);
  CHECK(quad.data->uvs[2] == Vec2(1, 1));

  const auto& cube1 = spec<MeshSpec>(child(root, 2));
  const auto& cube2 = spec<MeshSpec>(child(child(root, 3), 0));
  CHECK(cube1.src == "meshes/cube.obj");
  CHECK(cube1.smooth == SmoothMode::True);
  REQUIRE(cube1.data);
  CHECK(cube1.data->triangles.size() == 12);
  CHECK(cube1.data->closed);
  CHECK(cube1.data == cube2.data);  // the same file is read once
  CHECK(countScene(*s).triangles == 8 + 2 + 12 + 12);
}

TEST_CASE("lang: CSG: nested operations over groups, unions, uses and planes", "[lang][valid]") {
  auto s = load("csg.xml");
  SceneCounts c = countScene(*s);
  CHECK(c.csgDepth == 3);
  CHECK(c.instances == 11);
  CHECK(c.nodes["difference"] == 2);
  CHECK(c.nodes["union"] == 2);
  const Node& diff = child(*s->root, 0);
  CHECK(diff.kind == NodeKind::Difference);
  REQUIRE(diff.children.size() == 3);
  CHECK(child(diff, 0).kind == NodeKind::Intersection);
  CHECK(child(diff, 1).isSolid());  // a union of a sphere and a group of solids
  CHECK_FALSE(
      child(*s->root, 1).isSolid());  // a union of a disc and a triangle (allowed outside CSG)
  World world(*s);
  CHECK(world.leaves().size() == 11);
}

TEST_CASE("lang: warnings do not refuse a scene", "[lang][valid]") {
  ParseResult r = parseSceneFile((validDir() / "warnings.xml").string());
  INFO(messages(r));
  REQUIRE(r.scene);
  REQUIRE(r.diagnostics.all().size() == 2);
  CHECK_FALSE(r.diagnostics.hasErrors());
  CHECK(r.diagnostics.all()[0].str() ==
        (validDir() / "warnings.xml").string() +
            ":3:3: warning: <camera>: 'fov' has no effect on cameras of type orthographic (their "
            "'width' frames the image)");
  CHECK_THAT(r.diagnostics.all()[1].str(),
             Catch::EndsWith(
                 ":4:9: warning: <sphere> in <defs> has no id, so no <use> can instantiate it"));
  CHECK(spec<SphereSpec>(child(*r.scene->root, 0)).radius == 1.0);
}

TEST_CASE("lang: in-memory scenes: defaults of an almost empty scene", "[lang][valid]") {
  ParseResult r = parseSceneString(
      "<?xml version=\"1.0\"?>\n<scene version=\"1\"><camera/></scene>", "mem.xml");
  REQUIRE(r.scene);
  const Scene& s = *r.scene;
  CHECK(s.file == "mem.xml");
  CHECK(s.render.width == 640);
  CHECK(s.render.height == 480);
  CHECK(s.render.samples == 1);
  CHECK(s.render.background == Color(0.0f));
  CHECK(s.render.ambient == Color(1.0f));
  CHECK_FALSE(s.render.epsilon);
  const Camera& c = s.cameras[0];
  CHECK(c.type == CameraType::Pinhole);
  CHECK(c.position == Vec3(0.0));
  CHECK(c.lookAt == Vec3(0, 0, -1));
  CHECK(c.up == Vec3(0, 1, 0));
  CHECK(c.fov == 60.0);
  CHECK(c.fovAxis == FovAxis::Horizontal);
  CHECK(c.near == 0.0);
  CHECK(c.far == kInf);
  CHECK(s.materials.size() == 1);
  CHECK(s.root->children.empty());

  const std::string two =
      "<scene version=\"1\"><render epsilon=\"auto\" background=\"#000000\"/><camera "
      "far=\"+inf\"/><render/></scene>";
  ParseResult e = parseSceneString(two, "two.xml");
  CHECK_FALSE(e.scene);
  REQUIRE(e.diagnostics.errorCount() == 1);
  CHECK(e.diagnostics.all()[0].str() ==
        "two.xml:1:" + std::to_string(two.find("<render/>") + 1) +
            ": error: <render> is given twice (first at two.xml:1:20)");
}
