// The scene reader's shapes beyond the simple ones (sdl/read_shapes.cpp): each read from
// POV-Ray text into its spec, field by field, after z → −z; what Lucent cannot hold
// refused at its place; bad input located.
#include <catch2/catch.hpp>

#include "scene_read_support.h"
#include "sdl_test_support.h"

#include "primitives/height_map_function.h"
#include "sdl/scene_reader.h"

#include <variant>

using namespace lucent;
using namespace lucent::sdl;

namespace {

using sdltest::errorsOf;
using sdltest::readScene;

const Node& topNode(const Scene& scene, size_t i) {
  REQUIRE(scene.root->children.size() > i);
  return *scene.root->children[i];
}

template <class Spec>
const Spec& shapeOf(const Scene& scene, size_t i) {
  const Node& n = topNode(scene, i);
  REQUIRE(n.shape);
  REQUIRE(std::holds_alternative<Spec>(*n.shape));
  return std::get<Spec>(*n.shape);
}

using sdltest::checkMat;
using sdltest::checkVec;

// The warnings of a read, each as printed.
std::vector<std::string> warningsOf(const sdltest::Read& r) { return r.out.warnings; }

}  // namespace

TEST_CASE("scene shapes: quadric, its terms odd in z negated", "[sdl][scene][shapes]") {
  auto r = readScene(R"(
quadric { <1, 2, 3>, <4, 5, 6>, <7, 8, 9>, 10 }
#declare Q = quadric { <1, 1, 0>, <0, 0, 0>, <0, 0, -1>, 0 }
object { Q translate x }
)");
  REQUIRE(r->load.scene);
  const auto& q = shapeOf<QuadricSpec>(*r->load.scene, 0);
  checkVec(q.a, Vec3(1, 2, 3));
  checkVec(q.b, Vec3(4, -5, -6));  // xy, xz, yz
  checkVec(q.c, Vec3(7, 8, -9));   // x, y, z
  CHECK(q.d == 10.0);
  const auto& p = shapeOf<QuadricSpec>(*r->load.scene, 1);
  checkVec(p.c, Vec3(0, 0, 1));
  checkMat(topNode(*r->load.scene, 1).parentFromNode,
           PovTransform::translation(Vec3(1, 0, 0)).lucentMatrix());
}

TEST_CASE("scene shapes: shapes_old.inc's quadrics", "[sdl][scene][shapes]") {
  auto r = readScene(R"(
#include "shapes_old.inc"
object { Paraboloid_Y }
object { QCone_Z }
)");
  REQUIRE(r->load.scene);
  const auto& para = shapeOf<QuadricSpec>(*r->load.scene, 0);  // <1, 0, 1>, 0, <0, -1, 0>, 0
  checkVec(para.a, Vec3(1, 0, 1));
  checkVec(para.c, Vec3(0, -1, 0));
  const auto& cone = shapeOf<QuadricSpec>(*r->load.scene, 1);  // QCone_Z: <1, 1, -1>, 0, 0, 0
  checkVec(cone.a, Vec3(1, 1, -1));
  CHECK(cone.d == 0.0);
}

