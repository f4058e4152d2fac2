// Nodes of the scene graph: shapes, groups, CSG operations, <use> references and lights,
// each with its local transform (parentFromNode) and, optionally, its own material.
#pragma once

#include "light.h"
#include "shape_spec.h"
#include "source_loc.h"

#include "primitives/math.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lucent {

enum class NodeKind { Shape, Group, Union, Merge, Intersection, Difference, Use, Light };

const char* nodeKindName(NodeKind k);  // "shape", "group", "union", ...

struct Node {
  NodeKind kind = NodeKind::Group;
  std::string element;  // the element name as written: "sphere", "group", "use", ...
  std::string id;       // empty unless given
  SourceLoc loc;

  Mat4 parentFromNode{1.0};          // the node's own transform, in the order written
  std::optional<uint32_t> material;  // index into Scene::materials; none: inherit
  // shadows="false": the node and everything under it cast no shadow (POV-Ray's no_shadow).
  // Inside a merge, intersection or difference only the whole operation's counts, as in
  // POV-Ray (World splits a union whose children differ, as POV-Ray splits its unions).
  bool shadows = true;
  // image="false" / reflection="false": the node and everything under it are not seen by
  // camera rays (and rays that went on through surfaces from the camera, never reflected),
  // or by reflected rays (POV-Ray's no_image, no_reflection). Shadows are cast either way.
  // Inside a merge, intersection or difference only the whole operation's count.
  bool image = true;
  bool reflection = true;
  // double-illuminate="true": the surfaces are lit from both sides, a light behind the
  // surface counting as one in front (POV-Ray's double_illuminate); inherited by children.
  bool doubleIlluminate = false;
  // interior-material: the material the surface shows where a ray meets it from inside
  // (POV-Ray's interior_texture); none: inherit (or the node's material). Its surface
  // only: the medium inside stays the node's material's.
  std::optional<uint32_t> interiorMaterial;
  // inverse="true" on a solid: inside and outside swapped (POV-Ray's inverse), built as
  // csg/inverted.h around the node's geometry.
  bool inverse = false;
  // <light-group> (POV-Ray's light_group): a group whose own lights (its light children, not
  // those deeper down) light only the geometry inside it, and only they do unless
  // globalLights (global-lights="true") lets the scene's other lights in too
  // (scenegraph/light_group.h has the rules for nested groups).
  bool lightGroup = false;
  bool globalLights = false;

  // <clip> (POV-Ray's clipped_by): solids in the node's own frame; the node's surface is
  // kept only inside all of them, left open where they cut it (csg/clipped.h).
  std::vector<std::unique_ptr<Node>> clip;
  // <bound> (POV-Ray's bounded_by as POV-Ray applies it): solids in the node's own frame;
  // the node is searched only along rays that meet all of them or start inside them
  // (csg/bounded.h).
  std::vector<std::unique_ptr<Node>> bound;

  std::optional<ShapeSpec> shape;               // kind == Shape
  std::vector<std::unique_ptr<Node>> children;  // groups and CSG operations
  const Node* target = nullptr;                 // kind == Use: the referenced node
  // kind == Light: the light in the node's own frame; Scene::lights holds it placed in the
  // world, once for every path from the root to it (scenegraph/light_placement.h). A light
  // is no operand: groups and CSG operations build their geometry without it.
  std::unique_ptr<Light> light;

  bool isCsg() const {
    return kind == NodeKind::Union || kind == NodeKind::Merge || kind == NodeKind::Intersection ||
           kind == NodeKind::Difference;
  }
  // Does the node enclose a volume, so it may be an operand of merge/intersection/difference?
  // Lights among a group's children do not count either way.
  bool isSolid() const;
  // A light, or a <use> of one.
  bool isLight() const {
    return kind == NodeKind::Light ||
           (kind == NodeKind::Use && target && target->kind == NodeKind::Light);
  }
};

}  // namespace lucent
