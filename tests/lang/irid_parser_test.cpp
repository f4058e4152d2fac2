// The irid finish term on <material>: its three attributes, their defaults, base= and the
// messages for bad values.
#include "../support/scene_text.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

TEST_CASE("irid: amount, thickness and turbulence are read, and all default to 0",
          "[lang][finish][irid]") {
  auto s = parseClean(
      "<material id=\"film\" diffuse=\"0.5\" irid=\"0.35\" irid-thickness=\"0.4\" "
      "irid-turbulence=\"0.7\"/>"
      "<material id=\"thicker\" base=\"film\" irid-thickness=\"1.25\"/>"
      "<material id=\"plain\" diffuse=\"0.5\"/>");
  const Material& film = materialNamed(*s, "film");
  CHECK(film.irid == 0.35);
  CHECK(film.iridThickness == 0.4);
  CHECK(film.iridTurbulence == 0.7);
  // base= keeps what the material does not write.
  const Material& thicker = materialNamed(*s, "thicker");
  CHECK(thicker.irid == 0.35);
  CHECK(thicker.iridThickness == 1.25);
  CHECK(thicker.iridTurbulence == 0.7);
  const Material& plain = materialNamed(*s, "plain");
  CHECK(plain.irid == 0.0);
  CHECK(plain.iridThickness == 0.0);
  CHECK(plain.iridTurbulence == 0.0);
  CHECK(Material::defaultMaterial().irid == 0.0);
}

TEST_CASE("irid: bad values are errors at the attribute, POV-Ray's thickness is hinted",
          "[lang][finish][irid]") {
  ParseResult r = parseBody(
      "\n<material id=\"a\" irid=\"1.5\" irid-thickness=\"-1\" irid-turbulence=\"x\"/>"
      "\n<material id=\"b\" thickness=\"2\"/>",
      "irid.xml");
  CHECK(messages(r) ==
        "irid.xml:2:24: error: <material> attribute 'irid': expected a number from 0 to 1, "
        "got '1.5'\n"
        "irid.xml:2:45: error: <material> attribute 'irid-thickness': expected a number >= 0, "
        "got '-1'\n"
        "irid.xml:2:66: error: <material> attribute 'irid-turbulence': expected a number, got "
        "'x'\n"
        "irid.xml:3:18: error: <material>: unknown attribute 'thickness' (POV-Ray's "
        "'thickness' is 'irid-thickness' in Lucent)\n");
  ParseResult negative = parseBody("<material id=\"a\" irid=\"-0.2\"/>", "irid.xml");
  CHECK(messages(negative).find("attribute 'irid': expected a number from 0 to 1, got '-0.2'") !=
        std::string::npos);
}