TEST_CASE("scene shapes: poly, cubic, quartic and polynomial", "[sdl][scene][shapes]") {
  std::string cubic = "cubic { <", quartic = "quartic { <";
  for (int i = 1; i <= 20; ++i) cubic += std::to_string(i) + (i < 20 ? ", " : "> }\n");
  for (int i = 1; i <= 35; ++i) quartic += std::to_string(i) + (i < 35 ? ", " : "> sturm }\n");
  auto r = readScene("poly { 2, <1, 2, 3, 4, 5, 6, 7, 8, 9, 10> }\n" + cubic + quartic +
                     "polynomial { 4, xyz(4, 0, 0): 1, xyz(0, 0, 3): 2, xyz(0, 1, 1): 3 "
                     "xyz(0, 0, 0): -1 }\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  // Order 2's terms: x², xy, xz, x, y², yz, y, z², z, 1; xz, yz and z change sign.
  const auto& p2 = shapeOf<PolySpec>(s, 0);
  CHECK(p2.order == 2);
  CHECK(p2.coefficients == std::vector<double>{1, 2, -3, 4, 5, -6, 7, 8, -9, 10});
  // Order 3: x³ x²y x²z x² xy² xyz xy xz² xz x y³ y²z y² yz² yz y z³ z² z 1
  const auto& p3 = shapeOf<PolySpec>(s, 1);
  CHECK(p3.order == 3);
  CHECK(p3.coefficients == std::vector<double>{1,  2,   -3, 4,  5,   -6, 7,   8,  -9,  10,
                                               11, -12, 13, 14, -15, 16, -17, 18, -19, 20});
  const auto& p4 = shapeOf<PolySpec>(s, 2);
  CHECK(p4.order == 4);
  REQUIRE(p4.coefficients.size() == 35);
  CHECK(p4.coefficients[0] == 1);     // x⁴
  CHECK(p4.coefficients[2] == -3);    // x³z
  CHECK(p4.coefficients[30] == 31);   // z⁴
  CHECK(p4.coefficients[31] == -32);  // z³
  CHECK(p4.coefficients[34] == 35);   // 1
  const auto& pn = shapeOf<PolySpec>(s, 3);
  std::vector<double> want(35, 0.0);
  want[0] = 1;    // x⁴
  want[31] = -2;  // z³, negated (the list ends z⁴, z³, z², z, 1)
  want[28] = -3;  // yz, negated (before it y⁴, y³z, y³, y²z², y²z, y², yz³, yz²)
  want[34] = -1;
  CHECK(pn.coefficients == want);
}

TEST_CASE("scene shapes: poly and polynomial above order 4, up to POV-Ray's 35",
          "[sdl][scene][shapes]") {
  // Order 6 has 84 terms: x⁶ first, then x⁵y, x⁵z, ...; z⁶ is the 78th, the constant last.
  std::string sextic = "poly { 6, <1";
  for (int i = 1; i < 84; ++i) sextic += i == 77 ? ", 2" : i == 83 ? ", -1" : ", 0";
  sextic += "> }\n";
  auto r = readScene(sextic + "polynomial { 35, xyz(0, 0, 35): 1, xyz(0, 0, 0): -1 }\n");
  REQUIRE(r->load.scene);
  const auto& p6 = shapeOf<PolySpec>(*r->load.scene, 0);
  CHECK(p6.order == 6);
  REQUIRE(p6.coefficients.size() == 84);
  CHECK(p6.coefficients[0] == 1);
  CHECK(p6.coefficients[77] == 2);  // z⁶: an even power, so not negated
  CHECK(p6.coefficients[83] == -1);
  const auto& p35 = shapeOf<PolySpec>(*r->load.scene, 1);
  CHECK(p35.order == 35);
  REQUIRE(p35.coefficients.size() == 8436);  // 36·37·38/6
  // z³⁵ is the first of the last 36 (z³⁵ ... z, 1), and odd: negated with z.
  CHECK(p35.coefficients[8436 - 36] == -1);
  CHECK(p35.coefficients.back() == -1);
  CHECK(errorsOf("poly { 36, <1> }\n")[0] ==
        "test.pov:1:8: error: the order of a poly must be from 2 to 35");
}

TEST_CASE("scene shapes: blob components, their transforms carried in", "[sdl][scene][shapes]") {
  auto r = readScene(R"(
blob {
  threshold 0.5
  sphere { <1, 2, 3>, 2, 1.5 }
  sphere { <0, 0, 1>, 1, strength -2 scale 2 translate <1, 0, 0> }
  cylinder { <0, 0, 0>, <0, 0, 2>, 0.5, strength 3 rotate y*90 }
  component 2, -0.5, <0, 1, 2>
  sturm hierarchy
}
)");
  REQUIRE(r->load.scene);
  const auto& b = shapeOf<BlobSpec>(*r->load.scene, 0);
  CHECK(b.threshold == 0.5);
  REQUIRE(b.components.size() == 4);
  CHECK(b.components[0].kind == BlobComponent::Sphere);
  checkVec(b.components[0].a, Vec3(1, 2, -3));
  CHECK(b.components[0].radius == 2.0);
  CHECK(b.components[0].strength == 1.5);
  checkVec(b.components[1].a, Vec3(1, 0, -2));
  CHECK(b.components[1].radius == 2.0);
  CHECK(b.components[1].strength == -2.0);
  CHECK(b.components[2].kind == BlobComponent::Cylinder);
  checkVec(b.components[2].a, Vec3(0, 0, 0));
  checkVec(b.components[2].b, Vec3(2, 0, 0));  // POV-Ray's rotate y*90 takes +z to +x
  CHECK(b.components[2].strength == 3.0);
  checkVec(b.components[3].a, Vec3(0, 1, -2));
  CHECK(b.components[3].radius == 0.5);  // POV-Ray keeps the square of the radius
  CHECK(b.components[3].strength == 2.0);
  for (const BlobComponent& c : b.components) CHECK(c.transform == Mat4(1.0));  // carried in
}

TEST_CASE("scene shapes: a blob component scaled unevenly keeps its transform",
          "[sdl][scene][shapes]") {
  auto r = readScene(R"(
blob {
  threshold 0.5
  sphere { <0, 0, 1>, 2, 1 scale <2, 1, 0.5> translate <0, 3, 1> }
}
)");
  REQUIRE(r->load.scene);
  const auto& b = shapeOf<BlobSpec>(*r->load.scene, 0);
  REQUIRE(b.components.size() == 1);
  const BlobComponent& c = b.components[0];
  checkVec(c.a, Vec3(0, 0, -1));  // the centre in the component's own space (z mirrored)
  CHECK(c.radius == 2.0);
  // S·M·S: POV-Ray's point (0, 0, 1) goes to (0, 3, 1.5), Lucent's (0, 0, -1) to (0, 3, -1.5).
  checkVec(Vec3(c.transform * Vec4(c.a, 1.0)), Vec3(0, 3, -1.5));
  checkVec(Vec3(c.transform * Vec4(1, 0, 0, 0)), Vec3(2, 0, 0));
  checkVec(Vec3(c.transform * Vec4(0, 0, 1, 0)), Vec3(0, 0, 0.5));
}

TEST_CASE("scene shapes: lathe, sor, prism and superellipsoid", "[sdl][scene][shapes]") {
  auto r = readScene(R"(
lathe { bezier_spline 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> sturm }
lathe { 3, <0, 0>, <1, 0.5>, <0, 1> }
sor { 4, <0, 0>, <1, 1>, <0.5, 2>, <1, 3> open }
prism { conic_sweep cubic_spline 1, 0.25, 7, <0, -1>, <1, 0>, <0, 1>, <-1, 0>, <0, -1>, <1, 0>,
        <0, 1> open }
prism { 0, 1, 3, <0, 0>, <1, 0>, <0, 2> }
superellipsoid { <0.25, 2> }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const auto& l = shapeOf<LatheSpec>(s, 0);
  CHECK(l.spline == LatheSpline::Bezier);
  CHECK(l.points == std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  CHECK(shapeOf<LatheSpec>(s, 1).spline == LatheSpline::Linear);
  const auto& sor = shapeOf<SorSpec>(s, 2);
  CHECK(sor.points == std::vector<Vec2>{{0, 0}, {1, 1}, {0.5, 2}, {1, 3}});
  CHECK(sor.open);
  const auto& p = shapeOf<PrismSpec>(s, 3);
  CHECK(p.spline == PrismSpline::Cubic);
  CHECK(p.conic);
  CHECK(p.open);
  CHECK(p.height1 == 0.25);  // POV-Ray puts the lower height first
  CHECK(p.height2 == 1.0);
  CHECK(p.points == std::vector<Vec2>{{0, 1}, {1, 0}, {0, -1}, {-1, 0}, {0, 1}, {1, 0}, {0, -1}});
  const auto& closed = shapeOf<PrismSpec>(s, 4);
  CHECK(!closed.conic);
  CHECK(closed.spline == PrismSpline::Linear);
  CHECK(closed.points == std::vector<Vec2>{{0, 0}, {1, 0}, {0, -2}});
  const auto& se = shapeOf<SuperellipsoidSpec>(s, 5);
  CHECK(se.e == 0.25);
  CHECK(se.n == 2.0);
  // The unclosed linear prism is closed with POV-Ray's warning.
  bool said = false;
  for (const std::string& w : r->out.warnings)
    said |= w.find("test.pov:7:1: warning: the prism's last polygon is not closed") == 0;
  CHECK(said);
}

TEST_CASE("scene shapes: lathes are open where POV-Ray's are, closed within a CSG",
          "[sdl][scene][shapes]") {
  auto r = readScene(R"(lathe { 3, <0, 0>, <1, 0>, <1, 1> }
lathe { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
lathe { 4, <0.5, 0>, <1, 0>, <1, 1>, <0.5, 0> }
difference { lathe { 3, <0, 0>, <1, 0>, <1, 1> } sphere { 0, 0.5 } }
union { lathe { 3, <0, 0>, <1, 0>, <1, 1> } sphere { 0, 0.5 } })");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  CHECK(shapeOf<LatheSpec>(s, 0).open);        // its end is off the axis: no disc
  CHECK_FALSE(shapeOf<LatheSpec>(s, 1).open);  // from the axis to the axis
  CHECK_FALSE(shapeOf<LatheSpec>(s, 2).open);  // back where it started
  const auto childLathe = [&](size_t i) {
    const Node& csg = topNode(s, i);
    REQUIRE(!csg.children.empty());
    REQUIRE(csg.children[0]->shape);
    return std::get<LatheSpec>(*csg.children[0]->shape);
  };
  CHECK_FALSE(childLathe(3).open);  // a difference asks its inside: a solid
  CHECK(childLathe(4).open);        // a union does not
  size_t said = 0;
  for (const std::string& w : r->out.warnings)
    said += w.find(
                "test.pov:4:14: warning: in an intersection, difference, merge or clip "
                "Lucent's lathe is a solid") == 0;
  CHECK(said == 1);
}

TEST_CASE("scene shapes: a height field that clips is closed, as in a CSG",
          "[sdl][scene][shapes][clip]") {
  auto r = readScene(R"(sphere { <0.5, 0.5, 0.5>, 0.6
  clipped_by { height_field { pgm "hf.pgm" } } })");
  REQUIRE(r->load.scene);
  const Node& sphere = *r->load.scene->root->children.at(0);
  REQUIRE(sphere.clip.size() == 1);
  const Node* field = sphere.clip[0].get();
  while (!field->shape && !field->children.empty()) field = field->children[0].get();
  REQUIRE(field->shape);
  CHECK_FALSE(std::get<HeightFieldSpec>(*field->shape).open);
  size_t said = 0;
  for (const std::string& w : r->out.warnings)
    said += w.find("merge or clip Lucent's height field is a solid") != std::string::npos;
  CHECK(said == 1);
}

TEST_CASE("scene shapes: text, its font found in POV-Ray's include folder",
          "[sdl][scene][shapes]") {
  auto r = readScene(R"(text { ttf "timrom.ttf" "Lu" 0.25, <0.1, 0, 0> })");
  REQUIRE(r->load.scene);
  const auto& t = shapeOf<TextSpec>(*r->load.scene, 0);
  CHECK(t.font == "timrom.ttf");
  CHECK(std::filesystem::path(t.fontPath).filename() == "timrom.ttf");
  CHECK(t.string == "Lu");
  CHECK(t.thickness == 0.25);
  CHECK(t.offset == Vec2(0.1, 0.0));
  REQUIRE(t.outline);
  CHECK(t.outline->glyphs.size() == 2);
  // POV-Ray's text lies from z = 0 to 0.25, Lucent's too: moved to [−0.25, 0] after z → −z.
  checkMat(topNode(*r->load.scene, 0).parentFromNode,
           PovTransform::translation(Vec3(0, 0, 0.25)).lucentMatrix());
  CHECK(topNode(*r->load.scene, 0).parentFromNode[3][2] == -0.25);
  // POV-Ray adds the font type's extensions; its internal fonts are the files it ships.
  auto more = readScene(R"(text { ttf "cyrvetic" "a" 1, 0 }
text { internal 3 "a" 1, 0 })");
  REQUIRE(more->load.scene);
  CHECK(std::filesystem::path(shapeOf<TextSpec>(*more->load.scene, 0).fontPath).filename() ==
        "cyrvetic.ttf");
  CHECK(shapeOf<TextSpec>(*more->load.scene, 1).font == "crystal.ttf");
}

TEST_CASE("scene shapes: height_field, mirrored into Lucent's space", "[sdl][scene][shapes]") {
  auto r = readScene(R"(height_field { pgm "hf.pgm" smooth water_level 0.1 hierarchy off }
height_field { "hf.pgm" })");
  REQUIRE(r->load.scene);
  const auto& h = shapeOf<HeightFieldSpec>(*r->load.scene, 0);
  CHECK(h.src == "hf.pgm");
  CHECK(std::filesystem::path(h.path).filename() == "hf.pgm");
  CHECK(h.smooth);
  CHECK(h.waterLevel == 0.1);
  REQUIRE(h.map);
  CHECK(h.map->width == 3);
  CHECK(h.map->depth == 2);
  CHECK(h.map->at(0, 0) > h.map->at(0, 1));  // row z = 0 is the image's bottom row
  checkMat(topNode(*r->load.scene, 0).parentFromNode,
           PovTransform::scaling(Vec3(1, 1, -1)).lucentMatrix());
  CHECK(!shapeOf<HeightFieldSpec>(*r->load.scene, 1).smooth);
  // POV-Ray's height field has neither walls nor a floor: open, nothing to say.
  CHECK(h.open);
  CHECK(shapeOf<HeightFieldSpec>(*r->load.scene, 1).open);
  CHECK(r->out.warnings.empty());
  // Within an intersection it stays a closed solid, said.
  auto csg = readScene(R"(intersection { height_field { "hf.pgm" } box { 0, 0.5 } })");
  REQUIRE(csg->load.scene);
  const Node& n = topNode(*csg->load.scene, 0);
  REQUIRE(n.children.size() == 2);
  CHECK_FALSE(std::get<HeightFieldSpec>(*n.children[0]->shape).open);
  bool said = false;
  for (const std::string& w : csg->out.warnings)
    said |=
        w.find("Lucent's height field is a solid closed by walls and a floor") != std::string::npos;
  CHECK(said);
}

TEST_CASE("scene shapes: height_field of a function, sampled where it is read",
          "[sdl][scene][shapes]") {
  auto r = readScene(R"(height_field { function 3.4, 2.5 { x + 0.25*y } smooth }
#declare P = pigment { gradient x color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } }
height_field { function 5, 2 { pigment { P } } })");
  REQUIRE(r->load.scene);
  const auto& h = shapeOf<HeightFieldSpec>(*r->load.scene, 0);
  CHECK(h.smooth);
  CHECK(h.open);
  CHECK(h.src.empty());
  CHECK(h.resolution[0] == 3);  // POV-Ray rounds the sizes
  CHECK(h.resolution[1] == 3);
  REQUIRE(h.map);
  REQUIRE(h.map->width == 3);
  REQUIRE(h.map->depth == 3);
  // Row z = 0 takes the function at y = 1 (POV-Ray's function image read bottom up).
  CHECK(h.map->at(0, 0) == heightOfFunctionValue(0.25));
  CHECK(h.map->at(2, 0) == heightOfFunctionValue(1.25));  // wrapped, as POV-Ray's
  CHECK(h.map->at(1, 2) == heightOfFunctionValue(0.5));
  CHECK(h.map->at(1, 1) == heightOfFunctionValue(0.5 + 0.125));
  checkMat(topNode(*r->load.scene, 0).parentFromNode,
           PovTransform::scaling(Vec3(1, 1, -1)).lucentMatrix());
  // A pigment function's height is its grey: 0.297 r + 0.589 g at x = 0.5 (gradient x).
  const auto& g = shapeOf<HeightFieldSpec>(*r->load.scene, 1);
  REQUIRE(g.map);
  CHECK(g.pigments.size() == 1);
  const double grey = 0.297 * 0.5 + 0.589 * 0.25;
  CHECK(std::abs(int(g.map->at(2, 0)) - int(heightOfFunctionValue(grey))) <= 1);
  CHECK(g.map->at(0, 1) == 0);
}

TEST_CASE("scene shapes: mesh and mesh2 as inline meshes", "[sdl][scene][shapes]") {
  auto r = readScene(R"(
mesh {
  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 1> uv_vectors <0, 0>, <1, 0>, <0, 1> }
  triangle { <0, 0, 0>, <1, 0, 0>, <2, 0, 0> }
  smooth_triangle { <1, 0, 0>, <0, 0, -1>, <1, 1, 0>, <1, 0, 0>, <0, 1, 1>, <0, 2, 0> }
  inside_vector y
}
mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <0, 0, 1>, <0, 1, 0> }
  normal_vectors { 2, <0, 1, 0>, <0, 0, 1> }
  face_indices { 2, <0, 1, 2>, <0, 1, 3> }
  normal_indices { 2, <0, 0, 1>, <0, 1, 1> }
}
)");
  REQUIRE(r->load.scene);
  const auto& m = shapeOf<MeshSpec>(*r->load.scene, 0);
  REQUIRE(m.data);
  // The degenerate triangle is dropped, as POV-Ray drops it; each triangle keeps its corners.
  REQUIRE(m.data->triangles.size() == 2);
  REQUIRE(m.data->positions.size() == 6);
  std::vector<Vec3> corners;
  for (const auto& t : m.data->triangles)
    for (uint32_t i : t) corners.push_back(m.data->positions[i]);
  CHECK(std::count(corners.begin(), corners.end(), Vec3(0, 1, -1)) == 2);
  CHECK(std::count(corners.begin(), corners.end(), Vec3(1, 1, 0)) == 1);
  // Normals: the flat triangle's face normal at its corners, the smooth one's own (unit, z
  // negated).
  REQUIRE(m.data->normals.size() == 6);
  CHECK(std::count(m.data->normals.begin(), m.data->normals.end(), Vec3(0, 0, 1)) == 1);
  CHECK(std::count(m.data->normals.begin(), m.data->normals.end(), Vec3(0, 1, 0)) == 1);
  // One triangle has uvs: the other's are POV-Ray's (0, 0) (its Parse_Three_UVCoords).
  REQUIRE(m.data->uvs.size() == 6);
  CHECK(std::count(m.data->uvs.begin(), m.data->uvs.end(), Vec2(0.0)) == 4);
  CHECK(std::count(m.data->uvs.begin(), m.data->uvs.end(), Vec2(0, 1)) == 1);
  const auto& m2 = shapeOf<MeshSpec>(*r->load.scene, 1);
  REQUIRE(m2.data);
  REQUIRE(m2.data->triangles.size() == 2);
  REQUIRE(m2.data->normals.size() == 6);
  CHECK(std::count(m2.data->normals.begin(), m2.data->normals.end(), Vec3(0, 0, -1)) == 3);
  // POV-Ray's mesh is solid only with inside_vector, Lucent's when closed: both said.
  bool said = false;
  for (const std::string& w : r->out.warnings)
    said |= w.find("test.pov:2:1: warning: the mesh has an inside_vector but is not closed") == 0;
  CHECK(said);
}

