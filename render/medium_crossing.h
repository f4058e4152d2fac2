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

// A surface that bounds its own part (not `cut`) is left or entered by its side: the part's
// medium, its material, is behind its outward normal. A cut wall (Hit::flip: a later
// operand of a difference, an inverse part) bounds the cut, which holds the cut part's
// medium as POV-Ray gives each CSG part an interior of its own: the ray passes between the
// medium it is in and that one. A cut whose medium is the one the ray is in (the same
// material or the same interior terms, as one interior shared by the whole solid) is empty:
// the ray leaves the solid there and enters it again on the way out of the cut, into the
// solid's medium (a cut open to the outside, met from outside, included).
inline MediumCrossing mediumCrossing(const WorldLeaf& leaf, bool cut, bool front,
                                     const MediaStack& media) {
  if (!leaf.medium) return {};
  if (!cut) return {leaf.medium, !front};
  if (!front) {  // into the cut
    const Material* in = media.top();
    if (in && sameMedium(*in, *leaf.medium)) return {in, true};
    return {leaf.medium, false};
  }
  // Out of the cut: out of its medium if the ray is in it, else into the solid.
  if (const Material* in = media.find(*leaf.medium)) return {in, true};
  return {leaf.solidMedium ? leaf.solidMedium : leaf.medium, false};
}

}  // namespace lucent
