// Geometry in POV-Ray: every primitive's syntax, CSG with a texture on each leaf, groups
// and <use> flattened as the World builds them, planes turned so the camera is outside,
// and meshes declared once as mesh2.
#include "pov_test_support.h"

#include "povray/pov_geometry.h"

using namespace lucent;
using namespace lucent::test;

TEST_CASE("every primitive is written in POV-Ray's syntax", "[povray][geometry]") {
  Exported e = exportScene(R"XML(<sphere center="1 2 3" radius="0.5"/>
<box min="-1 0 1" max="1 1 2"/>
<cylinder base="0 0 0" cap="0 2 0" radius="0.3" open="true"/>
<cone base="0 0 0" base-radius="1" cap="0 1 0" cap-radius="0.25"/>
<torus major="2" minor="0.5"/>
<disc center="0 1 0" normal="0 0 1" radius="2" inner-radius="0.5"/>
<triangle a="0 0 0" b="1 0 0" c="0 1 0"/>
<triangle a="0 0 0" b="1 0 0" c="0 1 0" na="0 0 1" nb="0 0 2" nc="0 1 1"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.has("sphere {  // <sphere> test.xml:3:1\n  <1, 2, 3>, 0.5\n"));
  CHECK(e.has("box {  // <box> test.xml:4:1\n  <-1, 0, 1>, <1, 1, 2>\n"));
  CHECK(e.has("cylinder {  // <cylinder> test.xml:5:1\n  <0, 0, 0>, <0, 2, 0>, 0.3\n  open\n"));
  CHECK(e.has("cone {  // <cone> test.xml:6:1\n  <0, 0, 0>, 1, <0, 1, 0>, 0.25\n"));
  CHECK(e.has("torus {  // <torus> test.xml:7:1\n  2, 0.5\n"));
  CHECK(e.has("disc {  // <disc> test.xml:8:1\n  <0, 1, 0>, <0, 0, 1>, 2, 0.5\n"));
  CHECK(e.has("triangle {  // <triangle> test.xml:9:1\n  <0, 0, 0>, <1, 0, 0>, <0, 1, 0>\n"));
  CHECK(
      e.has("smooth_triangle {  // <triangle> test.xml:10:1\n"
            "  <0, 0, 0>, <0, 0, 1>,\n  <1, 0, 0>, <0, 0, 1>,\n"
            "  <0, 1, 0>, <0, 0.7071067811865475, 0.7071067811865475>\n"));
}

TEST_CASE("an ovus is POV-Ray's, or its top sphere where POV-Ray would substitute it",
          "[povray][geometry]") {
  Exported e = exportScene(R"XML(<ovus bottom-radius="1" top-radius="0.65"/>
<ovus bottom-radius="0.5" top-radius="1"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.has("ovus {  // <ovus> test.xml:3:1\n  1, 0.65\n"));
  // POV-Ray warns and makes the top sphere: written as that sphere, without the warning.
  CHECK(e.has("sphere {  // <ovus> test.xml:4:1\n  <0, 0.5, 0>, 1\n"));
}