TEST_CASE("scene shapes: a mesh's triangle textures make a union of a mesh per texture",
          "[sdl][scene][shapes][mesh]") {
  auto r = readScene(R"(
#declare A = texture { pigment { rgb <1, 0, 0> } }
#declare B = texture { pigment { rgb <0, 0, 1> } }
mesh {
  triangle { 0, x, y texture { A } }
  triangle { x, x + y, y texture_list { B, B, B } }
  triangle { 0, y, z }
  triangle { 0, x, z texture { A } }
  pigment { rgb <0, 1, 0> }
}
mesh2 {
  vertex_vectors { 4, 0, x, y, z }
  texture_list { 2, texture { A } texture { B } }
  face_indices { 3, <0, 1, 2>, 1, <0, 2, 3>, 1, 1, 1, <0, 1, 3> }
}
)");
  REQUIRE(r->load.scene);
  const Scene& scene = *r->load.scene;
  // The mesh's own triangles first (the one without a texture), then a mesh per texture, in
  // the order the textures were first written; the triangles of one texture together.
  const Node& mesh = topNode(scene, 0);
  CHECK(mesh.kind == NodeKind::Union);
  REQUIRE(mesh.children.size() == 3);
  const size_t triangles[] = {1, 2, 1};
  for (size_t k = 0; k < 3; ++k) {
    const auto* m = std::get_if<MeshSpec>(&*mesh.children[k]->shape);
    REQUIRE(m);
    CHECK(m->data->triangles.size() == triangles[k]);
  }
  // The untextured triangles take the mesh's material; the others their texture's.
  REQUIRE(mesh.material);
  CHECK(scene.materials[*mesh.material].diffuse == Color(0.0f, 0.6f, 0.0f));
  CHECK(!mesh.children[0]->material);
  REQUIRE(mesh.children[1]->material);
  CHECK(scene.materials[*mesh.children[1]->material].diffuse == Color(0.6f, 0.0f, 0.0f));
  REQUIRE(mesh.children[2]->material);
  CHECK(scene.materials[*mesh.children[2]->material].diffuse == Color(0.0f, 0.0f, 0.6f));
  // A mesh2 face without an index takes the mesh's texture; three equal indices are one.
  const Node& mesh2 = topNode(scene, 1);
  REQUIRE(mesh2.children.size() == 2);
  CHECK(std::get<MeshSpec>(*mesh2.children[0]->shape).data->triangles.size() == 1);
  CHECK(std::get<MeshSpec>(*mesh2.children[1]->shape).data->triangles.size() == 2);
  REQUIRE(mesh2.children[1]->material);
  CHECK(scene.materials[*mesh2.children[1]->material].diffuse == Color(0.0f, 0.0f, 0.6f));
}

