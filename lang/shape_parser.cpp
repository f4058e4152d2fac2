// The attributes of a shape element, read through its entry in the shape registry
// (scenegraph/shape_registry.h): this file only connects the registry's AttributeInput to
// one XML element, and knows no shape by name.
#include "element_input.h"
#include "element_parsers.h"

#include "scenegraph/shape_registry.h"

namespace lucent {

bool isShapeElement(std::string_view name) { return findShapeType(name) != nullptr; }

std::vector<std::string_view> shapeAttributes(std::string_view element) {
  const ShapeType* t = findShapeType(element);
  return t ? t->attributeNames() : std::vector<std::string_view>{};
}

std::optional<ShapeSpec> parseShape(ElementReader& r) {
  const ShapeType* t = findShapeType(r.element().name());
  if (!t) return std::nullopt;
  ElementInput in(r);
  return t->read(in);
}

}  // namespace lucent
