// POV-Ray 3.7's object pattern: 1 where the pattern-space point is inside a solid, 0
// outside it (its Inside_Object, the solid's own inside test with its clips). The scene
// keeps the node the pattern names and the solid built from it once, when the scene is
// read, so that a pattern anywhere (a normal, a map's entry) evaluates it without a world.
#pragma once

#include "node.h"

#include "primitives/shape.h"

#include <memory>
#include <string>

namespace lucent {

struct ObjectPattern {
  std::string id;              // the id of the <defs> node, as written (convert writes it back)
  const Node* node = nullptr;  // that node, owned by the scene (export-pov writes its shape)
  // Its geometry with its own transform, in pattern space; only inside() is asked, so its
  // materials play no part.
  std::shared_ptr<const Shape> solid;
};

}  // namespace lucent