TEST_CASE("scene shapes: a mesh's triangle textures wrongly written, said where they are",
          "[sdl][scene][shapes][mesh][errors]") {
  const auto index = errorsOf(R"(mesh2 { vertex_vectors { 3, 0, x, y }
  texture_list { 1, texture { } } face_indices { 1, <0, 1, 2>, 1 } })");
  REQUIRE(index.size() == 1);
  CHECK(index[0] ==
        "test.pov:2:64: error: the face's texture index 1 is outside the mesh2's "
        "texture_list of 1 textures");
  const auto second = errorsOf(R"(mesh2 { vertex_vectors { 3, 0, x, y }
  texture_list { 1, texture { } } texture_list { 1, texture { } } face_indices { 1, <0, 1, 2> } })");
  REQUIRE(second.size() == 1);
  CHECK(second[0] == "test.pov:2:35: error: the mesh2 has a second texture_list");
  // POV-Ray's mesh triangle takes declared textures only.
  const auto inline_ = errorsOf("mesh { triangle { 0, x, y texture { pigment { rgb 1 } } } }");
  REQUIRE(inline_.size() == 1);
  CHECK(inline_[0].find("test.pov:1:37: error: a mesh triangle's texture takes a declared "
                        "texture (as in POV-Ray), not ") == 0);
  const auto extra = errorsOf(R"(mesh2 { vertex_vectors { 3, 0, x, y }
  face_indices { 1, <0, 1, 2> <0, 1, 2> } })");
  REQUIRE(extra.size() == 1);
  CHECK(extra[0].find("test.pov:2:31: error: ") == 0);
}

TEST_CASE("scene shapes: smooth_triangle, its normals unit and z negated", "[sdl][scene][shapes]") {
  auto r = readScene(
      "smooth_triangle { <0, 0, 1>, <0, 0, -2>, <1, 0, 1>, <0, 3, 0>, <0, 1, 2>, "
      "<1, 0, 0> }");
  REQUIRE(r->load.scene);
  const auto& t = shapeOf<TriangleSpec>(*r->load.scene, 0);
  checkVec(t.a, Vec3(0, 0, -1));
  checkVec(t.c, Vec3(0, 1, -2));
  REQUIRE(t.normals);
  checkVec((*t.normals)[0], Vec3(0, 0, 1));
  checkVec((*t.normals)[1], Vec3(0, 1, 0));
  checkVec((*t.normals)[2], Vec3(1, 0, 0));
}

TEST_CASE("scene shapes: declared and placed, and in CSG", "[sdl][scene][shapes]") {
  auto r = readScene(R"(
#declare B = blob { sphere { 0, 1, 1 } }
#declare L = lathe { 2, <1, 0>, <1, 1> }
#declare S = sor { 4, <0, 0>, <1, 1>, <0.5, 2>, <1, 3> }
#declare P = prism { 0, 1, 4, <0, 0>, <1, 0>, <0, 1>, <0, 0> }
#declare E = superellipsoid { <1, 1> }
#declare M = mesh { triangle { 0, x, y } }
union { object { B } object { L } object { S } object { P } object { E } object { M } }
)");
  REQUIRE(r->load.scene);
  REQUIRE(topNode(*r->load.scene, 0).children.size() == 6);
}

