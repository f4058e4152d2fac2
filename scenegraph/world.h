// The world a renderer traces, built once from a scene graph: the scene side (the graph
// flattened into objects and leaves that know their materials, flatten.h) joined to the
// geometry side (the masked aggregate that searches them, primitives/aggregate.h). The
// tracer asks it every ray query and gets back typed hits: no cast on the ray path.
#pragma once

#include "flatten.h"
#include "scene.h"

#include "primitives/aggregate.h"
#include "primitives/hit.h"

#include <cstddef>
#include <vector>

namespace lucent {

// A hit as the tracer sees it: the leaf's Hit (its distance and payload) and the leaf,
// with the material, medium and transmissive flag the world worked out when it was built.
class WorldHit {
 public:
  Hit hit;

  // The leaf hit (the one Hit::tag names). Only after a query that found a hit.
  const WorldLeaf& leaf() const { return leaves_[hit.tag]; }
  double t() const { return hit.t; }
  // The geometry at the hit, for the ray it was found with.
  SurfaceInfo surface(const Ray& ray) const {
    return leaf().instance->surface(ray, hit, leaf().uvMapped);
  }

 private:
  friend class World;
  // The world's leaves, set by the query: the leaf is looked up when asked, so that the
  // query itself is only the aggregate's search (a call that does no work after it).
  const WorldLeaf* leaves_ = nullptr;
};

class World {
 public:
  // Flattens the scene (flattenScene, through makeShape or the given maker) and puts the
  // top-level objects into an Aggregate. The scene must outlive the world, its materials
  // kept in place. Throws LocatedError (checkWorld's).
  explicit World(const Scene& scene);
  World(const Scene& scene, const ShapeMaker& makeShape);

  const Scene& scene() const { return scene_; }
  // The top-level objects, in scene order.
  const std::vector<WorldObject>& objects() const { return objects_; }
  // Every leaf, those inside CSG nodes too, in scene order.
  const std::vector<WorldLeaf>& leaves() const { return leaves_; }
  // The leaf a hit names (Hit::tag).
  const WorldLeaf& leaf(const Hit& hit) const { return leaves_[hit.tag]; }
  const Material& material(const Hit& hit) const { return *leaf(hit).material; }

  // The closest hit: the geometry alone, or typed.
  bool intersect(const Ray& ray, Hit& hit) const;
  bool intersect(const Ray& ray, WorldHit& hit) const;
  // The closest hit a ray of the tracer sees: a reflected ray (or one that went on from a
  // reflection) does not see the objects of reflection="false" nodes, any other the objects
  // of image="false" nodes (POV-Ray's no_reflection, no_image). In a scene without them,
  // intersect().
  bool intersectSeen(const Ray& ray, WorldHit& hit, bool reflected) const;
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
  ObjectId occluder(const Ray& ray, ObjectId first = kNoObject) const;
  // The object an id names (an Instance or a CSG node), nullptr for kNoObject.
  const Shape* object(ObjectId id) const { return aggregate_.object(id); }

  // For shadow rays in scenes with transmissive materials. An object "may transmit" when
  // one of its leaves has a transmissive material and it casts shadows (the shadow
  // queries skip every object built from shadows="false" nodes). opaqueOccluder() is occluder()
  // over the other objects only: one of them in the way blocks the light whatever else the ray
  // crosses. intersectTransmissive() is intersect() over the objects that may transmit
  // only, with the same tests and so the same hits to the last bit: a shadow ray that no
  // opaque object blocks walks these alone.
  ObjectId opaqueOccluder(const Ray& ray, ObjectId first = kNoObject) const;
  bool intersectTransmissive(const Ray& ray, Hit& hit) const;
  bool intersectTransmissive(const Ray& ray, WorldHit& hit) const;
  // How many top-level objects may transmit light.
  size_t transmissiveObjectCount() const { return aggregate_.selectedCount(); }

  // Light k's projected-through objects (Scene::lights[k].projectedThrough) as one shape
  // in the world; null when it has none.
  const Shape* projection(size_t light) const {
    return light < projections_.size() ? projections_[light].get() : nullptr;
  }

  // The top-level search structure, for statistics.
  const Aggregate& aggregate() const { return aggregate_; }
  const Bvh& bvh() const { return aggregate_.bvh(); }
  const std::vector<const Shape*>& directObjects() const { return aggregate_.directObjects(); }
  size_t inlineSphereCount() const { return aggregate_.inlineSphereCount(); }

 private:
  // The meaning of the aggregate's mask bits: the object may transmit light (and casts
  // shadows); it casts no shadow (shadows="false").
  // Not seen by camera rays (image="false"); not seen by reflected rays (reflection="false").
  static constexpr Aggregate::Mask kTransmits = 1, kShadowless = 2, kNoImage = 4, kNoReflection = 8;

  const Scene& scene_;
  std::vector<WorldObject> objects_;
  std::vector<WorldLeaf> leaves_;
  std::deque<std::vector<uint32_t>> componentMaterials_;  // WorldLeaf::componentMaterials
  Aggregate aggregate_;
  std::vector<std::unique_ptr<Shape>> projections_;  // projection(), empty when no light has one
  // Whether occluder() and opaqueOccluder() have objects to leave out.
  bool occluderSkips_ = false, opaqueSkips_ = false;
};

}  // namespace lucent
