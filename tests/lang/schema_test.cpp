// The schema is made from the shape registry (lang/schema.h): every shape element and its
// attributes appear in it, and <scene> takes the attributes that point an editor at it.
#include "lang/schema.h"
#include "lang/parser.h"
#include "scenegraph/shape_registry.h"

#include <catch2/catch.hpp>

using namespace lucent;

TEST_CASE("schema: every registered shape and attribute is declared", "[lang][schema]") {
  const std::string xsd = schemaText();
  CHECK(xsd.find("@SHAPE") == std::string::npos);
  for (const ShapeType& t : shapeTypes()) {
    INFO(t.element);
    const std::string head = "<xs:complexType name=\"" + t.element + "Type\">";
    size_t at = xsd.find(head);
    REQUIRE(at != std::string::npos);
    CHECK(xsd.find("<xs:element name=\"" + t.element + "\" type=\"" + t.element + "Type\">") !=
          std::string::npos);
    CHECK(xsd.find(".//" + t.element + " | ") != std::string::npos);
    const std::string body = xsd.substr(at, xsd.find("</xs:complexType>", at) - at);
    for (const AttributeInfo& a : t.attributes) {
      INFO(a.name);
      CHECK(body.find("<xs:attribute name=\"" + a.name + "\"") != std::string::npos);
    }
  }
  // A default is declared as the parameters' own default value.
  CHECK(xsd.find("<xs:attribute name=\"minor\" type=\"positiveNumber\" default=\"0.25\">") !=
        std::string::npos);
  CHECK(xsd.find("<xs:attribute name=\"a\" type=\"vector3\" use=\"required\">") !=
        std::string::npos);
}

TEST_CASE("lang: <scene> accepts xmlns and xsi: attributes for editors, nothing else unknown",
          "[lang][schema]") {
  ParseResult ok = parseSceneString(
      "<scene version=\"1\" xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\"\n"
      "       xsi:noNamespaceSchemaLocation=\"lucent.xsd\"><camera/></scene>",
      "editor.xml");
  CHECK(ok.scene);
  CHECK(ok.diagnostics.all().empty());

  ParseResult bad =
      parseSceneString("<scene version=\"1\" xsd=\"lucent.xsd\"><camera/></scene>", "bad.xml");
  CHECK_FALSE(bad.scene);
  REQUIRE(bad.diagnostics.errorCount() == 1);
  CHECK(bad.diagnostics.all()[0].str().find(
            "bad.xml:1:20: error: <scene>: unknown attribute 'xsd'") == 0);
}
