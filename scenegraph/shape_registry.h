// The one table of geometry elements (style habit 7: an explicit table, no self-registration).
// Its rows are ShapeSpec's alternatives in order, each from the entry in shapes/NAME.cpp;
// docs/architecture.md lists what adding a shape touches.
#pragma once

#include "shape_type.h"

#include <functional>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace lucent {

// Every row (building those not yet built): for the schema, the tests, listing names.
const std::vector<std::reference_wrapper<const ShapeType>>& shapeTypes();
// One row, built on its first use; slot is ShapeSpec's alternative.
const ShapeType& shapeType(size_t slot);
// The elements' names, in slot order, without building any row.
const std::vector<std::string_view>& shapeElementNames();
// Null when no shape element has that name.
const ShapeType* findShapeType(std::string_view element);
const ShapeType& shapeTypeOf(const ShapeSpec& spec);

// What the table tells of one element's parameters.
bool isSolid(const ShapeSpec& spec);                  // may it be a CSG operand?
std::string whyNotSolid(const ShapeSpec& spec);       // "" for a solid, else "it is open", ...
const char* shapeElementName(const ShapeSpec& spec);  // "sphere", ...
std::shared_ptr<const Shape> makeShape(const ShapeSpec& spec);
// The name --stats prints for a test slot (test_counts.h): "spheres", "mesh triangles", ...
std::string testSlotName(size_t slot);

// The registry row (and --stats slot) of a parameter type, at compile time.
template <class S, size_t I = 0>
constexpr size_t slotOf() {
  static_assert(I < std::variant_size_v<ShapeSpec>, "not a ShapeSpec alternative");
  if constexpr (std::is_same_v<std::variant_alternative_t<I, ShapeSpec>, S>) return I;
  else return slotOf<S, I + 1>();
}

}  // namespace lucent