TEST_CASE("scene shapes: what Lucent cannot take in a shape, refused where it is, every one",
          "[sdl][scene][shapes][errors]") {
  // Every POV-Ray 3.7 shape is read; what is refused is within one (a height field's image
  // format, a mesh face's texture per corner, superellipsoid exponents).
  const auto errors = errorsOf(R"(sphere { 0, 1 }
union { height_field { iff "x.iff" }
        sphere { 0, 1 } }
#declare P = height_field { iff "x.iff" } object { P }
height_field { sys "x.sys" }
mesh2 { vertex_vectors { 3, 0, x, y } texture_list { 2, texture { } texture { } } face_indices { 1, <0, 1, 2>, 0, 1, 1 } }
superellipsoid { <0, 1> }
height_field { iff "x.iff" }
)");
  REQUIRE(errors.size() == 6);
  CHECK(errors[0] ==
        "test.pov:2:24: error: a height field from 'iff' is not supported by Lucent (it reads "
        "png, pgm, ppm, tga, jpeg, tiff, gif and pot images as height fields)");
  // A declared object's refusal is said where it is used, with that place as a note.
  CHECK(errors[1] ==
        "test.pov:4:29: error: a height field from 'iff' is not supported by Lucent (it reads "
        "png, pgm, ppm, tga, jpeg, tiff, gif and pot images as height fields)\ntest.pov:4:52: "
        "note: the "
        "declaration is used here");
  CHECK(errors[2].find("test.pov:5:16: error: a height field from 'sys' is not supported") == 0);
  CHECK(errors[3].find("test.pov:6:110: error: a texture per corner of a mesh2 face (three "
                       "different texture indices, which POV-Ray blends across the face) is not "
                       "supported by Lucent") == 0);
  CHECK(errors[4].find("test.pov:7:1: error: 'superellipsoid' exponents of 0 or less, or above "
                       "10, are not supported by Lucent (here <0, 1>") == 0);
  CHECK(errors[5].find("test.pov:8:16: error: a height field from 'iff' is not supported") == 0);
}

TEST_CASE("scene shapes: a declared shape Lucent cannot render is refused where it is placed",
          "[sdl][scene][shapes][errors]") {
  // shapesq.inc declares polys of orders 5 to 8 among its quartics (read since poly takes
  // every order POV-Ray does): a scene that uses a quartic is read. (Its helix is clipped by
  // shapes.inc's Cylinder_Z, which it does not include: POV-Ray needs shapes.inc first, too.)
  auto r = readScene(R"(#include "shapes.inc"
#include "shapesq.inc"
object { Monkey_Saddle }
#declare J = height_field { iff "x.iff" }
#declare A = texture { pigment { rgb 1 } }
#declare B = texture { pigment { rgb 0 } }
#declare Meshes = union { mesh { triangle { 0, x, y texture_list { A, B, A } } } sphere { 0, 1 } }
)");
  REQUIRE(r->load.scene);
  CHECK(shapeOf<PolySpec>(*r->load.scene, 0).order == 4);  // a quartic
  // Placed (twice), each refusal is said once, at its keyword.
  const auto errors = errorsOf(
      R"(#declare J = height_field { iff "x.iff" }
#declare A = texture { pigment { rgb 1 } }
#declare B = texture { pigment { rgb 0 } }
#declare Meshes = union { mesh { triangle { 0, x, y texture_list { A, B, A } } } sphere { 0, 1 } }
object { J }
object { Meshes translate x }
object { Meshes }
)");
  REQUIRE(errors.size() == 2);
  CHECK(errors[0].find("test.pov:1:29: error: a height field from 'iff' is not supported") == 0);
  CHECK(errors[1].find("test.pov:4:53: error: a texture per corner of a mesh triangle") == 0);
}

TEST_CASE("scene shapes: blob thresholds and mesh triangles Lucent cannot hold",
          "[sdl][scene][shapes][errors]") {
  const auto errors = errorsOf(R"(blob {
  sphere { 0, 1, 1 scale <1, 2, 1> }
  sphere { 0, 1, 1 pigment { rgb 1 } }
  threshold 0.5
}
blob { sphere { 0, 1, 1 } threshold -1 }
#declare A = texture { pigment { rgb 1 } } #declare B = texture { A }
mesh { triangle { 0, x, y texture_list { A, B, A } } }
mesh2 { vertex_vectors { 3, 0, x, y } texture_list { 2, texture { } texture { } } face_indices { 1, <0, 1, 2>, 1, 0, 1 } }
)");
  // The first blob is read: the first component scaled unevenly (its own transform), the
  // second with its own pigment.
  REQUIRE(errors.size() == 3);
  CHECK(errors[0] ==
        "test.pov:6:1: error: a blob threshold of -1 is not supported by Lucent (it takes a "
        "threshold above 0: at or below 0 all of space away from the components would be inside)");
  CHECK(errors[1].find("test.pov:8:27: error: a texture per corner of a mesh triangle") == 0);
  CHECK(errors[2].find("test.pov:9:110: error: a texture per corner of a mesh2 face") == 0);
}

TEST_CASE("scene shapes: a blob component's own texture is a material of the blob's space",
          "[sdl][scene][shapes][blob]") {
  auto r = readScene(R"(
blob {
  threshold 0.5
  sphere { 0, 1, 1 pigment { rgb <1, 0, 0> } translate x }
  cylinder { 0, y, 0.5, 1 }
  sphere { 0, 1, 1 translate z texture { pigment { checker rgb 0, rgb 1 } } scale 2 }
  pigment { rgb <0, 0, 1> }
}
blob { sphere { 0, 1, 1 } sphere { x, 1, 1 } }
)");
  REQUIRE(r->load.scene);
  const Scene& scene = *r->load.scene;
  const Node& n = topNode(scene, 0);
  const auto& b = shapeOf<BlobSpec>(scene, 0);
  REQUIRE(b.components.size() == 3);
  REQUIRE(b.componentMaterials.size() == 3);
  REQUIRE(b.componentMaterials[0]);
  CHECK_FALSE(b.componentMaterials[1]);  // the blob's own
  REQUIRE(b.componentMaterials[2]);
  REQUIRE(n.material);
  CHECK(scene.materials[*b.componentMaterials[0]].diffuse.r > 0.0f);
  CHECK(scene.materials[*b.componentMaterials[0]].diffuse.b == 0.0f);
  CHECK(scene.materials[*n.material].diffuse.r == 0.0f);
  CHECK(b.componentMaterials[0] != b.componentMaterials[2]);
  // The checker was written after `translate z`: it follows only `scale 2` (z negated).
  const auto* checker =
      std::get_if<CheckerTexture>(&scene.materials[*b.componentMaterials[2]].texture);
  REQUIRE(checker);
  CHECK(checker->placement.patternFromObject[0][0] == Approx(0.5));
  CHECK(shapeOf<BlobSpec>(scene, 1).componentMaterials.empty());
}

