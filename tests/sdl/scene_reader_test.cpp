// The scene reader: POV-Ray scenes read from their text into Lucent scenes, checked field by
// field against the pov_* mappings, and the unsupported features listed, every one.
#include <catch2/catch.hpp>

#include "scene_read_support.h"
#include "sdl_test_support.h"

#include "sdl/console_text.h"
#include "sdl/scene_reader.h"

#include <fstream>
#include <sstream>
#include <variant>

using namespace lucent;
using namespace lucent::sdl;

namespace {

using sdltest::errorsOf;
using sdltest::readScene;

// The material index of each top-level object, in order (99 for none).
std::vector<uint32_t> topMaterials(const Scene& scene) {
  std::vector<uint32_t> m;
  for (const auto& n : scene.root->children) m.push_back(n->material.value_or(99));
  return m;
}

const Node& topNode(const Scene& scene, size_t i) {
  REQUIRE(scene.root->children.size() > i);
  return *scene.root->children[i];
}

const Material& materialOf(const Scene& scene, const Node& n) {
  REQUIRE(n.material);
  return scene.materials.at(*n.material);
}

void checkColor(const Color& got, const Color& want) {
  for (int c = 0; c < 3; ++c) CHECK(got[c] == Approx(want[c]).margin(1e-6));
}

using sdltest::checkMat;
using sdltest::checkVec;

}  // namespace

