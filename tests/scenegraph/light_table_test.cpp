// The table of light types and <light> attributes (scenegraph/light.cpp) and what is derived
// from it: the parser's names, attribute check and readers, the schema, `lucent check`'s
// counts and the POV-Ray exporter's keywords.
#include "../povray/pov_test_support.h"
#include "../support/scene_text.h"
#include "lang/schema.h"
#include "scenegraph/light.h"
#include "scenegraph/scene_summary.h"

#include <catch2/catch.hpp>

#include <set>
#include <string>

using namespace lucent;
using namespace lucent::test;

namespace {

// A value the attribute's type accepts, for the parser to get past it.
std::string sampleValue(const AttributeInfo& a) {
  if (a.name == "type") return "point";
  if (a.name == "samples") return "2 2";
  if (a.name == "id") return "lamp";
  if (a.name == "transform") return "translate(0 1 0)";
  if (a.name == "angle" || a.name == "inner") return "20";
  if (a.name == "adaptive") return "1";
  if (a.name == "handedness") return "right";  // "left" needs orient="true"
  switch (a.type) {
    case AttrType::Boolean:
      return "true";
    case AttrType::Number:
      return "1";
    default:
      return a.name == "color" ? "1 1 1" : "0 1 0.5";
  }
}

}  // namespace

TEST_CASE("light table: a row per type in LightType's order, names unique", "[lights][table]") {
  const auto& types = lightTypes();
  REQUIRE(types.size() >= 4);
  std::set<std::string_view> names;
  for (size_t i = 0; i < types.size(); ++i) {
    CHECK(static_cast<size_t>(types[i].type) == i);
    CHECK(&lightTypeInfo(types[i].type) == &types[i]);
    CHECK_FALSE(types[i].name.empty());
    CHECK_FALSE(types[i].doc.empty());
    CHECK(names.insert(types[i].name).second);
  }
  std::set<std::string> attributes;
  for (const LightAttribute& a : lightAttributes()) {
    CHECK(attributes.insert(a.info.name).second);
    CHECK_FALSE(a.info.doc.empty());
  }
}

TEST_CASE("light table: every attribute but type, id and transform carries its reader",
          "[lights][table]") {
  for (const LightAttribute& a : lightAttributes()) {
    INFO(a.info.name);
    const bool generic = a.info.name == "type" || a.info.name == "id" || a.info.name == "transform";
    CHECK(static_cast<bool>(a.read) == !generic);
  }
  for (const LightTypeInfo& t : lightTypes()) CHECK(static_cast<bool>(t.writePov));
}

TEST_CASE("light table: each type takes its attributes and names the owners of the others",
          "[lights][table][lang]") {
  for (const LightTypeInfo& t : lightTypes()) {
    for (const LightAttribute& a : lightAttributes()) {
      if (a.info.name == "type") continue;
      const std::string body = "<light type=\"" + std::string(t.name) + "\" " + a.info.name +
                               "=\"" + sampleValue(a.info) + "\"/>";
      INFO(body);
      ParseResult r = parseBody(body, "lights.xml");
      const std::string said = messages(r);
      INFO(said);
      if (a.takenBy(t.type)) {
        CHECK(r.diagnostics.errorCount() == 0);
        continue;
      }
      CHECK(r.diagnostics.errorCount() == 1);
      CHECK(said.find("this light is " + std::string(t.name)) != std::string::npos);
      for (const LightTypeInfo& owner : lightTypes())
        if (a.takenBy(owner.type)) CHECK(said.find(std::string(owner.name)) != std::string::npos);
    }
  }
}

TEST_CASE("light table: the schema declares every type and every attribute with its docs",
          "[lights][table][schema]") {
  const std::string xsd = schemaText();
  const size_t begin = xsd.find("<xs:complexType name=\"lightType_\">");
  REQUIRE(begin != std::string::npos);
  const std::string lightType = xsd.substr(begin, xsd.find("</xs:complexType>", begin) - begin);
  for (const LightTypeInfo& t : lightTypes())
    CHECK(xsd.find("<xs:enumeration value=\"" + std::string(t.name) + "\">") != std::string::npos);
  for (const LightAttribute& a : lightAttributes()) {
    INFO(a.info.name);
    CHECK(lightType.find("<xs:attribute name=\"" + a.info.name + "\"") != std::string::npos);
  }
  CHECK(lightType.find("<xs:attribute name=\"type\" type=\"lightType\" default=\"point\">") !=
        std::string::npos);
}

TEST_CASE("light table: check counts and the exporter writes every type by the table's names",
          "[lights][table][povray]") {
  std::string body;
  for (const LightTypeInfo& t : lightTypes())
    body += "<light type=\"" + std::string(t.name) + "\"/>";
  auto scene = parseValid(body, "lights.xml");
  const SceneCounts counts = countScene(*scene);
  for (const LightTypeInfo& t : lightTypes()) CHECK(counts.lights.at(std::string(t.name)) == 1);

  Exported e = exportScene(body);
  REQUIRE(e.pov.ok());
  for (const LightTypeInfo& t : lightTypes())
    if (!t.pov.empty()) CHECK(e.pov.text.find("  " + std::string(t.pov)) != std::string::npos);
}