TEST_CASE("scene shapes: bad input, located", "[sdl][scene][shapes][errors]") {
  struct Case {
    const char* text;
    const char* error;
  };
  const Case cases[] = {
      {"poly { 1, <1, 2, 3, 4> }", "test.pov:1:8: error: the order of a poly must be from 2 to 35"},
      {"poly { 2, <1, 2, 3> }", "test.pov:1:19: error: expected a numeric expression, found '>'"},
      {"quadric { 0, 0, 0, 1 }",
       "test.pov:1:1: error: the quadric's coefficients are all 0 but the constant: it has no "
       "surface"},
      {"polynomial { 2, xyz(3, 0, 0): 1 }",
       "test.pov:1:17: error: xyz(3, 0, 0) is not a term of a polynomial of order 2"},
      {"lathe { quadratic_spline 2, <0, 0>, <1, 1> }",
       "test.pov:1:26: error: a quadratic lathe needs 3 points or more, not 2"},
      {"sor { 4, <0, 0>, <1, 1>, <1, 0.5>, <1, 3> }",
       "test.pov:1:1: error: point 3 of the sor is incorrect (x < 0, or not above the point "
       "before)"},
      {"prism { bezier_spline 0, 1, 5, <0, 0>, <1, 0>, <0, 1>, <0, 0>, <1, 1> }",
       "test.pov:1:29: error: a bezier prism needs 4 points a segment, not 5"},
      {"blob { cylinder { 0, 0, 1, 1 } }",
       "test.pov:1:8: error: the blob's cylinder component has no length (its ends are the same "
       "point)"},
      {"blob { threshold 0.5 }", "test.pov:1:1: error: the blob has no component"},
      {"superellipsoid { <1, 1, 1> }",
       "test.pov:1:18: error: a 2-D vector <u, v> expected, not one of 3 components"},
      {"text { ttf \"nofont.ttf\" \"a\" 1, 0 }",
       "test.pov:1:12: error: cannot find the file 'nofont.ttf' (searched "},
      {"text { ttf \"hf.pgm\" \"a\" 1, 0 }",
       "test.pov:1:12: error: cannot read the font 'hf.pgm': "},
      {"text { ttf \"timrom.ttf\" \"a\" 0, 0 }",
       "test.pov:1:29: error: the text's thickness must be above 0 in Lucent, not 0"},
      {"height_field { png \"none.png\" }",
       "test.pov:1:20: error: cannot find the file 'none.png' (searched "},
      {"height_field { pgm \"hf.pgm\" water_level 1 }",
       "test.pov:1:29: error: the water level must be from 0 to below 1, not 1"},
      {"height_field { function 1, 8 { x } }",
       "test.pov:1:25: error: the function height field's width must be from 2 to 4096, not 1"},
      {"height_field { function 8, 5000 { x } }",
       "test.pov:1:28: error: the function height field's height must be from 2 to 4096, not 5000"},
      {"height_field { function 8, 8 { x + nosuch } }", "test.pov:1:36: error: "},
      {"mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0, 1, 3> } }",
       "test.pov:1:1: error: the mesh2's vertex index 3 is outside its 3 vectors"},
      {"smooth_triangle { 0, y, x, 0, z, y }",
       "test.pov:1:28: error: the smooth_triangle's normal has no length"},
      {"mesh { triangle { 0, x, 2*x } }",
       "test.pov:1:1: error: the mesh has no triangle (of some area)"},
  };
  for (const Case& c : cases) {
    INFO(c.text);
    const auto errors = errorsOf(c.text);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].substr(0, std::string(c.error).size()) == c.error);
  }
}

TEST_CASE("scene shapes: polygon, 2-D points at z = 0, closed as POV-Ray closes it",
          "[sdl][scene][shapes]") {
  auto r = readScene(R"(
polygon { 5, <0, 0>, <1, 0, 0>, <1, 1, 2>, <0, 1, 2>, <0, 0, 0> }
polygon { 3, <0, 0>, <1, 0>, <0, 1>, }
#declare P = polygon { 4, <0, 0>, <2, 0>, <0, 2>, <0, 0> }
object { P translate x }
)");
  REQUIRE(r->load.scene);
  const auto& a = shapeOf<PolygonSpec>(*r->load.scene, 0);
  REQUIRE(a.points.size() == 5);
  checkVec(a.points[2], Vec3(1, 1, -2));  // z negated
  checkVec(a.points[4], Vec3(0, 0, 0));
  const auto& b = shapeOf<PolygonSpec>(*r->load.scene, 1);
  REQUIRE(b.points.size() == 3);  // closed when built
  CHECK(shapeOf<PolygonSpec>(*r->load.scene, 2).points.size() == 4);
  const auto warnings = warningsOf(*r);
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0].find("test.pov:3:1: warning: the polygon's last outline is not closed") == 0);
}

TEST_CASE("scene shapes: a polygon POV-Ray ignores is left out, with a warning",
          "[sdl][scene][shapes]") {
  auto r = readScene(R"(
polygon { 5, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0.001>, <0, 0, 0> }
polygon { 4, <0, 0>, <1, 1>, <2, 2>, <0, 0> }
sphere { 0, 1 }
)");
  REQUIRE(r->load.scene);
  REQUIRE(r->load.scene->root->children.size() == 3);
  for (size_t i = 0; i < 2; ++i) {
    const Node& n = topNode(*r->load.scene, i);
    CHECK(n.kind == NodeKind::Group);
    CHECK(n.children.empty());
  }
  const auto warnings = warningsOf(*r);
  REQUIRE(warnings.size() == 2);
  CHECK(warnings[0].find("test.pov:2:1: warning: the polygon is left out, as POV-Ray ignores "
                         "it: the points do not lie in one plane (point 4") == 0);
  CHECK(warnings[1].find("test.pov:3:1: warning: the polygon is left out, as POV-Ray ignores "
                         "it: the points lie on one line") == 0);
}

TEST_CASE("scene shapes: bicubic_patch, keywords and POV-Ray 1.5's numbers",
          "[sdl][scene][shapes]") {
  auto r = readScene(R"(
#declare Row = 0;
bicubic_patch { type 1 flatness 0.01 u_steps 4 v_steps 3 accuracy 0.001,
  <0, 0, 2>, <1, 0, 0>, <2, 0, 0>, <3, 0, -2>, <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1, 0>,
  <0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2, 0>, <0, 3, 2>, <1, 3, 0>, <2, 3, 0>, <3, 3, -2> }
bicubic_patch { 0, 2, 5
  0 x 2*x 3*x y x+y 2*x+y 3*x+y 2*y x+2*y 2*x+2*y 3*x+2*y 3*y x+3*y 2*x+3*y 3*x+3*y }
bicubic_patch { 3, 0.5, 1, 1
  0 x 2*x 3*x y x+y 2*x+y 3*x+y 2*y x+2*y 2*x+2*y 3*x+2*y 3*y x+3*y 2*x+3*y 3*x+3*y }
)");
  REQUIRE(r->load.scene);
  const auto& a = shapeOf<BicubicPatchSpec>(*r->load.scene, 0);
  CHECK(a.type == 1);
  CHECK(a.flatness == 0.01);
  CHECK(a.uSteps == 4);
  CHECK(a.vSteps == 3);
  CHECK(a.flatnessInWorld);
  checkVec((*a.points)[0], Vec3(0, 0, -2));
  checkVec((*a.points)[15], Vec3(3, 3, 2));
  const auto& b = shapeOf<BicubicPatchSpec>(*r->load.scene, 1);
  CHECK(b.type == 0);
  CHECK(b.flatness == 0.1);  // the old syntax's flatness for types 0 and 1
  CHECK(b.uSteps == 2);
  CHECK(b.vSteps == 5);
  checkVec((*b.points)[6], Vec3(2, 1, 0));
  const auto& c = shapeOf<BicubicPatchSpec>(*r->load.scene, 2);
  CHECK(c.type == 1);  // type 3 is type 1, with POV-Ray's warning
  CHECK(c.flatness == 0.5);
  const auto warnings = warningsOf(*r);
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0].find("test.pov:8:1: warning: bicubic_patch type 3 is type 1") == 0);
}

