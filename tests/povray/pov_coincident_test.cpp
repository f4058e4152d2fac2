// The warning where CSG operands have surfaces in one place (POV-Ray speckles there, Lucent
// decides by its rule): given for flush box faces, a box face in an axis plane and the same
// sphere twice, once per CSG node; never for operands that only come close or meet at edges.
#include "pov_test_support.h"

using namespace lucent;
using namespace lucent::test;

namespace {

std::string rule(const std::string& csg, const std::string& a, const std::string& b,
                 const std::string& what) {
  return "test.xml:3:1: warning: <" + csg + ">: its operands " + a + " and " + b + " " + what +
         ": where surfaces coincide POV-Ray takes one or the other pixel by pixel (speckles), "
         "Lucent decides by its rule for coincident surfaces (docs/csg.md), so the images "
         "differ there\n";
}

}  // namespace

TEST_CASE("export warns where CSG operands have faces in one plane", "[povray][coincident]") {
  SECTION("a pocket flush with the top of a box") {
    Exported e = exportScene(R"XML(<difference>
<box min="-1 -1 -1" max="1 1 1"/>
<box min="-0.5 0 -0.5" max="0.5 1 0.5"/></difference>)XML");
    CHECK(e.messages() == rule("difference", "<box> (test.xml:4:1)", "<box> (test.xml:5:1)",
                               "have faces in one plane (y = 1)"));
  }
  SECTION("the same, the second box placed by a transform and inside a group") {
    Exported e = exportScene(R"XML(<difference transform="rotate-y(20)">
<box min="-1 -1 -1" max="1 1 1"/>
<group><box min="-1 -1 -1" max="1 1 1" transform="scale(0.5) translate(0 0.5 0)"/></group></difference>)XML");
    CHECK(e.messages() == rule("difference", "<box> (test.xml:4:1)", "<box> (test.xml:5:8)",
                               "have faces in one plane (y = 1)"));
  }
  SECTION("a box on an axis plane") {
    Exported e = exportScene(R"XML(<intersection>
<plane normal="0 -1 0" offset="0"/>
<box min="-1 0 -1" max="1 1 1"/></intersection>)XML");
    CHECK(e.messages() == rule("intersection", "<plane> (test.xml:4:1)", "<box> (test.xml:5:1)",
                               "lie in one plane (y = 0)"));
  }
  SECTION("the same sphere twice, once as a scaled larger sphere") {
    Exported e = exportScene(R"XML(<union>
<sphere center="0 1 0" radius="1"/>
<sphere radius="2" transform="scale(0.5) rotate-z(30) translate(0 1 0)"/></union>)XML");
    CHECK(e.messages() == rule("union", "<sphere> (test.xml:4:1)", "<sphere> (test.xml:5:1)",
                               "have the same bounding box and may coincide"));
  }
}

TEST_CASE("export does not warn for operands that only come close or meet at an edge",
          "[povray][coincident]") {
  // A pocket below the top; boxes apart whose tops are level but do not overlap;
  // a sphere in a box it touches at six points; different spheres.
  for (
      const char* body : {
          R"XML(<difference><box/><box min="-0.5 0 -0.5" max="0.5 0.999 0.5"/></difference>)XML",
          R"XML(<union><box min="0 0 0" max="1 1 1"/><box min="1.5 0 0" max="2.5 1 1"/></union>)XML",
          R"XML(<intersection><box/><sphere/></intersection>)XML",
          R"XML(<union><sphere/><sphere radius="1.0001"/></union>)XML",
      }) {
    INFO(body);
    Exported e = exportScene(body);
    CHECK(e.pov.issues.empty());
  }
}
