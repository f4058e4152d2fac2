// The container of a shape sought by search (<isosurface>, <parametric>): `container`
// (box or sphere) with `min`, `max` or `center`, `radius`. Shared by the two rows, which
// read, check and write it alike.
#pragma once

#include "scenegraph/shape_type.h"

#include "primitives/isosurface.h"

#include <string>
#include <vector>

namespace lucent {

inline const std::vector<std::string_view> kContainerKinds{"box", "sphere"};

// The container's attributes for the schema (read by readContainer).
template <class S>
std::vector<Field<S>> containerFields() {
  return {
      readByEntry<S>("container", AttrType::Choice, "box", kContainerKinds)
          .doc("The region the surface is sought in: a box (min, max) or a sphere (center, "
               "radius)."),
      readByEntry<S>("min", AttrType::Vector, "-1 -1 -1").doc("A box container's lowest corner."),
      readByEntry<S>("max", AttrType::Vector, "1 1 1").doc("A box container's highest corner."),
      readByEntry<S>("center", AttrType::Vector, "0 0 0").doc("A sphere container's centre."),
      readByEntry<S>("radius", AttrType::Number, "1").doc("A sphere container's radius (> 0).")};
}

// Reads and checks the container (errors located at its attributes).
IsosurfaceContainer readContainer(AttributeInput& in);
// POV-Ray's `contained_by { box { ... } }` or `contained_by { sphere { ... } }`.
std::string povContainer(const IsosurfaceContainer& c, const PovShapeOut& out);

}  // namespace lucent
