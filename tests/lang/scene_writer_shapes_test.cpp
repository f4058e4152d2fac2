// The scene writer on every shape (lang/scene_writer_shapes.cpp): each element read, written
// and read again makes the same parameters, field by field, including the lists, files,
// functions and child elements a shape's entry reads itself.
#include "../support/scene_text.h"
#include "../temp_dir.h"

#include "lang/scene_writer.h"
#include "primitives/text_outline.h"
#include "scenegraph/pigment_function.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

using namespace lucent;
using namespace lucent::test;

namespace {

namespace fs = std::filesystem;

// A folder of its own holding the files the shapes name: a mesh, a height field's image and
// a font; the scenes are read (and written) as if from a file in it. One folder per test
// process, made once: ctest runs this file's cases in parallel processes, which must not
// rewrite each other's files while they read them.
fs::path shapeFolder() {
  static const TempDir folder("scene-writer-shapes");
  static bool made = false;
  const fs::path dir = folder.path;
  if (made) return dir;
  made = true;
  std::ofstream(dir / "quad.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\n"
                                     "vt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n";
  std::ofstream pgm(dir / "ridge.pgm", std::ios::binary);
  pgm << "P5\n3 3\n255\n";
  const unsigned char grey[] = {10, 200, 10, 20, 250, 30, 0, 120, 40};
  pgm.write(reinterpret_cast<const char*>(grey), sizeof grey);
  pgm.close();
  fs::copy_file(defaultFontFile(), dir / "font copy.ttf", fs::copy_options::overwrite_existing);
  return dir;
}

struct RoundTrip {
  std::unique_ptr<Scene> first, second;
  std::string text;
};

// BODY parsed (without a message unless `warns`), written as a file in the same folder, and
// read again (without an error, and with no more warnings than the first read).
RoundTrip roundTrip(const std::string& body, bool warns = false) {
  const fs::path dir = shapeFolder();
  const std::string file = (dir / "writer.xml").string();
  RoundTrip r;
  ParseResult first = parseBody(body, file);
  INFO(body << "\n" << messages(first));
  REQUIRE(first.scene);
  REQUIRE(first.diagnostics.errorCount() == 0);
  if (!warns) REQUIRE(first.diagnostics.all().empty());
  r.first = std::move(first.scene);
  WriteOptions options;
  options.folder = dir.string();
  r.text = writeSceneXml(*r.first, options);
  ParseResult again = parseSceneString(r.text, file);
  INFO(r.text << "\n" << messages(again));
  REQUIRE(again.scene);
  REQUIRE(again.diagnostics.errorCount() == 0);
  REQUIRE(again.diagnostics.all().size() <= first.diagnostics.all().size());
  r.second = std::move(again.scene);
  return r;
}

template <class S>
const S& shapeOf(const Scene& scene) {
  REQUIRE(!scene.root->children.empty());
  const Node& n = *scene.root->children.front();
  REQUIRE(n.shape);
  REQUIRE(std::holds_alternative<S>(*n.shape));
  return std::get<S>(*n.shape);
}

template <class S>
std::pair<const S&, const S&> specs(const RoundTrip& r) {
  return {shapeOf<S>(*r.first), shapeOf<S>(*r.second)};
}

void sameMesh(const MeshData& a, const MeshData& b) {
  CHECK(a.positions == b.positions);
  CHECK(a.triangles == b.triangles);
  CHECK(a.normals == b.normals);
  CHECK(a.uvs == b.uvs);
  CHECK(a.closed == b.closed);
}

}  // namespace

TEST_CASE("scene writer: the simple shapes read back field by field", "[lang][scene-writer]") {
  {
    auto r = roundTrip("<sphere center=\"1 2 3\" radius=\"0.1\"/>");
    auto [a, b] = specs<SphereSpec>(r);
    CHECK(a.center == b.center);
    CHECK(a.radius == b.radius);
    CHECK(b.radius == 0.1);
  }
  {
    auto r = roundTrip("<box min=\"-1 -2 -3\" max=\"0.3 0.2 0.1\"/>");
    auto [a, b] = specs<BoxSpec>(r);
    CHECK(a.min == b.min);
    CHECK(a.max == b.max);
  }
  {
    auto r = roundTrip("<cylinder base=\"0 0.5 0\" cap=\"0 2 0\" radius=\"0.3\" open=\"true\"/>");
    auto [a, b] = specs<CylinderSpec>(r);
    CHECK(a.base == b.base);
    CHECK(a.cap == b.cap);
    CHECK(a.radius == b.radius);
    CHECK(b.open);
  }
  {
    auto r =
        roundTrip("<cone base=\"0 0 0\" base-radius=\"0.7\" cap=\"0 1 0\" cap-radius=\"0.2\"/>");
    auto [a, b] = specs<ConeSpec>(r);
    CHECK(a.base == b.base);
    CHECK(a.baseRadius == b.baseRadius);
    CHECK(a.cap == b.cap);
    CHECK(a.capRadius == b.capRadius);
    CHECK(a.open == b.open);
  }
  {
    auto r = roundTrip("<torus major=\"1.5\" minor=\"0.3\"/>");
    auto [a, b] = specs<TorusSpec>(r);
    CHECK(a.major == b.major);
    CHECK(a.minor == b.minor);
  }
  {
    auto r = roundTrip("<plane normal=\"0 0 1\" offset=\"-0.25\"/>");
    auto [a, b] = specs<PlaneSpec>(r);
    CHECK(a.normal == b.normal);
    CHECK(a.offset == b.offset);
  }
  {
    auto r =
        roundTrip("<disc center=\"1 0 0\" normal=\"0 0 1\" radius=\"2\" inner-radius=\"0.5\"/>");
    auto [a, b] = specs<DiscSpec>(r);
    CHECK(a.center == b.center);
    CHECK(a.normal == b.normal);
    CHECK(a.radius == b.radius);
    CHECK(a.innerRadius == b.innerRadius);
  }
  {
    auto r = roundTrip("<quadric a=\"1 2 3\" b=\"0.5 0 0\" c=\"0 0 0.25\" d=\"-2\"/>");
    auto [a, b] = specs<QuadricSpec>(r);
    CHECK(a.a == b.a);
    CHECK(a.b == b.b);
    CHECK(a.c == b.c);
    CHECK(a.d == b.d);
  }
  {
    auto r = roundTrip("<superellipsoid e=\"0.3\" n=\"0.7\"/>");
    auto [a, b] = specs<SuperellipsoidSpec>(r);
    CHECK(a.e == b.e);
    CHECK(a.n == b.n);
  }
}

TEST_CASE("scene writer: a triangle's vertex normals read back", "[lang][scene-writer]") {
  auto r = roundTrip(
      "<triangle a=\"0 0 0\" b=\"1 0 0\" c=\"0 1 0\" na=\"0 0 1\" nb=\"0 0.6 0.8\" "
      "nc=\"0.6 0 0.8\"/>");
  auto [a, b] = specs<TriangleSpec>(r);
  CHECK(a.a == b.a);
  CHECK(a.b == b.b);
  CHECK(a.c == b.c);
  REQUIRE(b.normals);
  CHECK(*a.normals == *b.normals);
  auto flat = roundTrip("<triangle a=\"0 0 0\" b=\"1 0 0\" c=\"0 1 0\"/>");
  CHECK(!shapeOf<TriangleSpec>(*flat.second).normals);
}

TEST_CASE("scene writer: an inline mesh is written inline, a file mesh by its file",
          "[lang][scene-writer]") {
  {
    // The second triangle is given backwards: loading turns it over (a warning), and the
    // written lists are the data as loaded, read again without one.
    auto r = roundTrip(
        "<mesh positions=\"0 0 0 1 0 0 1 1 0 0 1 0.5\" indices=\"0 1 2 0 3 2\" "
        "normals=\"0 0 1 0 0 1 0 0 1 0 0 1\" uvs=\"0 0 1 0 1 1 0 1\" smooth=\"false\"/>",
        true);
    auto [a, b] = specs<MeshSpec>(r);
    CHECK(b.src.empty());
    CHECK(b.smooth == SmoothMode::False);
    REQUIRE(b.data);
    sameMesh(*a.data, *b.data);
    CHECK(b.data->triangles.size() == 2);
    CHECK(b.data->repairs.flippedFaces == 0);
  }
  {
    auto r = roundTrip("<mesh src=\"quad.obj\" smooth=\"true\"/>");
    auto [a, b] = specs<MeshSpec>(r);
    CHECK(b.src == "quad.obj");
    CHECK(b.smooth == SmoothMode::True);
    sameMesh(*a.data, *b.data);
  }
}

TEST_CASE("scene writer: poly, prism, lathe and sor write their point and coefficient lists",
          "[lang][scene-writer]") {
  {
    auto r =
        roundTrip("<poly order=\"2\" coefficients=\"1 0 0 0 1 0 0 1 0 -0.30000000000000004\"/>");
    auto [a, b] = specs<PolySpec>(r);
    CHECK(b.order == 2);
    CHECK(a.coefficients == b.coefficients);
    CHECK(b.coefficients.back() == -0.30000000000000004);
  }
  {
    auto r = roundTrip(
        "<prism points=\"0 0 1 0 1 1 0 1 0 0 0.25 0.25 0.75 0.25 0.75 0.75 0.25 0.25\" "
        "height1=\"-0.5\" height2=\"0.1\" sweep=\"conic\" open=\"true\"/>");
    auto [a, b] = specs<PrismSpec>(r);
    CHECK(a.points == b.points);
    CHECK(b.points.size() == 9);
    CHECK(a.height1 == b.height1);
    CHECK(a.height2 == b.height2);
    CHECK(b.spline == PrismSpline::Linear);
    CHECK(b.conic);
    CHECK(b.open);
    auto cubic = roundTrip("<prism spline=\"cubic\" points=\"0 -1 1 0 0 1 -1 0 0 -1 1 0 0 1\"/>");
    CHECK(shapeOf<PrismSpec>(*cubic.second).spline == PrismSpline::Cubic);
    CHECK(shapeOf<PrismSpec>(*cubic.second).points == shapeOf<PrismSpec>(*cubic.first).points);
  }
  {
    auto r = roundTrip("<lathe spline=\"bezier\" points=\"0 0 1.2 0 1.2 1 0 1\"/>");
    auto [a, b] = specs<LatheSpec>(r);
    CHECK(b.spline == LatheSpline::Bezier);
    CHECK(a.points == b.points);
  }
  {
    auto r = roundTrip("<sor points=\"0 -0.5 0.6 0 0.9 0.4 0.4 1 0.5 1.4\" open=\"true\"/>");
    auto [a, b] = specs<SorSpec>(r);
    CHECK(a.points == b.points);
    CHECK(b.open);
  }
}

TEST_CASE("scene writer: a blob's components are written as its children", "[lang][scene-writer]") {
  auto r = roundTrip(
      "<blob threshold=\"0.6\"><component type=\"sphere\" center=\"0.1 0 0\" radius=\"1\" "
      "strength=\"2\"/><component type=\"cylinder\" base=\"0 0 0\" cap=\"0 1 0\" radius=\"0.3\" "
      "strength=\"-0.5\" transform=\"scale(1 0.3 2) rotate-x(10) rotate-z(30)\"/></blob>");
  auto [a, b] = specs<BlobSpec>(r);
  CHECK(a.threshold == b.threshold);
  REQUIRE(b.components.size() == 2);
  for (size_t i = 0; i < 2; ++i) {
    CHECK(a.components[i].kind == b.components[i].kind);
    CHECK(a.components[i].a == b.components[i].a);
    CHECK(a.components[i].radius == b.components[i].radius);
    CHECK(a.components[i].strength == b.components[i].strength);
  }
  CHECK(b.components[1].kind == BlobComponent::Cylinder);
  CHECK(a.components[1].b == b.components[1].b);
  CHECK(b.components[0].transform == Mat4(1.0));
  CHECK(b.components[1].transform != Mat4(1.0));
  CHECK(a.components[1].transform == b.components[1].transform);  // to the last bit
}

TEST_CASE("scene writer: a blob component's own material is written by id",
          "[lang][scene-writer]") {
  auto r = roundTrip(
      "<material id=\"red\" diffuse=\"0.8 0.1 0.1\"/><blob threshold=\"0.5\">"
      "<component type=\"sphere\" radius=\"1\" material=\"red\"/>"
      "<component type=\"sphere\" center=\"1 0 0\" radius=\"1\"/></blob>");
  auto [a, b] = specs<BlobSpec>(r);
  REQUIRE(b.componentMaterials.size() == 2);
  REQUIRE(b.componentMaterials[0]);
  CHECK_FALSE(b.componentMaterials[1]);
  CHECK(r.second->materials[*b.componentMaterials[0]].diffuse ==
        r.first->materials[*a.componentMaterials[0]].diffuse);
  CHECK(r.text.find("material=\"red\"") != std::string::npos);
}

TEST_CASE("scene writer: an isosurface's function keeps its parameters as local <param>s",
          "[lang][scene-writer]") {
  auto r = roundTrip(
      "<param name=\"k\" value=\"0.30000000000000004\"/>"
      "<isosurface function=\"sqrt(x*x + y*y + z*z) - 0.8 + k*sin(10*x)\" container=\"sphere\" "
      "center=\"0 0.1 0\" radius=\"1.2\" threshold=\"0.05\" max-gradient=\"4\" accuracy=\"0.002\" "
      "open=\"true\"/>");
  auto [a, b] = specs<IsosurfaceSpec>(r);
  CHECK(a.function == b.function);
  CHECK(a.constants == b.constants);
  CHECK(b.constants == std::vector<std::pair<std::string, double>>{{"k", 0.30000000000000004}});
  CHECK(b.container.kind == IsosurfaceContainer::Sphere);
  CHECK(a.container.center == b.container.center);
  CHECK(a.container.radius == b.container.radius);
  CHECK(a.threshold == b.threshold);
  CHECK(a.maxGradient == b.maxGradient);
  CHECK(a.accuracy == b.accuracy);
  CHECK(b.open);
  for (const Vec3& p : {Vec3(0.0), Vec3(0.3, -0.2, 0.9), Vec3(-1, 0.5, 0.25)})
    CHECK(a.field->value(p) == b.field->value(p));
  CHECK(r.text.find("<param name=\"k\" value=\"0.30000000000000004\"/>") != std::string::npos);

  auto box = roundTrip("<isosurface function=\"x + y\" min=\"-2 -1 -1\" max=\"1 2 3\"/>");
  auto [c, d] = specs<IsosurfaceSpec>(box);
  CHECK(d.container.kind == IsosurfaceContainer::Box);
  CHECK(c.container.min == d.container.min);
  CHECK(c.container.max == d.container.max);
  CHECK(d.constants.empty());
}

TEST_CASE("scene writer: text keeps its string, font and offset", "[lang][scene-writer]") {
  {
    auto r = roundTrip(
        "<text string=\"Cost: $$5 &amp; &lt;more&gt;\" font=\"font copy.ttf\" thickness=\"0.2\" "
        "offset=\"0.1 -0.05\"/>");
    auto [a, b] = specs<TextSpec>(r);
    CHECK(b.string == "Cost: $5 & <more>");
    CHECK(a.string == b.string);
    CHECK(b.font == "font copy.ttf");
    CHECK(a.fontPath == b.fontPath);
    CHECK(a.thickness == b.thickness);
    CHECK(a.offset == b.offset);
    REQUIRE(b.outline);
    CHECK(a.outline->glyphs.size() == b.outline->glyphs.size());
  }
  {
    // Tab and newline, which XML reads as spaces unless written as character references.
    auto r = roundTrip("<text string=\"a&#9;b&#10;c\"/>", true);
    auto [a, b] = specs<TextSpec>(r);
    CHECK(a.string == "a\tb\nc");
    CHECK(b.string == a.string);
  }
  {
    auto r = roundTrip("<text string=\"A\"/>");
    auto [a, b] = specs<TextSpec>(r);
    CHECK(b.font.empty());
    CHECK(b.fontPath.empty());
    CHECK(a.string == b.string);
  }
}

TEST_CASE("scene writer: a height field names its image", "[lang][scene-writer]") {
  auto r = roundTrip("<height-field src=\"ridge.pgm\" smooth=\"true\" water-level=\"0.02\"/>");
  auto [a, b] = specs<HeightFieldSpec>(r);
  CHECK(b.src == "ridge.pgm");
  CHECK(a.path == b.path);
  CHECK(b.smooth);
  CHECK(a.waterLevel == b.waterLevel);
  REQUIRE(b.map);
  CHECK(a.map->width == b.map->width);
  CHECK(a.map->depth == b.map->depth);
  CHECK(a.map->values == b.map->values);
}

TEST_CASE("scene writer: a height field of a function keeps its function, pigments and grid",
          "[lang][scene-writer]") {
  auto r = roundTrip(
      "<height-field function=\"k*x + G(x, y, z)\" resolution=\"7 5\" open=\"true\">"
      "<param name=\"k\" value=\"0.25\"/>"
      "<pigment-function name=\"G\" component=\"gray\">"
      "<pattern type=\"bozo\" transform=\"scale(0.3)\"/></pigment-function></height-field>");
  auto [a, b] = specs<HeightFieldSpec>(r);
  CHECK(b.src.empty());
  CHECK(b.function == a.function);
  CHECK(b.resolution[0] == 7);
  CHECK(b.resolution[1] == 5);
  CHECK(b.open);
  REQUIRE(b.pigments.size() == 1);
  CHECK(b.pigments[0]->component == PigmentComponent::gray);
  REQUIRE(b.map);
  CHECK(a.map->values == b.map->values);
  // The grid is not flat: the bozo and the slope in x both show.
  CHECK(*std::max_element(b.map->values.begin(), b.map->values.end()) >
        *std::min_element(b.map->values.begin(), b.map->values.end()) + 1000);
}

TEST_CASE("scene writer: a julia fractal keeps its parameter, algebra, function and slice",
          "[lang][scene-writer]") {
  {
    auto r = roundTrip(
        "<julia-fractal c=\"0.4 0.3 0.1 0.05\" algebra=\"hypercomplex\" function=\"pwr\" "
        "exponent=\"2 0.1\" max-iteration=\"9\" precision=\"35\" slice=\"0 0 0.2 1\" "
        "distance=\"0.1\"/>");
    auto [a, b] = specs<JuliaFractalSpec>(r);
    CHECK(b.c == Vec4(0.4, 0.3, 0.1, 0.05));
    CHECK(b.algebra == JuliaAlgebra::Hypercomplex);
    CHECK(b.function == JuliaFunction::Pwr);
    CHECK(b.exponent == Vec2(2.0, 0.1));
    CHECK(b.maxIteration == 9);
    CHECK(b.precision == 35.0);
    CHECK(b.slice == a.slice);
    CHECK(b.distance == 0.1);
  }
  {
    auto r = roundTrip("<julia-fractal c=\"-0.03 0.5 -0.2 -0.5\" function=\"cube\"/>");
    auto [a, b] = specs<JuliaFractalSpec>(r);
    CHECK(b.c == a.c);
    CHECK(b.algebra == JuliaAlgebra::Quaternion);
    CHECK(b.function == JuliaFunction::Cube);
    CHECK(b.maxIteration == 20);
    CHECK(b.slice == Vec4(0.0, 0.0, 0.0, 1.0));
  }
}

TEST_CASE("scene writer: a sphere sweep keeps its spline, spheres and tolerance",
          "[lang][scene-writer]") {
  auto r = roundTrip(
      "<sphere-sweep spline=\"b-spline\" spheres=\"0 0 0 0.5, 1 0.25 -1 0.125, 2 0 0 0, 3.5 1 2 "
      "0.75\" tolerance=\"0.001\"/>");
  auto [a, b] = specs<SphereSweepSpec>(r);
  CHECK(b.spline == SweepSpline::BSpline);
  REQUIRE(b.spheres.size() == 4);
  for (size_t i = 0; i < 4; ++i) {
    CHECK(b.spheres[i].center == a.spheres[i].center);
    CHECK(b.spheres[i].radius == a.spheres[i].radius);
  }
  CHECK(b.spheres[1].center == Vec3(1, 0.25, -1));
  CHECK(b.tolerance == 0.001);
  auto l = roundTrip("<sphere-sweep spheres=\"0 0 0 1, 1 0 0 0.5\"/>");
  auto [c, d] = specs<SphereSweepSpec>(l);
  CHECK(d.spline == SweepSpline::Linear);
  CHECK(d.spheres.size() == 2);
  CHECK(d.tolerance == 1e-6);
}

TEST_CASE("scene writer: an ovus keeps its radii", "[lang][scene-writer]") {
  auto r = roundTrip("<ovus bottom-radius=\"1.25\" top-radius=\"0.375\"/>");
  auto [a, b] = specs<OvusSpec>(r);
  CHECK(b.bottomRadius == 1.25);
  CHECK(b.topRadius == 0.375);
  auto d = roundTrip("<ovus/>");
  auto [c, e] = specs<OvusSpec>(d);
  CHECK(e.bottomRadius == 1.0);
  CHECK(e.topRadius == 0.5);
}

TEST_CASE("scene writer: a parametric keeps its functions, rectangle, container and precompute",
          "[lang][scene-writer][parametric]") {
  auto r = roundTrip(
      "<param name=\"R\" value=\"0.75\"/>"
      "<parametric x=\"R*cos(u)*sin(v)\" y=\"R*cos(v)\" z=\"R*sin(u)*sin(v)\" uv-min=\"0 0\" "
      "uv-max=\"6.25 3.125\" container=\"sphere\" center=\"0 0.5 0\" radius=\"1.5\" "
      "max-gradient=\"0.8\" accuracy=\"0.002\" precompute=\"5\" "
      "precompute-coordinates=\"y z\"/>");
  auto [a, b] = specs<ParametricSpec>(r);
  for (int i = 0; i < 3; ++i) {
    CHECK(b.functions->text[i] == a.functions->text[i]);
    CHECK(b.functions->constants[i] == a.functions->constants[i]);
  }
  CHECK(b.functions->constants[0] == std::vector<std::pair<std::string, double>>{{"R", 0.75}});
  const Vec3 q(0.5, 1.25, 0.0);
  CHECK(b.functions->fields[2]->value(q) == a.functions->fields[2]->value(q));
  CHECK(b.uvMax == Vec2(6.25, 3.125));
  CHECK(b.container.kind == IsosurfaceContainer::Sphere);
  CHECK(b.container.center == Vec3(0.0, 0.5, 0.0));
  CHECK(b.container.radius == 1.5);
  CHECK(b.maxGradient == 0.8);
  CHECK(b.accuracy == 0.002);
  CHECK(b.precomputeDepth == 5);
  CHECK(b.precompute == std::array<bool, 3>{false, true, true});
  REQUIRE(b.intervals);
  // The defaults.
  auto d = roundTrip("<parametric x=\"u\" y=\"v\" z=\"0\"/>");
  auto [c, e] = specs<ParametricSpec>(d);
  CHECK(e.uvMin == Vec2(0.0));
  CHECK(e.uvMax == Vec2(1.0));
  CHECK(e.container.kind == IsosurfaceContainer::Box);
  CHECK(e.container.min == Vec3(-1.0));
  CHECK(e.maxGradient == 1.0);
  CHECK(e.precomputeDepth == 0);
  CHECK_FALSE(e.intervals);
}

TEST_CASE("scene writer: a bicubic patch keeps its points, steps and uv corners",
          "[lang][scene-writer]") {
  auto r = roundTrip(
      "<bicubic-patch type=\"1\" flatness=\"0.05\" u-steps=\"3\" v-steps=\"2\" "
      "flatness-space=\"world\" uv-vectors=\"0.5 0 2 0.25 1 1.5 -1 1\" points=\"0 0 0, 1 0 0, "
      "2 0 0, 3 0 0.5, 0 1 0, 1 1 1, 2 1 1, 3 1 0, 0 2 0, 1 2 1, 2 2 1, 3 2 0, 0 3 0, 1 3 0, 2 3 "
      "0, 3 3 0\"/>");
  auto [a, b] = specs<BicubicPatchSpec>(r);
  CHECK(*b.points == *a.points);
  CHECK((*b.points)[3] == Vec3(3, 0, 0.5));
  CHECK(b.type == 1);
  CHECK(b.flatness == 0.05);
  CHECK(b.uSteps == 3);
  CHECK(b.vSteps == 2);
  CHECK(b.flatnessInWorld);
  const PatchUvCorners corners = {Vec2(0.5, 0), Vec2(2, 0.25), Vec2(1, 1.5), Vec2(-1, 1)};
  CHECK(a.uvVectors == corners);
  CHECK(b.uvVectors == corners);
  // The default corners are written as nothing, and read back as the default.
  auto d = roundTrip(
      "<bicubic-patch points=\"0 0 0, 1 0 0, 2 0 0, 3 0 0, 0 1 0, 1 1 0, 2 1 0, 3 1 0, 0 2 0, 1 "
      "2 0, 2 2 0, 3 2 0, 0 3 0, 1 3 0, 2 3 0, 3 3 0\"/>");
  CHECK(d.text.find("uv-vectors") == std::string::npos);
  auto [c, e] = specs<BicubicPatchSpec>(d);
  CHECK(e.uvVectors == kPatchOwnUv);
}

TEST_CASE("scene writer: a blob component's inline material is written by an id of its own",
          "[lang][scene-writer]") {
  auto r = roundTrip(
      "<blob threshold=\"0.5\"><component type=\"sphere\" radius=\"1\">"
      "<material diffuse=\"0.8 0.1 0.1\"/></component>"
      "<component type=\"sphere\" center=\"1 0 0\" radius=\"1\"/></blob>");
  auto [a, b] = specs<BlobSpec>(r);
  REQUIRE(b.componentMaterials.size() == 2);
  REQUIRE(b.componentMaterials[0]);
  CHECK_FALSE(b.componentMaterials[1]);
  CHECK(r.second->materials[*b.componentMaterials[0]].diffuse == Color(0.8f, 0.1f, 0.1f));
  CHECK(r.text.find("radius=\"1\" strength=\"1\" material=\"material-") != std::string::npos);
}
