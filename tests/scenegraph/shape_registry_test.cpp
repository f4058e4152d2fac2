// The shape registry against what reads it: each row's parameters build a primitive of
// that element, its solidity matches the primitive's, its POV-Ray writer writes an object
// for every sample, its slot is its row, and its declared defaults are its parameters'.
#include "scenegraph/shape_registry.h"

#include "primitives/test_counts.h"

#include <catch2/catch.hpp>

#include <set>
#include <string>

using namespace lucent;

namespace {

// Records what a writer writes.
class RecordingOut final : public PovShapeOut {
 public:
  void open(std::string_view keyword) override { keywords.emplace_back(keyword); }
  void line(std::string_view text) override { lines.emplace_back(text); }
  std::string number(double v) const override { return std::to_string(v); }
  std::string vector(const Vec3& v) const override {
    return "<" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ">";
  }
  std::string declaredMesh(const MeshSpec&) override { return "Mesh0"; }
  std::optional<std::string> function(const std::string& text,
                                      const std::vector<std::pair<std::string, double>>&,
                                      const std::vector<std::shared_ptr<const PigmentFunction>>&,
                                      std::string&) override {
    return "f(" + text + ")";
  }
  void error(const std::string& message) override { errors.push_back(message); }
  std::string materialTexture(uint32_t material) override {
    return "texture { M" + std::to_string(material) + " }";
  }

  std::vector<std::string> keywords, lines, errors;
};

const AttributeInfo* attribute(const ShapeType& t, const std::string& name) {
  for (const AttributeInfo& a : t.attributes)
    if (a.name == name) return &a;
  return nullptr;
}

}  // namespace

TEST_CASE("shape registry: one row per ShapeSpec alternative, each named once",
          "[scenegraph][registry]") {
  const auto& types = shapeTypes();
  REQUIRE(types.size() == std::variant_size_v<ShapeSpec>);
  std::set<std::string> names;
  REQUIRE(shapeElementNames().size() == types.size());
  for (size_t i = 0; i < types.size(); ++i) {
    const ShapeType& type = types[i];
    INFO(type.element);
    CHECK(type.slot == i);
    CHECK(names.insert(type.element).second);
    CHECK(findShapeType(type.element) == &type);
    CHECK(&shapeType(i) == &type);
    CHECK(shapeElementNames()[i] == type.element);
    CHECK(testSlotName(i) == type.plural);
  }
  CHECK(findShapeType("group") == nullptr);
  CHECK(slotOf<SphereSpec>() == 0);
  CHECK(shapeType(slotOf<MeshSpec>()).element == "mesh");
  CHECK(testSlotName(kMeshTriangleSlot) == "mesh triangles");
}

TEST_CASE("shape registry: samples build their element's primitive with its solidity",
          "[scenegraph][registry]") {
  for (const ShapeType& t : shapeTypes()) {
    for (const auto& [name, spec] : t.samples()) {
      INFO(t.element << ": " << name);
      REQUIRE(spec.index() == t.slot);
      std::shared_ptr<const Shape> s = makeShape(spec);
      CHECK(std::string(s->kind()) == t.element);
      CHECK(s->isSolid() == isSolid(spec));
      CHECK(whyNotSolid(spec).empty() == isSolid(spec));
      CHECK(shapeElementName(spec) == t.element);
    }
  }
}

TEST_CASE("shape registry: every row writes a POV-Ray object for every sample",
          "[scenegraph][registry][povray]") {
  for (const ShapeType& t : shapeTypes()) {
    REQUIRE(t.writePov);
    for (const auto& [name, spec] : t.samples()) {
      INFO(t.element << ": " << name);
      RecordingOut out;
      t.writePov(spec, out);
      CHECK(out.keywords.size() == 1);
      CHECK_FALSE(out.lines.empty());
    }
  }
}

TEST_CASE("shape registry: declared attributes and defaults are the parameters'",
          "[scenegraph][registry]") {
  const ShapeType& sphere = *findShapeType("sphere");
  CHECK(sphere.attributeNames() == std::vector<std::string_view>{"center", "radius"});
  CHECK(attribute(sphere, "center")->defaultText == "0 0 0");
  CHECK(attribute(sphere, "center")->type == AttrType::Vector);
  CHECK(attribute(sphere, "radius")->defaultText == "1");
  CHECK(attribute(sphere, "radius")->rule.loOpen);

  const ShapeType& torus = *findShapeType("torus");
  CHECK(attribute(torus, "minor")->defaultText == "0.25");
  const ShapeType& cylinder = *findShapeType("cylinder");
  CHECK(attribute(cylinder, "open")->defaultText == "false");
  CHECK(attribute(cylinder, "cap")->defaultText == "0 1 0");
  const ShapeType& triangle = *findShapeType("triangle");
  CHECK(attribute(triangle, "a")->required);
  CHECK(attribute(triangle, "a")->defaultText.empty());
  CHECK_FALSE(attribute(triangle, "na")->required);
  const ShapeType& mesh = *findShapeType("mesh");
  CHECK(attribute(mesh, "smooth")->choices ==
        std::vector<std::string_view>{"auto", "true", "false"});
  CHECK(attribute(mesh, "smooth")->defaultText == "auto");
}
