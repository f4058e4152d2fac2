#include "node.h"
#include "scenegraph/shape_registry.h"

namespace lucent {

const char* nodeKindName(NodeKind k) {
  switch (k) {
    case NodeKind::Shape:
      return "shape";
    case NodeKind::Group:
      return "group";
    case NodeKind::Union:
      return "union";
    case NodeKind::Merge:
      return "merge";
    case NodeKind::Intersection:
      return "intersection";
    case NodeKind::Difference:
      return "difference";
    case NodeKind::Use:
      return "use";
    case NodeKind::Light:
      return "light";
  }
  return "?";
}

bool Node::isSolid() const {
  switch (kind) {
    case NodeKind::Shape:
      return shape && lucent::isSolid(*shape);
    case NodeKind::Use:
      return target && target->isSolid();
    case NodeKind::Merge:
    case NodeKind::Intersection:
    case NodeKind::Difference:
      return true;  // their operands are checked to be solid
    case NodeKind::Union:
    case NodeKind::Group:
      if (children.empty()) return false;
      for (const auto& c : children)
        if (!c->isLight() && !c->isSolid()) return false;
      return true;
    case NodeKind::Light:
      return false;
  }
  return false;
}

}  // namespace lucent