TEST_CASE("scene shapes: bad polygons and bicubic patches", "[sdl][scene][shapes][errors]") {
  CHECK(errorsOf("polygon { 2, <0, 0>, <1, 0> }") ==
        std::vector<std::string>{
            "test.pov:1:11: error: a polygon needs at least three points, not 2"});
  CHECK(errorsOf("bicubic_patch { type 1 u_steps 11 <0,0,0> }") ==
        std::vector<std::string>{"test.pov:1:32: error: the u_steps must be from 0 to 10"});
  CHECK(
      errorsOf("bicubic_patch { u_steps 2 v_steps 2 0 x 2*x 3*x y x+y 2*x+y 3*x+y 2*y x+2*y "
               "2*x+2*y 3*x+2*y 3*y x+3*y 2*x+3*y 3*x+3*y }") ==
      std::vector<std::string>{"test.pov:1:1: error: the bicubic_patch has no type (type 0 or 1)"});
  const auto fifteen = errorsOf(
      "bicubic_patch { type 0 0 x 2*x 3*x y x+y 2*x+y 3*x+y 2*y x+2*y 2*x+2*y 3*x+2*y 3*y x+3*y "
      "2*x+3*y }");
  REQUIRE(fifteen.size() == 1);
  CHECK(fifteen[0].find("test.pov:1:") == 0);
  // uv_vectors end the keywords, as in POV-Ray: a keyword after them is no control point.
  const auto late = errorsOf(
      "bicubic_patch { type 0 uv_vectors <0,0>,<1,0>,<1,1>,<0,1> u_steps 2 0 x 2*x 3*x y x+y "
      "2*x+y 3*x+y 2*y x+2*y 2*x+2*y 3*x+2*y 3*y x+3*y 2*x+3*y 3*x+3*y }");
  REQUIRE(late.size() == 1);
  CHECK(late[0].find("test.pov:1:59: error: expected a numeric expression, found 'u_steps'") == 0);
}

TEST_CASE("scene shapes: a bicubic patch's uv_vectors are its corners' (u, v)",
          "[sdl][scene][shapes][uv-mapping]") {
  auto r = readScene(
      "bicubic_patch { type 0 u_steps 1 uv_vectors <0.5, 0> <2, 0.25>, <1, 1.5> <-1, 1> 0 x 2*x "
      "3*x y x+y 2*x+y 3*x+y 2*y x+2*y 2*x+2*y 3*x+2*y 3*y x+3*y 2*x+3*y 3*x+3*y }\n"
      "bicubic_patch { type 0 0 x 2*x 3*x y x+y 2*x+y 3*x+y 2*y x+2*y 2*x+2*y 3*x+2*y 3*y x+3*y "
      "2*x+3*y 3*x+3*y }");
  REQUIRE(r->load.scene);
  const auto& a = shapeOf<BicubicPatchSpec>(*r->load.scene, 0);
  CHECK(a.uSteps == 1);
  const PatchUvCorners want = {Vec2(0.5, 0), Vec2(2, 0.25), Vec2(1, 1.5), Vec2(-1, 1)};
  CHECK(a.uvVectors == want);
  CHECK(shapeOf<BicubicPatchSpec>(*r->load.scene, 1).uvVectors == kPatchOwnUv);
}

TEST_CASE("scene shapes: julia_fractal, its keywords in any order, mirrored in z",
          "[sdl][scene][shapes][julia]") {
  auto r = readScene(R"(
julia_fractal { <-0.083, 0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15 }
julia_fractal { <0.4, 0.3, 0.1, 0.05> precision 0.5 max_iteration -3 pwr(2, 0.1)
                slice <0, 0, 0.2, 1>, 0.1 hypercomplex }
julia_fractal { 0.3 hypercomplex atanh cube }
)");
  REQUIRE(r->load.scene);
  const auto& a = shapeOf<JuliaFractalSpec>(*r->load.scene, 0);
  CHECK(a.c == Vec4(-0.083, 0.0, -0.83, -0.025));
  CHECK(a.algebra == JuliaAlgebra::Quaternion);
  CHECK(a.function == JuliaFunction::Sqr);
  CHECK(a.maxIteration == 8);
  CHECK(a.precision == 15.0);
  CHECK(a.slice == Vec4(0.0, 0.0, 0.0, 1.0));
  // The map is the same in both spaces: the shape is mirrored in z first.
  checkMat(topNode(*r->load.scene, 0).parentFromNode,
           PovTransform::scaling(Vec3(1, 1, -1)).lucentMatrix());
  const auto& b = shapeOf<JuliaFractalSpec>(*r->load.scene, 1);
  CHECK(b.algebra == JuliaAlgebra::Hypercomplex);
  CHECK(b.function == JuliaFunction::Pwr);
  CHECK(b.exponent == Vec2(2.0, 0.1));
  CHECK(b.precision == 1.0);   // below 1: 1, as POV-Ray makes it
  CHECK(b.maxIteration == 1);  // below 1: 1
  CHECK(b.slice == Vec4(0.0, 0.0, 0.2, 1.0));
  CHECK(b.distance == 0.1);
  const auto& c = shapeOf<JuliaFractalSpec>(*r->load.scene, 2);
  CHECK(c.c == Vec4(0.3));                   // a float is all four components
  CHECK(c.function == JuliaFunction::Cube);  // the last function given counts
  CHECK(warningsOf(*r).empty());
}

TEST_CASE("scene shapes: julia_fractal's errors are POV-Ray's", "[sdl][scene][shapes][errors]") {
  CHECK(errorsOf("julia_fractal { <0.1, 0.2, 0.3, 0> exp }") ==
        std::vector<std::string>{"test.pov:1:36: error: illegal function: quaternion only "
                                 "supports sqr and cube (POV-Ray's error)"});
  CHECK(errorsOf("julia_fractal { <0.1, 0.2, 0.3, 0> slice <1, 0, 0, 0>, 0 }") ==
        std::vector<std::string>{
            "test.pov:1:36: error: the julia_fractal's slice t component is zero"});
  CHECK(errorsOf("julia_fractal { <0.1, 0.2, 0.3, 0> slice 0, 0 }") ==
        std::vector<std::string>{"test.pov:1:36: error: the julia_fractal's slice vector is zero"});
}

TEST_CASE("scene shapes: sphere_sweep, its splines and tolerance, centres mirrored in z",
          "[sdl][scene][shapes][sweep]") {
  auto r = readScene(R"(
sphere_sweep { linear_spline 2, <0, 0, 1>, 0.5, <1, 2, 3>, 0.25 }
sphere_sweep { cubic_spline, 4.7, <0, 0, 0>, 1 <1, 0, 0>, 1, <2, 0, 0>, 1, <3, 0, 0>, 1 tolerance 0.01 }
sphere_sweep { b_spline 4 <0, 0, 0> 1 <1, 0, 0> 1 <2, 0, 0> 1 <3, 0, 0> 0 }
)");
  REQUIRE(r->load.scene);
  const auto& a = shapeOf<SphereSweepSpec>(*r->load.scene, 0);
  CHECK(a.spline == SweepSpline::Linear);
  REQUIRE(a.spheres.size() == 2);
  CHECK(a.spheres[0].center == Vec3(0, 0, -1));
  CHECK(a.spheres[1].center == Vec3(1, 2, -3));
  CHECK(a.spheres[1].radius == 0.25);
  CHECK(a.tolerance == 1e-6);
  const auto& b = shapeOf<SphereSweepSpec>(*r->load.scene, 1);
  CHECK(b.spline == SweepSpline::Cubic);
  CHECK(b.spheres.size() == 4);  // 4.7 truncated, as POV-Ray's (int)
  CHECK(b.tolerance == 0.01);
  const auto& c = shapeOf<SphereSweepSpec>(*r->load.scene, 2);
  CHECK(c.spline == SweepSpline::BSpline);
  CHECK(c.spheres[3].radius == 0.0);
  CHECK(warningsOf(*r).empty());
}

