// The scene side of a world: the scene graph flattened into the objects a tracer meets,
// each leaf placed with its world transform and material, CSG nodes composed of such
// leaves, and what the tracer asks of them (material, medium, whether they transmit light)
// worked out here, once, rather than on the ray path. The geometry side, the search over
// these objects, is primitives/aggregate.h.
#pragma once

#include "scene.h"

#include "primitives/instance.h"
#include "primitives/shape.h"

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <vector>

namespace lucent {

// Builds the shape of one geometry node (makeShape; tests pass their own).
using ShapeMaker = std::function<std::shared_ptr<const Shape>(const ShapeSpec&)>;

// A leaf: a shape node placed in the world. A hit on it carries this (WorldHit).
struct WorldLeaf {
  const Instance* instance = nullptr;  // its tag is the leaf's index in FlatScene::leaves
  uint32_t materialIndex = 0;          // into Scene::materials (textures are per material)
  const Material* material = nullptr;
  // The medium the leaf encloses: its material when it is a solid; null for a surface
  // without an inside, which light crosses as a thin sheet.
  const Material* medium = nullptr;
  // The medium of the solid the leaf is part of (its top-level object's), which a ray
  // coming out of a cut this leaf makes enters (render/medium_crossing.h); null as medium.
  const Material* solidMedium = nullptr;
  bool transmissive = false;  // material->isTransmissive()
  // The material its surface shows to a ray that meets it from inside (interior-material),
  // null when it has none; Scene::materials' index of it.
  const Material* interior = nullptr;
  uint32_t interiorIndex = 0;
  bool doubleIlluminate = false;  // lit from both sides (double-illuminate)
  // Its material or interior material reads patterns at (u, v) (usesUvMapping): the
  // surface then carries POV-Ray's (u, v) (Instance::surface).
  bool uvMapped = false;
  // Light groups (scenegraph/light_group.h): the group whose lights light the leaf (0:
  // none) and whether the global lights do.
  uint32_t lightGroup = 0;
  bool globalLights = true;
  bool litBy(const Light& l) const { return l.group == 0 ? globalLights : l.group == lightGroup; }
  // A blob whose components have materials of their own (BlobSpec::componentMaterials):
  // each component's material, the leaf's where it has none (Scene::materials' indices);
  // null otherwise (FlatScene::componentMaterials holds them). Its surface is their blend
  // by the components' fields at the hit.
  const std::vector<uint32_t>* componentMaterials = nullptr;
};

// A top-level object: a leaf's Instance, a CSG node of leaves, or either inside out.
struct WorldObject {
  std::unique_ptr<Shape> shape;
  // The medium inside a solid: its first leaf's material (the surfaces of a CSG solid
  // normally share it); null for an object that is not a solid.
  const Material* medium = nullptr;
  bool castsShadow = true;  // false: built from shadows="false" nodes
  // false: built from image="false" nodes, or from reflection="false" ones
  bool seenByImage = true, seenByReflection = true;
  bool transmits = false;  // one of its leaves has a transmissive material
};

struct FlatScene {
  std::vector<WorldObject> objects;
  std::vector<WorldLeaf> leaves;  // every leaf, those inside CSG nodes too, in scene order
  // The leaves' WorldLeaf::componentMaterials (a deque: their addresses stay).
  std::deque<std::vector<uint32_t>> componentMaterials;
};

// Composes transforms down to the leaves (world matrix, inverse and normal matrix
// computed once per instance), resolves inherited materials and shares the shape of a
// node used many times: a mesh used through many <use> is stored and built once. A union
// whose children differ in casting shadows or being seen becomes several (POV-Ray splits every
// union into its children). Throws LocatedError (checkWorld's). The leaves point into
// scene.materials, which must keep its elements where they are while they are used.
FlatScene flattenScene(const Scene& scene, const ShapeMaker& makeShape);

// The geometry of one node as a single shape (a union of its parts when it has several),
// its own transform included: the solid of an object pattern (scenegraph/object_pattern.h),
// whose inside() alone is asked, so no material matters. Null for a node with no geometry.
// Throws LocatedError as flattenScene.
std::unique_ptr<Shape> buildSolid(const Scene& scene, const Node& node,
                                  const ShapeMaker& makeShape);

// A light's projectedThrough objects (Light::projectedThrough, a group) as one shape placed
// by the light's worldFromLight, whose intersect() alone is asked: a union of its parts when
// it has several. Null for a group with no geometry. Throws LocatedError as flattenScene.
std::unique_ptr<Shape> buildProjection(const Scene& scene, const Light& light,
                                       const ShapeMaker& makeShape);

// Throws, without building any shape, the LocatedError that flattening would: a
// transform down to some node that is singular or beyond double range (nested scales).
// `lucent check` calls it so that it refuses what `lucent render` refuses.
void checkWorld(const Scene& scene);

}  // namespace lucent
