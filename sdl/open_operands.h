// POV-Ray's CSG of objects that are not closed solids. An operation keeps each operand's
// surface where the others' insides say (POV-Ray's Inside): inside each of an intersection's
// others, inside a difference's first operand and inside its later ones inverted, outside a
// merge's others. Two kinds of object are not Lucent solids but have a POV-Ray inside:
// - no inside at all (triangle, polygon, bicubic_patch, parametric, a mesh without
//   inside_vector): Inside is false, even inverted, so an intersection or difference with
//   one keeps only its surface, cut by the others (with two, nothing), and in a merge it
//   shows outside the others;
// - a disc: inside is the half-space below its plane (its z < 0 in POV-Ray's disc space),
//   which its surface does not cover.
// Lucent's CSG takes solids only: the operation is rewritten as a union of pieces (the
// solids' own operation, and each other operand) each clipped by the others' insides,
// expressed as solids: a solid itself, a disc's half-space as a <plane>, inverted where
// the rule asks. A rewritten operation keeps its POV-Ray inside for the operation around it.
#pragma once

#include "pov_bounds.h"

#include "scenegraph/node.h"

#include <map>
#include <memory>
#include <optional>

namespace lucent::sdl {

// POV-Ray's inside of an object as Lucent solids in its parent's frame: `in` where
// Inside_Object is true, `inverted` where it is true of the object inverted (as a
// difference inverts its later operands). Null: nowhere.
struct PovInsides {
  std::unique_ptr<Node> in;
  std::unique_ptr<Node> inverted;
};

// One scene's rewrites: it remembers each rewritten operation's inside.
class OpenOperands {
 public:
  // Rewrites `csg` (a merge, intersection or difference read from POV-Ray) in place when
  // some of its operands are not solids and each has a POV-Ray inside Lucent can express;
  // leaves it as it is otherwise. With `closeCovered`, a disc that covers the whole cut it
  // makes in an intersection or difference (an operand it keeps within projects onto its
  // plane within its radius; no hole) closes it: it becomes its half-space, a <plane>, and
  // the operation stays a solid, whose glass refracts as one (a top-level operation, whose
  // box POV-Ray keeps is then its bound; an operand's is kept for the operation around it
  // only when it is rewritten). `povBox` receives POV-Ray's box of the operation when it
  // was changed. False when nothing of it is left (the object is then dropped: an empty
  // union is no scene's).
  bool rewrite(Node& csg, bool closeCovered, std::optional<AABB>& povBox);

  // A clip (clipped_by) asks its objects' inside only: one that is not a solid is replaced
  // by its inside (a disc by its half-space). False when a clip object is inside nowhere
  // (POV-Ray then keeps nothing of the clipped object); one whose inside Lucent cannot
  // express is left as it is (the scene's checks report it).
  bool clipByInside(std::unique_ptr<Node>& clip) const;

  // POV-Ray's box of a rewritten operation (in its parent's frame), which POV-Ray computes
  // from the operands read; null for any other node.
  const AABB* povBox(const Node& n) const;
  KnownBox knownBoxes() const {
    return [this](const Node& n) { return povBox(n); };
  }

 private:
  // The insides of n, when Lucent can express them.
  bool insidesOf(const Node& n, PovInsides& out) const;
  // A rewritten operation is a union with the operation's name as its element; its insides
  // are kept here (the node's address with its element checked: only a rewritten node
  // carries such a union, and the latest at an address is the one kept).
  struct Rewritten {
    PovInsides insides;
    AABB box;
  };
  const Rewritten* rewritten(const Node& n) const;
  // The surfaces of n inverted, in place: a union's (or group's) parts each kept where the
  // others are inside inverted (POV-Ray inverts a union into an intersection of its parts
  // inverted). False when nothing of it is left.
  bool invertSurfaces(Node& n) const;
  // Makes each disc of an intersection or difference that covers its cut its half-space.
  bool closeCoveredDiscs(Node& csg) const;
  std::map<const Node*, Rewritten> rewritten_;
};

}  // namespace lucent::sdl
