// Materials as POV-Ray textures: every finish value written, the local terms divided by
// what POV-Ray multiplies them by (pigment and opacity), transparency, fresnel,
// absorption as fade_power 1001, and the errors and warnings.
#include "pov_test_support.h"

#include "povray/pov_materials.h"

#include <cmath>

using namespace lucent;
using namespace lucent::test;

namespace {

Exported exportMaterial(const std::string& material) {
  return exportScene("<material id=\"m\" " + material + "/>\n<sphere material=\"m\"/>");
}

}  // namespace

TEST_CASE("an opaque material with a coloured diffuse puts it in the pigment",
          "[povray][materials]") {
  Exported e = exportMaterial(
      R"XML(ambient="0.1 0.2 0.05" diffuse="0.5 0.8 0.25" specular="0.5" shininess="50" reflective="0.2")XML");
  REQUIRE(e.pov.ok());
  CHECK(e.pov.issues.empty());
  // POV-Ray multiplies ambient by the pigment: 0.1/0.5, 0.2/0.8, 0.05/0.25.
  CHECK(
      e.has("#declare M1_m = texture {\n"
            "  pigment { rgbft <0.5, 0.8, 0.25, 0, 0> }\n"
            "  finish {\n"
            "    ambient rgb <0.2, 0.25, 0.2>\n"
            "    emission rgb <0, 0, 0>\n"
            "    diffuse 1\n"
            "    phong 0\n"
            "    specular 0.5\n"
            "    reflection { rgb <0.2, 0.2, 0.2> }\n"
            "    roughness 0.02\n"
            "    brilliance 1\n"
            "  }\n"
            "}\n"));
  CHECK(e.has("sphere {  // <sphere> test.xml:4:1\n  <0, 0, 0>, 1\n  texture { M1_m }\n}\n"));
}

TEST_CASE("a grey diffuse goes into `diffuse` with a white pigment", "[povray][materials]") {
  Exported e = exportMaterial(R"XML(diffuse="0.6" ambient="0.1" emissive="0.3 0 0")XML");
  REQUIRE(e.pov.ok());
  CHECK(e.has("  pigment { rgbft <1, 1, 1, 0, 0> }\n"));
  CHECK(e.has("    ambient rgb <0.1, 0.1, 0.1>\n    emission rgb <0.3, 0, 0>\n    diffuse 0.6\n"));
}

TEST_CASE("a shape without a material gets the default material (diffuse 0.8)",
          "[povray][materials]") {
  Exported e = exportScene("<sphere/>");
  REQUIRE(e.pov.ok());
  CHECK(e.has("#declare M0_default = texture {\n  pigment { rgbft <1, 1, 1, 0, 0> }\n"));
  CHECK(e.has("    ambient rgb <0, 0, 0>\n    emission rgb <0, 0, 0>\n    diffuse 0.8\n"));
  CHECK(e.has("  texture { M0_default }\n"));
}

TEST_CASE("a grey transmissive becomes transmit, local terms are divided by the opacity",
          "[povray][materials]") {
  PovIssues issues;
  Material m;
  m.diffuse = Color(0.3f);
  m.transmissive = Color(0.25f);
  m.ior = 1.5;
  PovSurface s = povSurface(m, issues);
  CHECK(s.transmit == 0.25);
  CHECK(s.filter == 0.0);
  // POV-Ray: P·diffuse·(1 − 0.25) must be 0.3.
  CHECK(s.diffuse == Approx(0.3f / 0.75));
  CHECK(s.interior);
  CHECK(s.ior == 1.5);
}

TEST_CASE("a coloured transmissive without local terms is an exact filter", "[povray][materials]") {
  Exported e = exportMaterial(R"XML(transmissive="0.9 0.5 0.2" ior="1.3")XML");
  REQUIRE(e.pov.ok());
  CHECK(e.has("  pigment { rgbft <0.9, 0.5, 0.2, 1, 0> }\n"));
  CHECK(e.has("    diffuse 0\n"));
  CHECK(e.has("#declare IM1_m = interior {\n  ior 1.3\n}\n"));
  CHECK(e.has("  interior { IM1_m }\n"));
}

TEST_CASE("fresnel uses reflection { 0, k_r fresnel } with conserve_energy",
          "[povray][materials]") {
  Exported e = exportMaterial(R"XML(transmissive="1" reflective="1" fresnel="true" ior="1.5")XML");
  REQUIRE(e.pov.ok());
  CHECK(e.pov.issues.empty());
  CHECK(
      e.has("    reflection { rgb <0, 0, 0>, rgb <1, 1, 1> fresnel on }\n"
            "    conserve_energy\n"));

  Exported weak =
      exportMaterial(R"XML(transmissive="1" reflective="0.5" fresnel="true" ior="1.5")XML");
  CHECK(weak.messages() ==
        "test.xml:3:1: warning: material 'm': fresnel with reflective 0.5 "
        "(not 1): POV-Ray reduces the transmission by 1 - R (conserve_energy, R its "
        "reflection), Lucent by 1 - F (fresnel-transmission=\"false\" with "
        "conserve-energy=\"true\" is POV-Ray's rule)\n");
}

