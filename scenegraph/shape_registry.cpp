#include "shape_registry.h"

#include "primitives/test_counts.h"

#include <fmt/format.h>

#include <utility>

namespace lucent {

namespace {

template <size_t... I>
std::vector<ShapeType> makeTable(std::index_sequence<I...>) {
  return {eraseShapeEntry(shapeEntry<std::variant_alternative_t<I, ShapeSpec>>(), I)...};
}

}  // namespace

static_assert(std::variant_size_v<ShapeSpec> <= kShapeTestSlots,
              "--stats has a slot for each shape: raise kShapeTestSlots");

const std::vector<ShapeType>& shapeTypes() {
  static const std::vector<ShapeType> table =
      makeTable(std::make_index_sequence<std::variant_size_v<ShapeSpec>>());
  return table;
}

const ShapeType* findShapeType(std::string_view element) {
  for (const ShapeType& t : shapeTypes())
    if (t.element == element) return &t;
  return nullptr;
}

const ShapeType& shapeTypeOf(const ShapeSpec& spec) { return shapeTypes()[spec.index()]; }

std::vector<std::string_view> ShapeType::attributeNames() const {
  std::vector<std::string_view> names;
  for (const AttributeInfo& a : attributes) names.push_back(a.name);
  return names;
}

const ChildElementInfo* ShapeType::child(std::string_view name) const {
  for (const ChildElementInfo& c : children)
    if (c.name == name) return &c;
  return nullptr;
}

std::string attributeText(double v) { return fmt::format("{}", v); }
std::string attributeText(const Vec3& v) { return fmt::format("{} {} {}", v.x, v.y, v.z); }

bool isSolid(const ShapeSpec& spec) { return shapeTypeOf(spec).notSolid(spec).empty(); }
std::string whyNotSolid(const ShapeSpec& spec) { return shapeTypeOf(spec).notSolid(spec); }
const char* shapeElementName(const ShapeSpec& spec) { return shapeTypeOf(spec).element.c_str(); }
std::shared_ptr<const Shape> makeShape(const ShapeSpec& spec) {
  return shapeTypeOf(spec).build(spec);
}

std::string testSlotName(size_t slot) {
  if (slot < shapeTypes().size()) return shapeTypes()[slot].plural;
  if (slot == kMeshTriangleSlot) return "mesh triangles";
  return "other shapes";
}

}  // namespace lucent