TEST_CASE("scene reader: the simple shapes, in Lucent's space", "[sdl][scene]") {
  auto r = readScene(R"(
sphere { <1, 2, 3>, 0.5 }
box { <1, 2, 3>, <-1, 0, -2> }
plane { <0, 2, 0>, 3 }
cylinder { <0, 0, 1>, <0, 2, 1>, 0.25 open }
cone { <0, 0, 0>, 1, <0, 0, 2>, 0.5 }
torus { 2, 0.5 }
disc { <0, 1, 2>, <0, 0, 3>, 2, 1 }
triangle { <0, 0, 1>, <1, 0, 1>, <0, 1, 2> }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  REQUIRE(s.root->children.size() == 8);
  const auto& sphere = std::get<SphereSpec>(*topNode(s, 0).shape);
  checkVec(sphere.center, Vec3(1, 2, -3));
  CHECK(sphere.radius == 0.5);
  const auto& box = std::get<BoxSpec>(*topNode(s, 1).shape);
  checkVec(box.min, Vec3(-1, 0, -3));
  checkVec(box.max, Vec3(1, 2, 2));
  const auto& plane = std::get<PlaneSpec>(*topNode(s, 2).shape);
  checkVec(plane.normal, Vec3(0, 1, 0));
  // POV-Ray makes the normal unit and keeps the distance (plane_normal_length.pov holds
  // its image to it).
  CHECK(plane.offset == 3.0);
  const auto& cylinder = std::get<CylinderSpec>(*topNode(s, 3).shape);
  checkVec(cylinder.base, Vec3(0, 0, -1));
  checkVec(cylinder.cap, Vec3(0, 2, -1));
  CHECK(cylinder.radius == 0.25);
  CHECK(cylinder.open);
  const auto& cone = std::get<ConeSpec>(*topNode(s, 4).shape);
  checkVec(cone.cap, Vec3(0, 0, -2));
  CHECK(cone.baseRadius == 1.0);
  CHECK(cone.capRadius == 0.5);
  CHECK(!cone.open);
  const auto& torus = std::get<TorusSpec>(*topNode(s, 5).shape);
  CHECK(torus.major == 2.0);
  CHECK(torus.minor == 0.5);
  const auto& disc = std::get<DiscSpec>(*topNode(s, 6).shape);
  checkVec(disc.center, Vec3(0, 1, -2));
  checkVec(disc.normal, Vec3(0, 0, -1));
  CHECK(disc.radius == 2.0);
  CHECK(disc.innerRadius == 1.0);
  const auto& triangle = std::get<TriangleSpec>(*topNode(s, 7).shape);
  checkVec(triangle.c, Vec3(0, 1, -2));
}

TEST_CASE("scene reader: an object's transforms, in order, as S·M·S", "[sdl][scene]") {
  auto r = readScene(R"(
#declare T = transform { rotate y*30 translate <1, 0, 0> }
sphere { 0, 1 scale <1, 2, 3> rotate <10, 20, 30> translate <4, 5, 6>
         matrix <1, 0, 0, 0.5, 1, 0, 0, 0, 1, 0, 0, 0> transform T transform { T inverse } }
)");
  REQUIRE(r->load.scene);
  PovTransform t = PovTransform::scaling(Vec3(1, 2, 3));
  t.rotate(Vec3(10, 20, 30)).translate(Vec3(4, 5, 6));
  t = t.then(PovTransform::matrix({1, 0, 0, 0.5, 1, 0, 0, 0, 1, 0, 0, 0}));
  PovTransform T = PovTransform::rotation(Vec3(0, 30, 0));
  T.translate(Vec3(1, 0, 0));
  t = t.then(T).then(T.inverse());
  checkMat(topNode(*r->load.scene, 0).parentFromNode, t.lucentMatrix());
}

TEST_CASE("scene reader: pigment, finish and interior make POV-Ray's material", "[sdl][scene]") {
  auto r = readScene(R"(
#include "colors.inc"
sphere { 0, 1 pigment { color rgbf <0.9, 0.3, 0.2, 0.25> }
         finish { ambient 0.2 diffuse 0.7 phong 0.5 phong_size 20 reflection { 0.1, 0.4 fresnel } }
         interior { ior 1.5 } }
sphere { 0, 1 texture { pigment { Red } finish { specular 0.3 roughness 0.01 } } }
sphere { 0, 1 }
#declare M = material { texture { pigment { rgb <0, 0, 1> } } interior { ior 1.3 } }
sphere { 0, 1 material { M } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  checkColor(materialOf(s, topNode(s, 3)).diffuse, Color(0.0f, 0.0f, 0.6f));
  CHECK(materialOf(s, topNode(s, 3)).ior == Approx(1.3));
  PovPigment p;
  p.color = Color(0.9f, 0.3f, 0.2f);
  p.filter = 0.25f;
  PovFinish f;
  f.ambient = Color(0.2f);
  f.diffuse = 0.7;
  f.phong = 0.5;
  f.phongSize = 20;
  f.reflection.min = Color(0.1f);
  f.reflection.max = Color(0.4f);
  f.reflection.fresnel = true;
  PovInterior i;
  i.ior = 1.5;
  const Material want = importMaterial(p, f, i).material;
  const Material& got = materialOf(s, topNode(s, 0));
  checkColor(got.diffuse, want.diffuse);
  checkColor(got.ambient, want.ambient);
  checkColor(got.phong, want.phong);
  checkColor(got.transmissive, want.transmissive);
  checkColor(got.reflective, want.reflective);
  CHECK(got.fresnel);
  CHECK(got.ior == 1.5);
  CHECK(got.phongSize == 20);

  const Material& red = materialOf(s, topNode(s, 1));
  checkColor(red.diffuse, Color(0.6f, 0.0f, 0.0f));  // colors.inc's Red times diffuse 0.6
  checkColor(red.specular, Color(0.3f));
  CHECK(red.shininess == Approx(100.0));
  // No texture at all: POV-Ray's default, black.
  checkColor(materialOf(s, topNode(s, 2)).diffuse, Color(0.0f));
  REQUIRE(got.reflectiveMin);
  checkColor(*got.reflectiveMin, Color(0.1f));
}

TEST_CASE("scene reader: reflection { C fresnel } is C over a minimum of 0, as POV-Ray reads it",
          "[sdl][scene]") {
  auto r = readScene(R"(
sphere { 0, 1 finish { reflection { 0.6 fresnel } } interior { ior 1.5 } }
sphere { 0, 1 finish { reflection { 0.2, 0.6 falloff 2 exponent 3 } } }
sphere { 0, 1 finish { reflection { 0.6 } } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const Material& fresnel = materialOf(s, topNode(s, 0));
  CHECK(fresnel.fresnel);
  CHECK_FALSE(fresnel.reflectiveMin);  // 0: Lucent's default under fresnel
  checkColor(fresnel.reflective, Color(0.6f));
  const Material& falloff = materialOf(s, topNode(s, 1));
  REQUIRE(falloff.reflectiveMin);
  checkColor(*falloff.reflectiveMin, Color(0.2f));
  CHECK(falloff.reflectFalloff == 2.0);
  CHECK(falloff.reflectExponent == 3.0);
  CHECK_FALSE(materialOf(s, topNode(s, 2)).reflectiveMin);
}

TEST_CASE("scene reader: #default finish and pigment apply to what follows", "[sdl][scene]") {
  auto r = readScene(R"(
sphere { 0, 1 pigment { rgb 1 } }
#default { finish { ambient 0 diffuse 0.9 } pigment { rgb <0, 0, 1> } }
sphere { 0, 1 pigment { rgb 1 } }
sphere { 0, 1 pigment { rgb 1 } finish { phong 1 } }
sphere { 0, 1 }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  checkColor(materialOf(s, topNode(s, 0)).diffuse, Color(0.6f));
  checkColor(materialOf(s, topNode(s, 1)).diffuse, Color(0.9f));
  checkColor(materialOf(s, topNode(s, 1)).ambient, Color(0.0f));
  // A finish block starts from the default finish.
  checkColor(materialOf(s, topNode(s, 2)).diffuse, Color(0.9f));
  checkColor(materialOf(s, topNode(s, 2)).phong, Color(1.0f));
  checkColor(materialOf(s, topNode(s, 3)).diffuse, Color(0.0f, 0.0f, 0.9f));
}

TEST_CASE("scene reader: CSG operands inherit the operation's texture", "[sdl][scene]") {
  auto r = readScene(R"(
#declare Ball = sphere { 0, 1 pigment { rgb <1, 0, 0> } }
difference {
  box { -1, 1 }
  object { Ball translate x no_shadow }
  pigment { rgb <0, 1, 0> }
  inverse
}
union { sphere { 0, 1 } merge { sphere { 0, 1 } sphere { x, 1 } } translate y }
intersection { sphere { 0, 1 } plane { y, 0 } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const Node& d = topNode(s, 0);
  CHECK(d.kind == NodeKind::Difference);
  CHECK(d.inverse);
  checkColor(materialOf(s, d).diffuse, Color(0.0f, 0.6f, 0.0f));
  REQUIRE(d.children.size() == 2);
  CHECK(!d.children[0]->material);  // inherits the difference's
  checkColor(materialOf(s, *d.children[1]).diffuse, Color(0.6f, 0.0f, 0.0f));
  CHECK(!d.children[1]->shadows);
  checkMat(d.children[1]->parentFromNode, PovTransform::translation(Vec3(1, 0, 0)).lucentMatrix());
  const Node& u = topNode(s, 1);
  CHECK(u.kind == NodeKind::Union);
  REQUIRE(u.children.size() == 2);
  CHECK(u.children[1]->kind == NodeKind::Merge);
  CHECK(u.children[1]->children.size() == 2);
  CHECK(topNode(s, 2).kind == NodeKind::Intersection);
}

// A declared object's copies share its texture, shape and children until one is changed
// (sdl/shared_values.h): a change to one use never reaches the declaration or another use.
TEST_CASE("scene reader: changing one use of a declared object leaves the others as declared",
          "[sdl][scene]") {
  auto r = readScene(R"(
#declare Pair = union {
  cylinder { 0, y, 1 pigment { rgb <1, 0, 0> } }
  sphere { 0, 1 }
  pigment { rgb <0, 0, 1> }
}
#declare Can = cylinder { 0, y, 1 pigment { rgb <1, 0, 0> } }
object { Pair pigment { rgb <0, 1, 0> } }
difference { object { Pair } box { -1, 1 } }
object { Pair }
object { Can open pigment { rgb <0, 1, 0> } }
object { Can }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  checkColor(materialOf(s, topNode(s, 0)).diffuse, Color(0.0f, 0.6f, 0.0f));
  for (size_t i = 1; i < 3; ++i) {
    INFO("use " << i);
    const Node& u = i == 1 ? *topNode(s, i).children.at(0) : topNode(s, i);
    checkColor(materialOf(s, u).diffuse, Color(0.0f, 0.0f, 0.6f));
    REQUIRE(u.children.size() == 2);
    checkColor(materialOf(s, *u.children[0]).diffuse, Color(0.6f, 0.0f, 0.0f));
  }
  const Node& opened = topNode(s, 3);
  const Node& can = topNode(s, 4);
  REQUIRE(opened.shape);
  REQUIRE(can.shape);
  CHECK(std::get<CylinderSpec>(*opened.shape).open);
  CHECK(!std::get<CylinderSpec>(*can.shape).open);
  checkColor(materialOf(s, opened).diffuse, Color(0.0f, 0.6f, 0.0f));
  checkColor(materialOf(s, can).diffuse, Color(0.6f, 0.0f, 0.0f));
}

TEST_CASE("scene reader: camera, lights and settings", "[sdl][scene]") {
  auto r = readScene(R"(
global_settings { assumed_gamma 1.0 max_trace_level 7 adc_bailout 0.01 ambient_light rgb 0.5 }
background { color rgb <0.1, 0.2, 0.3> }
camera { location <0, 1, -4> right x*4/3 look_at <0, 0.5, 0> }
light_source { <2, 4, -3> color rgb <1, 0.9, 0.8> }
light_source { <0, 5, 0>, 1 spotlight point_at <0, 0, 1> radius 10 falloff 20 shadowless }
light_source { <0, 5, 0>, 1 shadowless spotlight point_at <0, 0, 1> radius 10 falloff 20 }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  CHECK(s.render.maxDepth == 7);
  CHECK(s.render.minWeight == Approx(0.01));
  checkColor(s.render.ambient, Color(0.5f));
  checkColor(s.render.background, Color(0.1f, 0.2f, 0.3f));
  CHECK(s.render.width == 160);
  CHECK(s.render.height == 120);

  sdl::PovCamera c;
  c.location = Vec3(0, 1, -4);
  c.right = Vec3(4.0 / 3.0, 0, 0);
  c.rightGiven = true;
  c.lookAt = Vec3(0, 0.5, 0);
  const Camera want = importCamera(c, 160, 120).camera;
  REQUIRE(s.cameras.size() == 1);
  checkVec(s.cameras[0].position, want.position);
  checkVec(s.cameras[0].lookAt, want.lookAt);
  CHECK(s.cameras[0].fov == Approx(want.fov));
  CHECK(s.cameras[0].loc.line == 4);

  REQUIRE(s.lights.size() == 3);
  checkVec(s.lights[0].position, Vec3(2, 4, 3));
  checkColor(s.lights[0].color, Color(1.0f, 0.9f, 0.8f));
  // POV-Ray's light has one type: shadowless after spotlight makes its fill light, a point
  // light without shadows or highlights (checked with povray 3.7.0.10: no cone); spotlight
  // after shadowless makes a spotlight with both.
  CHECK(s.lights[1].type == LightType::Point);
  CHECK(!s.lights[1].shadows);
  CHECK(!s.lights[1].highlights);
  CHECK(s.lights[2].type == LightType::Spot);
  CHECK(s.lights[2].angle == Approx(20.0));
  CHECK(s.lights[2].inner == Approx(10.0));
  CHECK(s.lights[2].shadows);
  CHECK(s.lights[2].highlights);
  checkVec(s.lights[2].direction, glm::normalize(Vec3(0, -5, -1)));
}

TEST_CASE("scene reader: without a camera, POV-Ray's default", "[sdl][scene]") {
  auto r = readScene("sphere { z*3, 1 }\n");
  REQUIRE(r->load.scene);
  const Camera want = importCamera(sdl::PovCamera{}, 160, 120).camera;
  checkVec(r->load.scene->cameras.at(0).position, want.position);
  CHECK(r->load.scene->cameras.at(0).fov == Approx(want.fov));
  // POV-Ray's default right <1.33,0,0> on a 4:3 image: its frame, not the image's.
  CHECK(r->load.scene->cameras.at(0).frameAspect == Approx(1.33));
  CHECK_FALSE(r->load.scene->cameras.at(0).mirror);
  CHECK(r->out.warnings.empty());
}

TEST_CASE("scene reader: every unsupported feature is listed at its place",
          "[sdl][scene][errors]") {
  const auto errors = errorsOf(R"(global_settings { radiosity { count 100 } }
sphere { 0, 1 hollow interior { media { emission 1 } } }
sphere { 0, 1 photons { target } no_image }
sphere { 0, 1 interior { caustics 1 } }
)");
  REQUIRE(errors.size() == 4);  // no_image is read (tests/sdl/visibility_reader_test.cpp)
  CHECK(errors[0] ==
        "test.pov:1:19: error: 'radiosity' is not supported by Lucent (global illumination; "
        "ambient_light stands in for it)");
  CHECK(errors[1] ==
        "test.pov:2:33: error: 'media' is not supported by Lucent (participating media; the "
        "nearest Lucent feature is <fog>)");
  CHECK(errors[2] ==
        "test.pov:3:15: error: 'photons' is not supported by Lucent (photon mapping of caustics)");
  CHECK(errors[3] ==
        "test.pov:4:26: error: 'caustics' is not supported by Lucent (faked caustics)");
}

TEST_CASE("scene reader: what is not read yet, and syntax errors, at their place",
          "[sdl][scene][errors]") {
  const auto errors = errorsOf(
      "sphere { 0, 1 pigment { checker rgb 1 rgb 0 } finish { albedo } }\n"
      "hf_gray_16\n");
  REQUIRE(errors.size() == 2);
  CHECK(errors[0] == "test.pov:1:56: error: 'albedo' is not read yet by Lucent's POV-Ray reader");
  CHECK(errors[1] ==
        "test.pov:2:1: error: 'hf_gray_16' is not read yet by Lucent's POV-Ray reader");
  const auto syntax = errorsOf("sphere { 0, 1 pigment { rgb 1 } 3 }\n");
  REQUIRE(syntax.size() == 1);
  CHECK(syntax[0] == "test.pov:1:33: error: unexpected float constant in sphere");
}

TEST_CASE("scene reader: fog and sky_sphere", "[sdl][scene]") {
  auto r = readScene(R"(
fog { distance 10 color rgbt <0.5, 0.6, 0.7, 0.2> }
sky_sphere { pigment { gradient y color_map { [0 rgb 1] [1 color rgb <0, 0, 1>] } } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  REQUIRE(s.fogs.size() == 1);
  CHECK(s.fogs[0].type == FogType::Constant);
  CHECK(s.fogs[0].distance == 10.0);
  checkColor(s.fogs[0].color, Color(0.5f, 0.6f, 0.7f));
  CHECK(s.fogs[0].transmit == Approx(0.2f));
  REQUIRE(s.sky);
  REQUIRE(s.sky->layers.size() == 1);
  const auto& gradient = std::get<PatternTexture>(s.sky->layers[0]);
  REQUIRE(gradient.map.entries.size() == 2);
  checkColor(gradient.map.entries[1].color, Color(0.0f, 0.0f, 1.0f));
  // The gradient as POV-Ray writes it, evaluated in POV-Ray's space (z negated).
  checkVec(gradient.pattern.axis, Vec3(0.0, 1.0, 0.0));
  Mat4 s1(1.0);
  s1[2][2] = -1.0;
  checkMat(gradient.pattern.placement.patternFromObject, s1);
  checkMat(s.sky->skyFromWorld, Mat4(1.0));
}

TEST_CASE("scene reader: every fog, with its turbulence in POV-Ray's space", "[sdl][scene]") {
  auto r = readScene(R"(
global_settings { noise_generator 3 }
fog { fog_type 2 distance 1.5 color rgb <0, 0, 1> fog_alt 0.35
      turbulence <0.15, -0.2, 0.25> omega 0.35 lambda 1.25 octaves 12 turb_depth 0.7 }
fog { distance 9 color rgb 1 octaves 3 }
fog { distance 9 color rgb 1 }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  REQUIRE(s.fogs.size() == 3);
  REQUIRE(s.fogs[0].turbulence);
  const FogTurbulence& t = *s.fogs[0].turbulence;
  CHECK(t.strength == Vec3(0.15, 0.2, 0.25));
  // POV-Ray's point (x, y, z) is Lucent's (x, y, -z); a negative component mirrors too.
  CHECK(t.noiseFromWorld[0][0] == 1.0);
  CHECK(t.noiseFromWorld[1][1] == -1.0);
  CHECK(t.noiseFromWorld[2][2] == -1.0);
  CHECK(t.octaves == 10);  // clamped, as POV-Ray's parser does
  CHECK(t.omega == 0.35);
  CHECK(t.lambda == 1.25);
  CHECK(t.depth == 0.7);
  CHECK(t.noiseGenerator == 3);  // global_settings'
  // octaves alone make POV-Ray's turbulence, of strength 0.
  REQUIRE(s.fogs[1].turbulence);
  CHECK(s.fogs[1].turbulence->strength == Vec3(0.0));
  CHECK(s.fogs[1].turbulence->octaves == 3);
  CHECK_FALSE(s.fogs[2].turbulence);
}

TEST_CASE("scene reader: hollow is the material's and CSG operands without their own take it",
          "[sdl][scene]") {
  auto r = readScene(R"(
plane { y, 0 pigment { rgb 1 } hollow }
sphere { 0, 1 pigment { rgb 1 } }
union { sphere { 0, 1 } sphere { x, 1 hollow off } pigment { rgb 1 } hollow on }
sphere { 0, 1 pigment { rgb 1 } hollow off }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  CHECK(materialOf(s, topNode(s, 0)).hollow);
  CHECK_FALSE(materialOf(s, topNode(s, 1)).hollow);
  const Node& u = topNode(s, 2);
  CHECK(materialOf(s, u).hollow);
  REQUIRE(u.children.size() == 2);
  CHECK(!u.children[0]->material);  // the union's, hollow
  REQUIRE(u.children[1]->material);
  CHECK_FALSE(materialOf(s, *u.children[1]).hollow);
  CHECK_FALSE(materialOf(s, topNode(s, 3)).hollow);
}

TEST_CASE(
    "scene reader: an unsupported feature in a macro names the call, and nesting is "
    "bounded",
    "[sdl][scene][errors]") {
  const auto errors = errorsOf(
      "#macro Glow()\n  sphere { 0, 1 interior { media { } } }\n#end\n"
      "Glow()\nGlow()\n");
  REQUIRE(errors.size() == 2);
  CHECK(errors[0] ==
        "test.pov:2:28: error: 'media' is not supported by Lucent (participating media; the "
        "nearest Lucent feature is <fog>)\ntest.pov:4:1: note: in macro 'Glow' called here");
  CHECK(errors[1].find("test.pov:5:1: note: in macro 'Glow' called here") != std::string::npos);
  std::string deep;
  for (int i = 0; i < 257; ++i) deep += "union { ";
  const auto nested = errorsOf(deep);
  REQUIRE(nested.size() == 1);
  CHECK(nested[0] == "test.pov:1:2049: error: objects nested more than 256 deep");
}

TEST_CASE("scene reader: trace(), inside(), min_extent() and max_extent() as POV-Ray gives them",
          "[sdl][scene][povray]") {
  // tests/data/sdl/scenes/object_functions.pov prints rays traced at spheres, boxes, CSG and
  // a torus (hits, normals, misses), inside() of points and the extents; the .out beside it
  // is POV-Ray's own output, which Lucent's geometry must reproduce to the printed digits.
  const std::filesystem::path dir = sdltest::dataFolder() / "scenes";
  CollectedOutput out;
  Options options;
  options.output = &out;
  const SceneLoad load = loadScene(dir / "object_functions.pov", options);
  for (const Diagnostic& d : load.diagnostics.all()) UNSCOPED_INFO(d.str());
  REQUIRE(load.scene);
  std::ifstream in(dir / "object_functions.out");
  std::ostringstream expected;
  expected << in.rdbuf();
  CHECK(povPrinted(out.debugText) == expected.str());
  // An identifier that is no object is refused at the argument.
  CHECK(errorsOf("#declare A = 1; #declare P = trace(A, 0, x);\n").at(0) ==
        "test.pov:1:36: error: trace() needs an object identifier first, not float identifier "
        "'A'");
}

TEST_CASE("scene reader: a checker of pigments is read, and reading goes on after it",
          "[sdl][scene]") {
  // The list's blocks end with the pigment's own closing brace after them (once skipped as
  // a refusal, which made the rest of the scene an error of the plane:
  // advanced/cliche/cliche.pov).
  auto r = readScene(
      "plane { y, 0 texture { pigment { checker pigment { rgb 1 }, pigment { rgb 0 } scale 2 }\n"
      "  finish { ambient 0.1 } } }\n"
      "sphere { 0, 1 }\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  REQUIRE(s.root->children.size() == 2);
  REQUIRE(s.root->children[0]->material);
  const Material& m = s.materials.at(*s.root->children[0]->material);
  const auto& c = std::get<CheckerTexture>(m.texture);
  REQUIRE(c.pigments.size() == 2);
  CHECK(c.pigments[0].color.rgb == Color(1.0f));
  CHECK(c.pigments[1].color.rgb == Color(0.0f));
  CHECK(c.placement.patternFromObject[0][0] == Approx(0.5));
  CHECK(m.ambient == Color(0.1f));
}

TEST_CASE("scene reader: shared materials for the default texture and for declared textures",
          "[sdl][scene]") {
  auto r = readScene(R"(
#declare T_Red = texture { pigment { rgb <1, 0, 0> } finish { phong 1 } }
#declare M = material { texture { pigment { rgb 0.5 } } interior { ior 1.5 } }
sphere { 0, 1 }
sphere { x, 1 }
sphere { 0, 1 texture { T_Red } }
sphere { x*2, 1 texture { T_Red } }
sphere { x*4, 1 texture { T_Red } finish { ambient 0.5 } }
box { -1, 1 material { M } }
box { 2, 3 material { M } interior { ior 1.2 } }
#default { finish { ambient 0.3 } }
sphere { y, 1 }
#declare A = array[2] { texture { pigment { rgb x } }, texture { pigment { rgb y } } }
sphere { 0, 1 texture { A[0] } }
sphere { 0, 1 texture { A[1] } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const std::vector<uint32_t> m = topMaterials(s);
  REQUIRE(m.size() == 10);
  // Array elements are not named (the token's text is the array's): each its own material
  // (incdemo/finish.pov's nine textures of an array once came out as the first).
  CHECK(m[8] != m[9]);
  CHECK(s.materials.at(m[9]).diffuse.g > 0.5f);
  CHECK(m[0] == m[1]);  // the default texture: one material
  CHECK(m[2] == m[3]);  // T_Red as it is: one material, named after it
  CHECK(s.materials.at(m[2]).id == "T_Red");
  CHECK(m[4] != m[2]);  // T_Red with its finish changed: its own, unnamed
  CHECK(s.materials.at(m[4]).id.empty());
  CHECK(s.materials.at(m[5]).id == "M");
  CHECK(m[6] != m[5]);  // M with another interior
  CHECK(s.materials.at(m[6]).ior == Approx(1.2));
  // After a #default: the new default's material, here equal in every term to the first
  // (its ambient 0.3 multiplies the same black pigment), so the two share one index.
  CHECK(s.materials.at(m[7]).ambient.r == Approx(0.0f).margin(1e-7));
  CHECK(m[7] == m[0]);
}

TEST_CASE("scene reader: a texture declared again under its name is another material",
          "[sdl][scene]") {
  auto r = readScene(R"(
#declare T = texture { pigment { rgb <1, 0, 0> } }
sphere { -x, 1 texture { T } }
#declare T = texture { pigment { rgb <0, 1, 0> } }
sphere { x, 1 texture { T } }
sphere { 2*x, 1 texture { T } }
#declare P = texture { pigment { gradient y } }
sphere { 0, 1 texture { P } }
sphere { 0, 1 texture { P } }
sphere { 0, 1 texture { P } translate y }
sphere { 0, 1 translate y texture { P } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const std::vector<uint32_t> m = topMaterials(s);
  REQUIRE(m.size() == 7);
  CHECK(m[0] != m[1]);  // the second declaration's colour, not the first's
  CHECK(s.materials.at(m[0]).diffuse.r > 0.5f);
  CHECK(s.materials.at(m[1]).diffuse.g > 0.5f);
  CHECK(s.materials.at(m[1]).diffuse.r == Approx(0.0f).margin(1e-7));
  CHECK(m[1] == m[2]);
  CHECK(s.materials.at(m[0]).id == "T");
  CHECK(s.materials.at(m[1]).id == "T-2");
  // A patterned declared texture: one material wherever its pattern lies the same on the
  // object (written before the translate, it moves with the object: the same in object
  // space); another where it does not (written after: it stays, the object moves).
  CHECK(m[3] == m[4]);
  CHECK(m[5] == m[3]);
  CHECK(m[6] != m[3]);
  CHECK(s.materials.at(m[3]).id.empty());
}

TEST_CASE("scene reader: objects of equal plain materials share one index", "[sdl][scene]") {
  auto r = readScene(R"(
#declare X = 0;
#while (X < 6)
  sphere { <X, 0, 0>, 0.1 pigment { color rgb <1, mod(X, 2), 0> } }
  #declare X = X + 1;
#end
sphere { 0, 1 pigment { rgb <1, 0, 0> } finish { phong 1 } }
sphere { 0, 1 pigment { rgb <1, 0, 0> } finish { phong 1 } }
sphere { 0, 1 pigment { checker rgb 1 rgb 0 } }
sphere { 0, 1 pigment { checker rgb 1 rgb 0 } }
sphere { 0, 1 pigment { rgb <1, 0, 0> } hollow }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const std::vector<uint32_t> m = topMaterials(s);
  REQUIRE(m.size() == 11);
  // The loop's two colours: two materials, alternating.
  CHECK(m[0] == m[2]);
  CHECK(m[0] == m[4]);
  CHECK(m[1] == m[3]);
  CHECK(m[1] == m[5]);
  CHECK(m[0] != m[1]);
  CHECK(s.materials.at(m[0]).diffuse.g == Approx(0.0f).margin(1e-7));
  CHECK(s.materials.at(m[1]).diffuse.g == Approx(0.6f));
  // A finish term makes another material; written twice, still one.
  CHECK(m[6] != m[0]);
  CHECK(m[6] == m[7]);
  CHECK(s.materials.at(m[6]).phong.r == Approx(1.0f));
  // Patterned materials are not compared: each object keeps its own.
  CHECK(m[8] != m[9]);
  // hollow is a term of the material.
  CHECK(m[10] != m[0]);
  CHECK(s.materials.at(m[10]).hollow);
}

TEST_CASE("scene reader: a light's media_attenuation is its media-attenuation", "[sdl][scene]") {
  auto r = readScene(R"(
light_source { <0, 10, 0> rgb 1 media_attenuation on }
light_source { <0, 10, 0> rgb 1 media_attenuation off media_interaction off }
light_source { <0, 10, 0> rgb 1 }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  REQUIRE(s.lights.size() == 3);
  CHECK(s.lights[0].mediaAttenuation);
  CHECK_FALSE(s.lights[1].mediaAttenuation);
  CHECK_FALSE(s.lights[2].mediaAttenuation);
}

TEST_CASE("scene reader: POV-Ray's cylinder camera types 1 to 4, and others refused at the number",
          "[sdl][scene][errors]") {
  auto r = readScene(
      "camera { cylinder 3.7 angle 120 location <0, 1, -4> look_at <0, 1, 0> }\n"
      "sphere { 0, 1 }\n");
  REQUIRE(r->load.scene);
  REQUIRE(r->load.scene->cameras.size() == 1);
  const Camera& c = r->load.scene->cameras[0];
  CHECK(c.type == CameraType::Cylinder);
  CHECK(c.cylinderType == 3);  // POV-Ray truncates the number
  CHECK(c.sweep == 120.0);
  CHECK(c.axisLength == 1.0);  // |up|

  for (const char* bad : {"0", "5", "-1", "0.5"}) {
    const auto errors = errorsOf(std::string("camera {\n  cylinder ") + bad + " }\n");
    REQUIRE(errors.size() == 1);
    CHECK(errors[0] == std::string("test.pov:2:12: error: invalid cylinder camera type ") + bad +
                           ": the types are 1 to 4");
  }
}

TEST_CASE("scene reader: looks_like draws its object at the light, casting no shadow",
          "[sdl][scene][light]") {
  // POV-Ray moves the object to the light's centre as it is when looks_like is read, then
  // applies the modifiers in looks_like's block; transforms of the light written later move
  // both.
  auto r = readScene(R"(
light_source { <0, 5, 0> rgb 1 translate <0, 0, 2>
  looks_like { sphere { 0, 0.5 } scale <1, 2, 1> }
  translate <1, 0, 0> }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const Node& both = topNode(s, 0);
  REQUIRE(both.children.size() == 2);
  REQUIRE(both.children[0]->light);
  checkVec(both.children[0]->light->position, Vec3(1, 5, -2));
  const Node& sphere = *both.children[1];
  CHECK_FALSE(sphere.shadows);
  // The scale in looks_like's block comes after the move to <0, 5, 2>: about the origin, so
  // the centre goes to y 10 and the top to 11.
  checkVec(Vec3(sphere.parentFromNode * Vec4(0, 0, 0, 1)), Vec3(1, 10, -2));
  checkVec(Vec3(sphere.parentFromNode * Vec4(0, 0.5, 0, 1)), Vec3(1, 11, -2));
  CHECK(errorsOf("light_source { 0, 1 looks_like { sphere { 0, 1 } } looks_like { sphere { 0, 1 "
                 "} } }\n")
            .at(0) ==
        "test.pov:1:52: error: only one looks_like per light_source, as POV-Ray allows");
}

TEST_CASE("scene reader: projected_through's object follows the light's later transforms",
          "[sdl][scene][light][projected-through]") {
  // As looks_like's: the light's transforms written after projected_through move the object
  // too, those before it not; the object's texture is dropped.
  auto r = readScene(R"(
light_source { <0, 8, 0> rgb 1 translate <0, 0, 2>
  projected_through { sphere { <0, 4, 0>, 0.5 pigment { rgb 1 } } scale <1, 0.5, 1> }
  translate <1, 0, 0> }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  REQUIRE(s.lights.size() == 1);
  const Light& light = s.lights[0];
  checkVec(light.position, Vec3(1, 8, -2));
  REQUIRE(light.projectedThrough);
  REQUIRE(light.projectedThrough->children.size() == 1);
  const Node& sphere = *light.projectedThrough->children[0];
  // Its centre <0, 4, 0>, scaled to y 2, then moved by the later translate only (Lucent's z
  // is POV-Ray's negated).
  const Vec3 centre = Vec3(light.worldFromLight * sphere.parentFromNode *
                           Vec4(std::get<SphereSpec>(*sphere.shape).center, 1));
  checkVec(centre, Vec3(1, 2, 0));
  CHECK(errorsOf("light_source { 0, 1 projected_through { sphere { 0, 1 } } projected_through { "
                 "sphere { 0, 1 } } }\n")
            .at(0) ==
        "test.pov:1:59: error: only one projected_through per light_source, as POV-Ray allows");
}

TEST_CASE("scene reader: #version 3.6 keeps POV-Ray 3.6's opacity of a filtering pigment",
          "[sdl][scene]") {
  // 3.6: 1 - 0.5·max(0.2, 0.4, 0.2) = 0.8; 3.7: 1 - 0.5 = 0.5. The version in force where
  // the object is placed decides.
  auto r = readScene(R"(
#version 3.6;
sphere { 0, 1 pigment { rgbf <0.2, 0.4, 0.2, 0.5> } finish { ambient 0 diffuse 1 } }
#version 3.7;
sphere { 0, 1 pigment { rgbf <0.2, 0.4, 0.2, 0.5> } finish { ambient 0 diffuse 1 } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  checkColor(materialOf(s, topNode(s, 0)).diffuse, Color(0.2f, 0.4f, 0.2f) * 0.8f);
  checkColor(materialOf(s, topNode(s, 1)).diffuse, Color(0.2f, 0.4f, 0.2f) * 0.5f);
}