TEST_CASE("absorption maps onto an exponential interior fade", "[povray][materials]") {
  Exported e = exportMaterial(R"XML(transmissive="1" ior="1.5" absorption="0.5 0.25 0")XML");
  REQUIRE(e.pov.ok());
  // exp(−(1 − fade_color)·d / fade_distance) with fade_distance 1/0.5 = exp(−absorption·d).
  CHECK(
      e.has("#declare IM1_m = interior {\n  ior 1.5\n  fade_power 1001\n  fade_distance 2\n"
            "  fade_color rgb <0, 0.5, 1>\n}\n"));
}

TEST_CASE("a checker texture premultiplies the diffuse colour and keeps its scale",
          "[povray][materials]") {
  Exported e = exportScene(R"XML(<material id="c" diffuse="0.5 1 1" ambient="0.2">
        <checker color1="1 0.5 0" color2="0.2" scale="0.25"/>
      </material>
      <plane material="c"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(
      e.has("  pigment {\n    checker\n    rgbft <0.5, 0.5, 0, 0, 0>,\n"
            "    rgbft <0.1, 0.2, 0.2, 0, 0>\n    scale 0.25\n  }\n"));
  // A single-number ambient is multiplied by the texture in Lucent too: 0.2 / (0.5 1 1).
  CHECK(e.has("    ambient rgb <0.4, 0.2, 0.2>\n"));
}

TEST_CASE("a checker's placement follows its scale in POV-Ray's pigment", "[povray][materials]") {
  Exported e = exportScene(R"XML(<material id="c">
        <checker color1="1" color2="0" scale="0.25" transform="translate(1, 2, 3)"/>
      </material>
      <plane material="c"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.has("    scale 0.25\n    matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  1, 2, 3>\n  }\n"));
  // With turbulence, Lucent's order (transform, turbulence, then the cells' scale) is a
  // warp written between the scale and the matrix.
  Exported t = exportScene(R"XML(<material id="c">
        <checker color1="1" color2="0" scale="0.25" turbulence="0.5" transform="translate(1, 2, 3)"/>
      </material>
      <plane material="c"/>)XML");
  REQUIRE(t.pov.ok());
  CHECK(
      t.has("    scale 0.25\n    warp { turbulence <0.5, 0.5, 0.5> octaves 6 omega 0.5 lambda 2 }\n"
            "    matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  1, 2, 3>\n  }\n"));
}

TEST_CASE("materials POV-Ray cannot express are errors naming the material",
          "[povray][materials]") {
  Exported full = exportMaterial(R"XML(diffuse="0.5" transmissive="1")XML");
  CHECK_FALSE(full.pov.ok());
  CHECK(full.messages() ==
        "test.xml:3:1: error: material 'm': transmissive 1 with diffuse, "
        "ambient or emissive has no POV-Ray equivalent: POV-Ray scales those "
        "by 1 - transmit = 0\n");

  Exported zero = exportMaterial(R"XML(diffuse="0.5 0 0.5" ambient="0.1")XML");
  CHECK_FALSE(zero.pov.ok());
  CHECK(zero.messages() ==
        "test.xml:3:1: error: material 'm': ambient or emissive is non-zero "
        "in a channel where diffuse (0.5 0 0.5) is zero; POV-Ray multiplies "
        "both by the pigment, which carries the diffuse colour\n");
}

TEST_CASE("approximations are warnings naming the material", "[povray][materials]") {
  Exported spec = exportMaterial(R"XML(diffuse="0.5" specular="1 0.5 0")XML");
  CHECK(spec.pov.ok());
  CHECK(spec.has("    specular 0.5\n"));
  CHECK(spec.messages() ==
        "test.xml:3:1: warning: material 'm': POV-Ray's specular is one "
        "number; the coloured specular 1 0.5 0 becomes 0.5\n");

  Exported absorb = exportMaterial(R"XML(transmissive="1" reflective="0.3" absorption="0.5")XML");
  CHECK(absorb.messages() ==
        "test.xml:3:1: warning: material 'm': POV-Ray does not attenuate "
        "light reflected inside an absorbing object (its fade applies to "
        "transmitted light only); Lucent does\n");
  // fade-on-exit is POV-Ray's rule: nothing to say.
  CHECK(
      exportMaterial(
          R"XML(transmissive="1" reflective="0.3" absorption="0.5" specular="1" fade-on-exit="true")XML")
          .messages()
          .empty());

  // Lucent's weight under total internal reflection is k_r + k_t.
  Exported tir = exportMaterial(R"XML(transmissive="0.7" reflective="0.1" ior="1.5")XML");
  CHECK(tir.messages() ==
        "test.xml:3:1: warning: material 'm': under total internal "
        "reflection POV-Ray reflects with weight 1, Lucent with reflective + transmissive "
        "0.8 (full-tir=\"true\" is POV-Ray's rule)\n");
  // full-tir is POV-Ray's rule; so is a k_r + k_t of 1.
  CHECK(exportMaterial(R"XML(transmissive="0.7" reflective="0.1" ior="1.5" full-tir="true")XML")
            .messages()
            .empty());
  CHECK(
      exportMaterial(R"XML(transmissive="0.7" reflective="0.3" ior="1.5")XML").messages().empty());
}

TEST_CASE("the fade is POV-Ray's interior fade, its power as written", "[povray][materials]") {
  Exported e = exportMaterial(
      R"XML(transmissive="1" ior="1.5" fade-distance="0.8" fade-power="2" fade-color="0.9 0.3 0.1")XML");
  REQUIRE(e.pov.ok());
  CHECK(e.pov.issues.empty());
  CHECK(
      e.has("#declare IM1_m = interior {\n  ior 1.5\n  fade_power 2\n  fade_distance 0.8\n"
            "  fade_color rgb <0.9, 0.3, 0.1>\n}\n"));
}

TEST_CASE("metallic-amount, metallic-color and reflect-metallic: POV-Ray's pigment and keywords",
          "[povray][materials][finish]") {
  // The pigment is the metallic colour, its diffuse the factor to k_d.
  Exported e = exportMaterial(
      R"XML(diffuse="0.45 0.3 0.1" phong="0.9" metallic="true" metallic-amount="0.5" metallic-color="0.9 0.6 0.2" reflective="0.5" reflect-metallic="0.25")XML");
  REQUIRE(e.pov.ok());
  CHECK(e.pov.issues.empty());
  CHECK(e.has("  pigment { rgbft <0.9, 0.6, 0.2, 0, 0> }\n"));
  CHECK(e.has("    diffuse 0.5\n"));
  CHECK(e.has("    reflection { rgb <0.5, 0.5, 0.5> metallic 0.25 }\n"));
  CHECK(e.has("    metallic 0.5\n"));
  // A diffuse that is no multiple of it cannot be carried by the same pigment: said.
  Exported off = exportMaterial(
      R"XML(diffuse="0.45 0.3 0.3" phong="0.9" metallic="true" metallic-color="0.9 0.6 0.2")XML");
  CHECK(off.messages().find("is not a multiple of metallic-color") != std::string::npos);
}

TEST_CASE("phong, phong-size, brilliance and metallic are POV-Ray's finish keywords",
          "[povray][materials][finish]") {
  Exported e = exportMaterial(R"XML(diffuse="0.6" phong="0.7" phong-size="15" brilliance="3")XML");
  REQUIRE(e.pov.ok());
  CHECK(e.pov.issues.empty());
  CHECK(e.has("    diffuse 0.6\n    phong 0.7\n"));
  CHECK(e.has("    roughness 0.015625\n    phong_size 15\n    brilliance 3\n  }\n"));
  CHECK_FALSE(e.has("metallic"));

  // metallic tints by the pigment: a grey diffuse moves into the pigment (diffuse 1) so
  // that the pigment is Lucent's k_d.
  Exported metal = exportMaterial(R"XML(diffuse="0.6" specular="0.5" metallic="true")XML");
  REQUIRE(metal.pov.ok());
  CHECK(metal.has("  pigment { rgbft <0.6, 0.6, 0.6, 0, 0> }\n"));
  CHECK(metal.has("    diffuse 1\n"));
  CHECK(metal.has("    metallic\n"));

  // Without a highlight, metallic changes nothing and is not written.
  Exported plain = exportMaterial(R"XML(diffuse="0.6" metallic="true")XML");
  REQUIRE(plain.pov.ok());
  CHECK_FALSE(plain.has("metallic"));
}

TEST_CASE("a coloured phong is written as its mean with a warning", "[povray][materials][finish]") {
  Exported e = exportMaterial(R"XML(diffuse="0.5" phong="0.9 0.6 0.3")XML");
  REQUIRE(e.pov.ok());
  CHECK(e.has("    phong 0.6\n"));
  REQUIRE(e.pov.issues.size() == 1);
}

TEST_CASE("irid is POV-Ray's irid block, written only when its amount is above 0",
          "[povray][materials][finish][irid]") {
  Exported e = exportMaterial(
      R"XML(diffuse="0.5" irid="0.35" irid-thickness="0.4" irid-turbulence="0.7")XML");
  REQUIRE(e.pov.ok());
  CHECK(e.pov.issues.empty());
  CHECK(e.has("    brilliance 1\n    irid { 0.35 thickness 0.4 turbulence 0.7 }\n  }\n"));

  // Thickness and turbulence alone change nothing, in Lucent as in POV-Ray.
  Exported off = exportMaterial(R"XML(diffuse="0.5" irid-thickness="0.4")XML");
  REQUIRE(off.pov.ok());
  CHECK_FALSE(off.has("irid"));
}