TEST_CASE("a parametric is POV-Ray's, with u and v as its functions name them",
          "[povray][geometry][parametric]") {
  Exported e = exportScene(R"XML(<param name="R" value="2"/>
<parametric x="R*cos(u)" y="v^2" z="sin(u)" uv-min="0 -1" uv-max="3 1" min="-3 -1 -2"
            max="3 2 2" max-gradient="2.5" accuracy="0.01" precompute="8"
            precompute-coordinates="x z"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(
      e.has("parametric {  // <parametric> test.xml:4:1\n"
            "  function { ((2) * cos(u)) }\n  function { pow(v, 2) }\n  function { sin(u) }\n"
            "  <0, -1>, <3, 1>\n  contained_by { box { <-3, -1, -2>, <3, 2, 2> } }\n"
            "  max_gradient 2.5\n  accuracy 0.01\n  precompute 8, x, z\n"));
}

TEST_CASE("a bicubic patch's uv corners are its uv_vectors, after its other keywords",
          "[povray][geometry]") {
  Exported e =
      exportScene(R"XML(<bicubic-patch u-steps="2" v-steps="1" uv-vectors="0.5 0 2 0.25 1 1.5 -1 1"
  points="0 0 0, 1 0 0, 2 0 0, 3 0 0, 0 1 0, 1 1 1, 2 1 1, 3 1 0, 0 2 0, 1 2 1, 2 2 1, 3 2 0, 0 3 0, 1 3 0, 2 3 0, 3 3 0"/>
<bicubic-patch points="0 0 0, 1 0 0, 2 0 0, 3 0 0, 0 1 0, 1 1 1, 2 1 1, 3 1 0, 0 2 0, 1 2 1, 2 2 1, 3 2 0, 0 3 0, 1 3 0, 2 3 0, 3 3 0"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(
      e.has("  type 0 flatness 0 u_steps 2 v_steps 1\n"
            "  uv_vectors <0.5, 0>, <2, 0.25>, <1, 1.5>, <-1, 1>\n  <0, 0, 0>,"));
  CHECK(e.pov.text.find("uv_vectors") == e.pov.text.rfind("uv_vectors"));  // the first only
}

TEST_CASE("a blob component's own material is its texture, after its transform",
          "[povray][geometry]") {
  Exported e = exportScene(R"XML(<material id="red" diffuse="0.8 0.1 0.1"/>
<blob threshold="0.5">
  <component type="sphere" radius="1" material="red" transform="scale(1 2 1)"/>
  <component type="sphere" center="1 0 0" radius="1"/>
</blob>)XML");
  INFO(e.messages() << e.pov.text);
  REQUIRE(e.pov.ok());
  CHECK(
      e.has("sphere { <0, 0, 0>, 1, strength 1 matrix <1, 0, 0, 0, 2, 0, 0, 0, 1, 0, 0, 0> "
            "texture { M1_red } }\n"));
  CHECK(e.has("sphere { <1, 0, 0>, 1, strength 1 }\n"));
  CHECK(e.has("#declare M1_red = texture"));
}

TEST_CASE("transforms are written after the texture, so textures move with the shape",
          "[povray][geometry]") {
  Exported e = exportScene(R"XML(<sphere transform="scale(2) translate(0 1 0)"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.has("  texture { M0_default }\n  matrix <2, 0, 0,  0, 2, 0,  0, 0, 2,  0, 1, 0>\n}\n"));
}

TEST_CASE("CSG operations keep their operands, each leaf with its own material",
          "[povray][geometry]") {
  Exported e = exportScene(R"XML(<material id="red" diffuse="0.8 0.1 0.1"/>
<material id="blue" diffuse="0.1 0.1 0.8"/>
<difference material="red" transform="translate(0 1 0)">
  <box/>
  <sphere radius="1.3" material="blue"/>
</difference>)XML");
  REQUIRE(e.pov.ok());
  CHECK(
      e.has("difference {  // <difference> test.xml:5:1\n"
            "  box {  // <box> test.xml:6:3\n"
            "    <-1, -1, -1>, <1, 1, 1>\n"
            "    texture { M1_red }\n"
            "  }\n"
            "  sphere {  // <sphere> test.xml:7:3\n"
            "    <0, 0, 0>, 1.3\n"
            "    texture { M2_blue }\n"
            "  }\n"
            "  matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  0, 1, 0>\n"
            "}\n"));
}

TEST_CASE("groups and <use> are flattened with their transforms and inherited materials",
          "[povray][geometry]") {
  Exported e = exportScene(R"XML(<material id="gold" diffuse="0.9 0.7 0.2"/>
<defs><sphere id="ball" radius="0.5" transform="translate(1 0 0)"/></defs>
<group transform="translate(0 2 0)">
  <use ref="ball" material="gold" transform="scale(2)"/>
</group>)XML");
  REQUIRE(e.pov.ok());
  // translate(0 2 0) · scale(2) · translate(1 0 0): the ball's centre lands at (2, 2, 0).
  CHECK(
      e.has("  <0, 0, 0>, 0.5\n  texture { M1_gold }\n"
            "  matrix <2, 0, 0,  0, 2, 0,  0, 0, 2,  2, 2, 0>\n"));
  CHECK_FALSE(e.has("union"));
}

TEST_CASE("a CSG operation with one operand is that operand", "[povray][geometry]") {
  Exported e =
      exportScene(R"XML(<intersection transform="translate(0 0 1)"><sphere/></intersection>)XML");
  REQUIRE(e.pov.ok());
  CHECK_FALSE(e.has("intersection"));
  CHECK(e.has("  matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  0, 0, 1>\n"));
}

TEST_CASE("a top-level plane holding the camera is turned so the camera is outside",
          "[povray][geometry]") {
  // The camera at y = 1 is inside the half-space y < 5 of this ceiling.
  Exported e = exportScene(R"XML(<plane normal="0 1 0" offset="5"/>
<plane normal="0 1 0" offset="0"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(
      e.has("plane {  // <plane> test.xml:3:1 (turned so the camera is outside)\n"
            "  <0, -1, 0>, -5\n"));
  CHECK(e.has("plane {  // <plane> test.xml:4:1\n  <0, 1, 0>, 0\n"));

  PlaneSpec floor{Vec3(0, 1, 0), 0.0};
  CHECK_FALSE(cameraInsidePlane(floor, Mat4(1.0), Vec3(0, 1, 0)));
  // Moved up by 3 the floor holds the camera.
  Mat4 up(1.0);
  up[3] = Vec4(0, 3, 0, 1);
  CHECK(cameraInsidePlane(floor, up, Vec3(0, 1, 0)));
}

TEST_CASE("meshes are declared once as mesh2 and instanced, closed ones get an inside_vector",
          "[povray][geometry]") {
  // A tetrahedron, outward-facing.
  Exported e = exportScene(R"XML(<defs><mesh id="tet" positions="0 0 0  0 1 0  1 0 0  0 0 1"
      indices="0 1 2  0 2 3  0 3 1  2 1 3"/></defs>
<use ref="tet"/>
<use ref="tet" transform="translate(3 0 0)"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(
      e.has("#declare Mesh0 = mesh2 {\n"
            "  vertex_vectors {\n    4,\n    <0, 0, 0>,\n    <0, 1, 0>,\n    <1, 0, 0>,\n"
            "    <0, 0, 1>\n  }\n"
            "  face_indices {\n    4,\n    <0, 1, 2>,\n    <0, 2, 3>,\n    <0, 3, 1>,\n"
            "    <2, 1, 3>\n  }\n"
            "  inside_vector <0.2672612419124244, 0.5345224838248488, 0.8017837257372732>\n"
            "}\n"));
  CHECK_FALSE(e.has("Mesh1"));
  CHECK(e.has("object {  // <mesh> test.xml:3:7\n  Mesh0\n  texture { M0_default }\n}\n"));
  CHECK(e.has(
      "  Mesh0\n  texture { M0_default }\n  matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  3, 0, 0>\n"));
}

TEST_CASE("a poly above order 4 is written with its order, every coefficient and sturm",
          "[povray][geometry]") {
  // Glob_5 of shapesq.inc: −0.5x⁵ − 0.5x⁴ + y² + z², 56 coefficients in POV-Ray's order.
  std::vector<std::string> c(56, "0");
  c[0] = "-0.5";
  c[3] = "-0.5";
  c[44] = "1";
  c[53] = "1";
  std::string xmlList, povList;
  for (size_t i = 0; i < c.size(); ++i) {
    xmlList += (i ? " " : "") + c[i];
    povList += (i ? ", " : "") + c[i];
  }
  Exported e = exportScene("<poly order=\"5\" coefficients=\"" + xmlList + "\"/>");
  REQUIRE(e.pov.ok());
  CHECK(e.has("poly {  // <poly> test.xml:3:1\n  5, <" + povList + ">\n  sturm\n"));
}
