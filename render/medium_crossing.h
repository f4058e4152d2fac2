// Which medium a ray leaves or enters where it meets a solid's surface: the bookkeeping of
// the media stack (render/media_stack.h) for camera and shadow rays alike.
#pragma once

#include "media_stack.h"

#include "scenegraph/flatten.h"

namespace lucent {

struct MediumCrossing {
  const Material* medium = nullptr;  // null: a surface without an inside (a thin sheet)
  bool leaving = false;              // the ray was inside `medium`; else it enters it
};

// Each part of a solid is filled with its material's medium, as POV-Ray gives each CSG
// part an interior of its own. A part of the solid's medium (its first part's, or one with
// the same interior terms, which then stands for it) bounds the solid: it is left or
// entered by the side it is met from (its outward normal). A part with a medium of its own
// (a cut of a difference: a later operand, a part of one, an inverse part) is entered where
// the ray is not in that material and left where it is, as POV-Ray's list of interiors: so
// a cut holds its part's medium. A cut's wall (Hit::flip) met from inside the cut by a ray
// that is not in the cut's medium (it came from outside, through an opening) enters the
// solid's medium.
inline MediumCrossing mediumCrossing(const WorldLeaf& leaf, bool cut, bool front,
                                     const MediaStack& media) {
  if (!leaf.medium) return {};
  const Material* solid = leaf.solidMedium ? leaf.solidMedium : leaf.medium;
  if (sameMedium(*leaf.medium, *solid)) return {solid, !front};
  const bool in = media.contains(leaf.medium);
  if (cut && front && !in) return {solid, false};
  return {leaf.medium, in};
}

}  // namespace lucent
