#include "shape_registry.h"

#include "primitives/test_counts.h"

#include <fmt/format.h>

#include <array>
#include <utility>

namespace lucent {

namespace {

// The element of each ShapeSpec alternative, in order: findShapeType looks a name up here
// without building any entry (the registry test checks each against its entry).
constexpr std::array<std::string_view, std::variant_size_v<ShapeSpec>> kElements = {
    "sphere",         "box",           "cylinder",     "cone",         "torus",
    "plane",          "disc",          "triangle",     "mesh",         "quadric",
    "superellipsoid", "poly",          "prism",        "blob",         "lathe",
    "isosurface",     "text",          "sor",          "height-field", "polygon",
    "bicubic-patch",  "julia-fractal", "sphere-sweep", "ovus",         "parametric"};

constexpr bool everyShapeNamed() {
  for (std::string_view name : kElements)
    if (name.empty()) return false;
  return true;
}
static_assert(everyShapeNamed(), "a ShapeSpec alternative has no name in kElements");

// Each row is built on its first use: a scene of spheres builds the sphere's alone (the
// entries' attribute tables and documentation are most of a small scene's read-in).
template <class S>
const ShapeType& typeOf() {
  static const ShapeType type = eraseShapeEntry(shapeEntry<S>(), slotOf<S>());
  return type;
}

using TypeOf = const ShapeType& (*)();
template <size_t... I>
constexpr std::array<TypeOf, sizeof...(I)> rows(std::index_sequence<I...>) {
  return {&typeOf<std::variant_alternative_t<I, ShapeSpec>>...};
}
constexpr auto kRows = rows(std::make_index_sequence<std::variant_size_v<ShapeSpec>>());

}  // namespace

static_assert(std::variant_size_v<ShapeSpec> <= kShapeTestSlots,
              "--stats has a slot for each shape: raise kShapeTestSlots");

const ShapeType& shapeType(size_t slot) { return kRows.at(slot)(); }

const std::vector<std::reference_wrapper<const ShapeType>>& shapeTypes() {
  static const std::vector<std::reference_wrapper<const ShapeType>> all = [] {
    std::vector<std::reference_wrapper<const ShapeType>> types;
    for (size_t i = 0; i < kRows.size(); ++i) types.emplace_back(shapeType(i));
    return types;
  }();
  return all;
}

const std::vector<std::string_view>& shapeElementNames() {
  static const std::vector<std::string_view> names(kElements.begin(), kElements.end());
  return names;
}

const ShapeType* findShapeType(std::string_view element) {
  for (size_t i = 0; i < kElements.size(); ++i)
    if (kElements[i] == element) return &shapeType(i);
  return nullptr;
}

const ShapeType& shapeTypeOf(const ShapeSpec& spec) { return shapeType(spec.index()); }

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
  if (slot < kRows.size()) return shapeType(slot).plural;
  if (slot == kMeshTriangleSlot) return "mesh triangles";
  return "other shapes";
}

}  // namespace lucent
