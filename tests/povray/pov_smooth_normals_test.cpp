// The warning where Lucent's smooth shading and POV-Ray's part ways: given once per smooth
// mesh or smooth triangle whose vertex normals depart from its faces' normals, with the
// largest departure; never for flat shapes or normals that agree with their faces.
#include "pov_test_support.h"

#include "povray/pov_smooth_normals.h"

#include <cmath>

using namespace lucent;
using namespace lucent::test;

namespace {

constexpr const char* kOctahedron =
    R"(positions="1 0 0  -1 0 0  0 1 0  0 -1 0  0 0 1  0 0 -1"
      indices="0 2 4  2 1 4  1 3 4  3 0 4  2 0 5  1 2 5  3 1 5  0 3 5")";

std::string rule(const std::string& what, const std::string& amount) {
  return what + ": its vertex normals depart from the faces' normals by " + amount +
         ": near silhouettes, where an interpolated normal faces away from the viewer while its "
         "triangle faces it, Lucent shades with the triangle's normal and POV-Ray 3.7 turns the "
         "interpolated normal towards the viewer, so POV-Ray's image can show thin dark slivers "
         "there (docs/scene-language.md, For POV-Ray users)";
}

}  // namespace

TEST_CASE("smoothNormalDeviation: the largest angle between interpolated and face normal",
          "[povray][smooth]") {
  const std::array<Vec3, 3> p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};  // faces +z
  const Vec3 z(0, 0, 1);
  CHECK(smoothNormalDeviation(p, {z, z, z}) == 0.0);
  CHECK(smoothNormalDeviation(p, {-z, -z, -z}) == 0.0);  // inward normals are turned over
  const Vec3 tilted(std::sin(0.3), 0, std::cos(0.3));
  CHECK(smoothNormalDeviation(p, {z, tilted, z}) == Approx(0.3).epsilon(1e-12));
  CHECK(smoothNormalDeviation(p, {-z, -tilted, -z}) == Approx(0.3).epsilon(1e-12));
  // The axis normals of an octahedron's face: acos(1/sqrt 3) = 54.7 degrees at each corner.
  const std::array<Vec3, 3> face = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  CHECK(smoothNormalDeviation(face, face) == Approx(std::acos(1 / std::sqrt(3.0))).epsilon(1e-12));
  // Normals on both sides of the face: the interpolated one lies in the face's plane somewhere.
  CHECK(smoothNormalDeviation(p, {z, -tilted, z}) == Approx(kPi / 2));
}

TEST_CASE("export warns once per smooth mesh whose normals depart from its faces'",
          "[povray][smooth]") {
  SECTION("inline normals, the mesh used twice") {
    Exported e = exportScene(std::string(R"XML(<defs>
<mesh id="octa" )XML") + kOctahedron +
                             R"XML(
      normals="1 0 0  -1 0 0  0 1 0  0 -1 0  0 0 1  0 0 -1"/>
</defs>
<use ref="octa"/>
<use ref="octa" transform="translate(3 0 0)"/>)XML");
    REQUIRE(e.pov.ok());
    CHECK(e.messages() == "test.xml:4:1: warning: " + rule("<mesh>", "up to 54.7 degrees") + "\n");
  }
  SECTION("computed normals (smooth=\"true\") give the axis directions too") {
    Exported e = exportScene(std::string("<mesh ") + kOctahedron + R"XML( smooth="true"/>)XML");
    CHECK(e.messages() == "test.xml:3:1: warning: " + rule("<mesh>", "up to 54.7 degrees") + "\n");
  }
  SECTION("flat meshes, and smooth=\"false\" over given normals, give none") {
    Exported flat = exportScene(std::string("<mesh ") + kOctahedron + "/>");
    CHECK(flat.pov.issues.empty());
    Exported off = exportScene(
        std::string("<mesh ") + kOctahedron +
        R"XML( normals="1 0 0  -1 0 0  0 1 0  0 -1 0  0 0 1  0 0 -1" smooth="false"/>)XML");
    CHECK(off.pov.issues.empty());
  }
  SECTION("normals equal to the face normal give none") {
    Exported e =
        exportScene(R"XML(<mesh positions="0 0 0  1 0 0  1 1 0  0 1 0" indices="0 1 2  0 2 3"
      normals="0 0 1  0 0 1  0 0 1  0 0 1"/>)XML");
    CHECK(e.pov.issues.empty());
  }
}

TEST_CASE("export warns on smooth triangles whose normals depart from the face's",
          "[povray][smooth]") {
  Exported e =
      exportScene(R"XML(<triangle a="0 0 0" b="1 0 0" c="0 1 0" na="0 0 1" nb="0 0 1" nc="0 1 1"/>
<triangle a="0 0 0" b="1 0 0" c="0 1 0" na="0 0 1" nb="0 0 1" nc="0 0 1"/>
<triangle a="0 0 0" b="1 0 0" c="0 1 0"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.messages() ==
        "test.xml:3:1: warning: " + rule("<triangle>", "up to 45.0 degrees") + "\n");
}