TEST_CASE("scene shapes: sphere_sweep's errors are POV-Ray's", "[sdl][scene][shapes][errors]") {
  CHECK(errorsOf("sphere_sweep { cubic_spline 3, <0, 0, 0>, 1, <1, 0, 0>, 1, <2, 0, 0>, 1 }") ==
        std::vector<std::string>{
            "test.pov:1:29: error: a cubic_spline or b_spline sphere_sweep needs 4 spheres or "
            "more, not 3 (POV-Ray's 'Too few modeling spheres')"});
  CHECK(errorsOf("sphere_sweep { linear_spline 1, <0, 0, 0>, 1 }") ==
        std::vector<std::string>{"test.pov:1:30: error: a linear_spline sphere_sweep needs 2 "
                                 "spheres or more, not 1 (POV-Ray's 'Too few modeling spheres')"});
  CHECK(errorsOf("sphere_sweep { 2, <0, 0, 0>, 1, <1, 0, 0>, 1 }") ==
        std::vector<std::string>{
            "test.pov:1:16: error: the sphere_sweep's spline expected: linear_spline, cubic_spline "
            "or b_spline (POV-Ray's 'Invalid type of interpolation')"});
  CHECK(errorsOf("sphere_sweep { linear_spline 2, <0, 0, 0>, 1, <1, 0, 0>, -1 }") ==
        std::vector<std::string>{"test.pov:1:58: error: a negative sphere_sweep radius is not "
                                 "supported by Lucent (radii >= 0)"});
}

TEST_CASE("scene shapes: ovus, about the y axis in both spaces", "[sdl][scene][shapes][ovus]") {
  auto r = readScene(R"(
ovus { 1, 0.65 }
#declare E = ovus { 0.5 1.2 }
object { E translate z }
)");
  REQUIRE(r->load.scene);
  const auto& a = shapeOf<OvusSpec>(*r->load.scene, 0);
  CHECK(a.bottomRadius == 1.0);
  CHECK(a.topRadius == 0.65);
  // A top radius of twice the bottom one or more: POV-Ray's top sphere, as Lucent's ovus.
  const auto& b = shapeOf<OvusSpec>(*r->load.scene, 1);
  CHECK(b.bottomRadius == 0.5);
  CHECK(b.topRadius == 1.2);
  checkMat(topNode(*r->load.scene, 1).parentFromNode,
           PovTransform::translation(Vec3(0, 0, 1)).lucentMatrix());
}

TEST_CASE("scene shapes: an ovus's radii below 0, or both 0, are errors",
          "[sdl][scene][shapes][ovus][errors]") {
  CHECK(errorsOf("ovus { -1, 0.5 }") ==
        std::vector<std::string>{"test.pov:1:8: error: both of the ovus's radii must be >= 0"});
  CHECK(errorsOf("ovus { 0, 0 }") ==
        std::vector<std::string>{
            "test.pov:1:8: error: the ovus's radii are both 0: it has no surface"});
}

TEST_CASE("scene shapes: parametric, its functions in u and v and z negated",
          "[sdl][scene][shapes][parametric]") {
  auto r = readScene(R"(
#declare F = function(a, b) { a * b }
parametric {
  function { cos(u) + v } function { F(u, v) + z } function { sin(x) * y }
  <6, 1>, <0, -1>
  contained_by { sphere { <0, 0, 1>, 2 } }
  max_gradient 2.5 accuracy 0.01 precompute 6 x, z
}
parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> }
)");
  REQUIRE(r->load.scene);
  const auto& a = shapeOf<ParametricSpec>(*r->load.scene, 0);
  // The corners sorted, as POV-Ray sorts them.
  CHECK(a.uvMin == Vec2(0.0, -1.0));
  CHECK(a.uvMax == Vec2(6.0, 1.0));
  CHECK(a.container.kind == IsosurfaceContainer::Sphere);
  CHECK(a.container.center == Vec3(0.0, 0.0, -1.0));
  CHECK(a.container.radius == 2.0);
  CHECK(a.maxGradient == 2.5);
  CHECK(a.accuracy == 0.01);
  CHECK(a.precomputeDepth == 6);
  CHECK(a.precompute == std::array<bool, 3>{true, false, true});
  REQUIRE(a.intervals);
  CHECK(a.intervals->parts == 64);
  CHECK(a.intervals->low[1].empty());
  // u and v are the functions' x and y; z is 0; Lucent's z is POV-Ray's negated.
  const Vec3 q(0.7, -0.4, 9.0);
  CHECK(a.functions->fields[0]->value(q) == Approx(std::cos(0.7) - 0.4));
  CHECK(a.functions->fields[1]->value(q) == Approx(0.7 * -0.4));
  CHECK(a.functions->fields[2]->value(q) == Approx(-std::sin(0.7) * -0.4));
  CHECK(a.functions->text[2].rfind("-(", 0) == 0);
  // POV-Ray's defaults.
  const auto& b = shapeOf<ParametricSpec>(*r->load.scene, 1);
  CHECK(b.container.kind == IsosurfaceContainer::Box);
  CHECK(b.container.min == Vec3(-1.0));
  CHECK(b.container.max == Vec3(1.0));
  CHECK(b.maxGradient == 1.0);
  CHECK(b.accuracy == 0.001);
  CHECK(b.precomputeDepth == 0);
  CHECK_FALSE(b.intervals);
}

TEST_CASE(
    "scene shapes: a parametric's empty rectangle, bad precompute and missing function "
    "are errors",
    "[sdl][scene][shapes][parametric][errors]") {
  CHECK(errorsOf("parametric { function { u } function { v } function { 0 } <0, 1>, <0, 2> }") ==
        std::vector<std::string>{"test.pov:1:59: error: the parametric's (u, v) rectangle is empty "
                                 "(u 0 to 0, v 1 to 2): it has no surface"});
  CHECK(errorsOf("parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> "
                 "precompute 21 }") ==
        std::vector<std::string>{
            "test.pov:1:85: error: the parametric's precompute depth must be from 1 to 20 "
            "(POV-Ray's 'Precompute: invalid depth')"});
  const auto two = errorsOf("parametric { function { u } function { v } <0, 0>, <1, 1> }");
  REQUIRE(two.size() == 1);
  CHECK(two[0].rfind("test.pov:1:44: error: expected 'function' (the parametric's z coordinate)",
                     0) == 0);
}

TEST_CASE("scene shapes: superellipsoid exponents below 0.01 are drawn as 0.01, with a warning",
          "[sdl][scene][shapes][superellipsoid]") {
  // portfolio/allobjects.pov draws superellipsoids of random exponents in [0, 1).
  auto r = readScene("superellipsoid { <0.001, 0.5> }\nsuperellipsoid { <0.25, 0.005> }\n");
  REQUIRE(r->load.scene);
  const auto& a = shapeOf<SuperellipsoidSpec>(*r->load.scene, 0);
  CHECK(a.e == 0.01);
  CHECK(a.n == 0.5);
  const auto& b = shapeOf<SuperellipsoidSpec>(*r->load.scene, 1);
  CHECK(b.e == 0.25);
  CHECK(b.n == 0.01);
  const auto warnings = warningsOf(*r);
  REQUIRE(warnings.size() == 2);
  CHECK(warnings[0] ==
        "test.pov:1:1: warning: 'superellipsoid' exponents below 0.01 are drawn as 0.01, the "
        "least Lucent takes (here <0.001, 0.5>): the shape's corners and edges move by at most "
        "0.35 % of its half-width");
}
