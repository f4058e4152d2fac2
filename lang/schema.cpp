#include "schema.h"

#include "schema_template.h"  // kSchemaTemplate, made by CMake from schema_template.xsd

#include "scenegraph/camera.h"
#include "scenegraph/finish_terms.h"
#include "scenegraph/light.h"
#include "scenegraph/pattern.h"
#include "scenegraph/shape_registry.h"
#include "scenegraph/texture_spec.h"

#include <fmt/format.h>

#include <stdexcept>

namespace lucent {

namespace {

std::string escaped(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

// The template's simple type for an attribute; "" for a choice (written inline).
std::string typeName(const AttributeInfo& a) {
  if (!a.schemaType.empty()) return std::string(a.schemaType);
  switch (a.type) {
    case AttrType::Number:
      if (a.rule.lo == 0.0 && a.rule.loOpen) return "positiveNumber";
      if (a.rule.lo == 0.0) return "nonNegativeNumber";
      return "number";  // other ranges the parser checks alone
    case AttrType::Vector:
    case AttrType::Direction:
      return "vector3";
    case AttrType::Boolean:
      return "boolean";
    case AttrType::Text:
      return "xs:string";
    case AttrType::File:
      return "path";
    case AttrType::NumberList:
      return a.listArity == 3 ? "tripleList" : (a.listArity == 2 ? "pairList" : "numberList");
    case AttrType::IntegerList:
      return "indexTripleList";
    case AttrType::Choice:
      return "";
  }
  throw std::logic_error("schema: unknown attribute type");
}

// An <xs:attribute> at `indent` spaces (8 inside a type's extension, 4 directly in a type).
std::string attributeXsd(const AttributeInfo& a, int indent = 8) {
  const std::string pad(static_cast<size_t>(indent), ' ');
  std::string type = typeName(a);
  std::string head = fmt::format("{}<xs:attribute name=\"{}\"", pad, a.name);
  if (!type.empty()) head += fmt::format(" type=\"{}\"", type);
  if (a.required) head += " use=\"required\"";
  else if (!a.defaultText.empty()) head += fmt::format(" default=\"{}\"", escaped(a.defaultText));
  // The default ends the documentation, unless the documentation says it already (where it
  // reads better before a remark: "Default 1. Glass 1.5, ...").
  std::string doc = a.doc;
  const std::string defaultSentence = "Default " + a.defaultText + ".";
  if (!a.required && !a.defaultText.empty() && doc.find(defaultSentence) == std::string::npos)
    doc += (doc.empty() ? "" : " ") + defaultSentence;
  std::string out = head + ">\n";
  out += fmt::format("{}  <xs:annotation><xs:documentation>{}</xs:documentation></xs:annotation>\n",
                     pad, escaped(doc));
  if (type.empty()) {
    out += "          <xs:simpleType>\n            <xs:union memberTypes=\"parameterReference\">\n";
    out += "              <xs:simpleType>\n                <xs:restriction base=\"xs:token\">\n";
    for (std::string_view c : a.choices)
      out += fmt::format("                  <xs:enumeration value=\"{}\"/>\n", escaped(c));
    out += "                </xs:restriction>\n              </xs:simpleType>\n";
    out += "            </xs:union>\n          </xs:simpleType>\n";
  }
  return out + pad + "</xs:attribute>\n";
}

std::string shapeElements() {
  std::string out;
  for (const ShapeType& t : shapeTypes())
    out += fmt::format(
        "      <xs:element name=\"{0}\" type=\"{0}Type\">\n"
        "        <xs:annotation><xs:documentation>{1}</xs:documentation></xs:annotation>\n"
        "      </xs:element>\n",
        t.element, escaped(t.doc));
  return out;
}

// A shape with child elements of its own (a blob's <component>): leafType's children (local
// parameters, one inline material) and its own, in any order, and the node attributes.
std::string shapeWithChildrenXsd(const ShapeType& t) {
  std::string out = fmt::format(
      "  <xs:complexType name=\"{}Type\">\n"
      "    <xs:choice minOccurs=\"0\" maxOccurs=\"unbounded\">\n"
      "      <xs:group ref=\"localParam\"/>\n"
      "      <xs:element name=\"material\" type=\"inlineMaterialType\"/>\n"
      "      <xs:element name=\"clip\" type=\"solidsType\"/>\n"
      "      <xs:element name=\"bound\" type=\"solidsType\"/>\n",
      t.element);
  for (const ChildElementInfo& c : t.children)
    out += fmt::format(
        "      <xs:element name=\"{0}\" type=\"{1}{0}Type\">\n"
        "        <xs:annotation><xs:documentation>{2}</xs:documentation></xs:annotation>\n"
        "      </xs:element>\n",
        c.name, t.element, escaped(c.doc));
  out += "    </xs:choice>\n    <xs:attributeGroup ref=\"nodeAttributes\"/>\n";
  for (const AttributeInfo& a : t.attributes) out += attributeXsd(a);
  out += "  </xs:complexType>\n\n";
  // Each child's own type (named after the shape: blobcomponentType), after the shape's.
  for (const ChildElementInfo& c : t.children) {
    out += fmt::format("  <xs:complexType name=\"{}{}Type\">\n", t.element, c.name);
    out += c.contentXsd;
    if (c.inlineMaterial)
      out +=
          "    <xs:sequence>\n"
          "      <xs:element name=\"material\" type=\"inlineMaterialType\" minOccurs=\"0\"/>\n"
          "    </xs:sequence>\n";
    for (const AttributeInfo& a : c.attributes) out += attributeXsd(a);
    out += "  </xs:complexType>\n\n";
  }
  return out;
}

std::string shapeTypesXsd() {
  std::string out;
  for (const ShapeType& t : shapeTypes()) {
    if (!t.children.empty()) {
      out += shapeWithChildrenXsd(t);
      continue;
    }
    out += fmt::format(
        "  <xs:complexType name=\"{}Type\">\n    <xs:complexContent>\n"
        "      <xs:extension base=\"leafType\">\n",
        t.element);
    for (const AttributeInfo& a : t.attributes) out += attributeXsd(a);
    out += "      </xs:extension>\n    </xs:complexContent>\n  </xs:complexType>\n\n";
  }
  return out;
}

// The camera types as the enumeration of cameraTypeLiteral, each with its line of
// documentation.
std::string cameraTypesXsd() {
  std::string out;
  for (const CameraTypeInfo& t : cameraTypes())
    out += fmt::format(
        "      <xs:enumeration value=\"{}\"><xs:annotation><xs:documentation>{}</xs:documentation>"
        "</xs:annotation></xs:enumeration>\n",
        t.name, escaped(t.doc));
  return out;
}

std::string cameraAttributesXsd() {
  std::string out;
  for (const CameraAttribute& a : cameraAttributes()) out += attributeXsd(a.info, 4);
  return out;
}

// The light types as the enumeration of lightTypeLiteral, each with its line of documentation.
std::string lightTypesXsd() {
  std::string out;
  for (const LightTypeInfo& t : lightTypes())
    out += fmt::format(
        "      <xs:enumeration value=\"{}\"><xs:annotation><xs:documentation>{}</xs:documentation>"
        "</xs:annotation></xs:enumeration>\n",
        t.name, escaped(t.doc));
  return out;
}

// POV-Ray's patterns, from the pattern table: the enumerations of the colour patterns, or
// of those only a <normal> takes.
std::string patternEnumerationsXsd(bool colour) {
  std::string out;
  for (const PatternTypeInfo& t : kPatternTypes)
    if (t.colour == colour)
      out += fmt::format(
          "      <xs:enumeration value=\"{}\"><xs:annotation><xs:documentation>POV-Ray's {}: {}."
          "</xs:documentation></xs:annotation></xs:enumeration>\n",
          t.name, t.pov, escaped(t.doc));
  return out;
}

std::string colourPatternsXsd() { return patternEnumerationsXsd(true); }

// The type of <normal type>: any colour pattern, and those only a normal takes (a type of
// their own when there are any).
std::string normalPatternsXsd() {
  const std::string only = patternEnumerationsXsd(false);
  std::string out;
  if (!only.empty())
    out +=
        "  <xs:simpleType name=\"normalPatternLiteral\">\n    <xs:restriction "
        "base=\"xs:token\">\n" +
        only + "    </xs:restriction>\n  </xs:simpleType>\n";
  out += fmt::format(
      "  <xs:simpleType name=\"normalPattern\">\n    <xs:annotation><xs:documentation>Any colour "
      "pattern (its slope; bumps, dents, ripples, waves, wrinkles and quilted have normals of "
      "their own){}.</xs:documentation></xs:annotation>\n    <xs:union "
      "memberTypes=\"colourPatternLiteral {}parameterReference\"/>\n  </xs:simpleType>\n",
      only.empty() ? "" : ", or a pattern only a normal takes",
      only.empty() ? "" : "normalPatternLiteral ");
  return out;
}

// The texture kinds a <material> takes as its colour child, from the texture table.
std::string textureElementsXsd() {
  std::string out;
  for (const TextureKindInfo& k : textureKinds())
    out += fmt::format(
        "      <xs:element name=\"{0}\" type=\"{0}Type\">\n"
        "        <xs:annotation><xs:documentation>{1}</xs:documentation></xs:annotation>\n"
        "      </xs:element>\n",
        k.element, escaped(k.doc));
  return out;
}

// "point (default), directional, spot or area": the types in the table's order, the
// default marked, for the <light> element's documentation.
std::string lightTypeNames() {
  const std::vector<LightTypeInfo>& types = lightTypes();
  std::string out;
  for (size_t i = 0; i < types.size(); ++i) {
    out += (i == 0 ? "" : (i + 1 == types.size() ? " or " : ", ")) + std::string(types[i].name);
    if (types[i].type == Light{}.type) out += " (default)";
  }
  return out;
}

std::string lightAttributesXsd() {
  std::string out;
  for (const LightAttribute& a : lightAttributes()) out += attributeXsd(a.info, 4);
  return out;
}

// The finish table's terms, the attributes of materialAttributes (id, base and default are
// the template's).
std::string materialAttributesXsd() {
  std::string out;
  for (const FinishTerm& t : finishTerms()) out += attributeXsd(t.info, 4);
  return out;
}

// The surface terms, a <layer>'s attributes.
std::string layerAttributesXsd() {
  std::string out;
  for (const FinishTerm& t : finishTerms())
    if (!t.ofInterior) out += attributeXsd(t.info, 4);
  return out;
}

std::string shapeXpath() {
  std::string out;
  for (const ShapeType& t : shapeTypes()) out += ".//" + t.element + " | ";
  return out;
}

void replaceOnce(std::string& text, std::string_view marker, const std::string& with) {
  size_t at = text.find(marker);
  if (at == std::string::npos)
    throw std::logic_error("schema template: no marker " + std::string(marker));
  text.replace(at, marker.size(), with);
}

}  // namespace

std::string schemaText() {
  std::string text(kSchemaTemplate);
  replaceOnce(text, "@SHAPE_XPATH@", shapeXpath());
  replaceOnce(text, "@SHAPE_ELEMENTS@", shapeElements());
  replaceOnce(text, "@SHAPE_TYPES@", shapeTypesXsd());
  replaceOnce(text, "@CAMERA_TYPES@", cameraTypesXsd());
  replaceOnce(text, "@CAMERA_ATTRIBUTES@", cameraAttributesXsd());
  replaceOnce(text, "@LIGHT_TYPES@", lightTypesXsd());
  replaceOnce(text, "@LIGHT_TYPE_NAMES@", lightTypeNames());
  replaceOnce(text, "@LIGHT_ATTRIBUTES@", lightAttributesXsd());
  replaceOnce(text, "@COLOUR_PATTERNS@", colourPatternsXsd());
  replaceOnce(text, "@NORMAL_PATTERNS@", normalPatternsXsd());
  replaceOnce(text, "@TEXTURE_ELEMENTS@", textureElementsXsd());
  replaceOnce(text, "@MATERIAL_ATTRIBUTES@", materialAttributesXsd());
  replaceOnce(text, "@LAYER_ATTRIBUTES@", layerAttributesXsd());
  return text;
}

}  // namespace lucent
