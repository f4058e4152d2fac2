// The world a renderer traces: every leaf placed with its world transform and material,
// CSG nodes composed of such leaves, built once from a scene graph.
#pragma once

#include "scene.h"

#include "primitives/aggregate.h"
#include "primitives/instance.h"
#include "primitives/shape.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace lucent {

// Builds the shape of one geometry node (makeShape; tests pass their own).
using ShapeMaker = std::function<std::shared_ptr<const Shape>(const ShapeSpec&)>;

// Throws, without building any shape, the LocatedError that building the world would:
// a transform down to some node that is singular or beyond double range (nested scales).
// `lucent check` calls it so that it refuses what `lucent render` refuses.
void checkWorld(const Scene& scene);

class World {
 public:
  // Composes transforms down to the leaves (world matrix, inverse and normal matrix
  // computed once per instance), resolves inherited materials and shares the shape of a
  // node used many times: a mesh used through many <use> is stored and built once.
  // The top-level objects go into an Aggregate (primitives/aggregate.h), which answers
  // the ray queries. The scene must outlive the world. Throws LocatedError (checkWorld's).
  explicit World(const Scene& scene);
  World(const Scene& scene, const ShapeMaker& makeShape);

  const Scene& scene() const { return scene_; }
  const std::vector<std::unique_ptr<Shape>>& objects() const { return objects_; }
  // Every leaf instance, including those inside CSG nodes, in scene order.
  const std::vector<const Instance*>& instances() const { return instances_; }

  bool intersect(const Ray& ray, Hit& hit) const { return aggregate_.closest(ray, hit); }
  // Whether an object that casts shadows crosses the ray (objects of shadows="false"
  // nodes are not asked, here and in every shadow query below).
  bool occluded(const Ray& ray) const { return occluder(ray) != kNoObject; }

  // A top-level object as occluder() names it (Aggregate::ObjectId). kNoObject names none.
  using ObjectId = Aggregate::ObjectId;
  static constexpr ObjectId kNoObject = Aggregate::kNoObject;
  // occluded(), also naming an object that blocks the ray (kNoObject if none does).
  // `first`, kNoObject or an id an earlier call on this world returned, is tested
  // before all others (Aggregate::anyHit): a shadow cache passes the object that blocked
  // the previous ray towards the same light. occluder(ray, first) != kNoObject equals
  // occluded(ray) for every `first`.
  ObjectId occluder(const Ray& ray, ObjectId first = kNoObject) const {
    return aggregate_.anyHit(ray, kShadowless, first);
  }
  // The object an id names (an Instance or a CSG node), nullptr for kNoObject.
  const Shape* object(ObjectId id) const { return aggregate_.object(id); }

  // For shadow rays in scenes with transmissive materials. An object "may transmit" when
  // one of its leaves has a transmissive material and it casts shadows (the shadow
  // queries skip every object built from shadows="false" nodes). opaqueOccluder() is occluder()
  // over the other objects only: one of them in the way blocks the light whatever else the ray
  // crosses. intersectTransmissive() is intersect() over the objects that may transmit
  // only, with the same tests and so the same hits to the last bit: a shadow ray that no
  // opaque object blocks walks these alone.
  ObjectId opaqueOccluder(const Ray& ray, ObjectId first = kNoObject) const {
    return aggregate_.anyHit(ray, kTransmits | kShadowless, first);
  }
  bool intersectTransmissive(const Ray& ray, Hit& hit) const {
    return aggregate_.closestSelected(ray, hit);
  }
  // How many top-level objects may transmit light.
  size_t transmissiveObjectCount() const { return aggregate_.selectedCount(); }

  // The top-level search structure, for statistics.
  const Aggregate& aggregate() const { return aggregate_; }
  const Bvh& bvh() const { return aggregate_.bvh(); }
  const std::vector<const Shape*>& directObjects() const { return aggregate_.directObjects(); }
  size_t inlineSphereCount() const { return aggregate_.inlineSphereCount(); }

  // The material of a hit's leaf (hit.shape is always an Instance).
  const Material& material(const Hit& hit) const {
    return scene_.materials[static_cast<const Instance*>(hit.shape)->tag()];
  }

 private:
  // The meaning of the aggregate's mask bits: the object may transmit light (and casts
  // shadows); it casts no shadow (shadows="false").
  static constexpr Aggregate::Mask kTransmits = 1, kShadowless = 2;

  const Scene& scene_;
  std::vector<std::unique_ptr<Shape>> objects_;  // top level: instances and CSG nodes
  std::vector<const Instance*> instances_;
  Aggregate aggregate_;
};

}  // namespace lucent
