// The world a renderer traces: every leaf placed with its world transform and material,
// CSG nodes composed of such leaves, built once from a scene graph.
#pragma once

#include "scene.h"

#include "primitives/bvh.h"
#include "primitives/instance.h"
#include "primitives/shape.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <type_traits>
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
  // The top-level objects with a finite box go into a BVH; the others (planes), or a
  // lone object, are tested one by one. A top-level sphere whose transform is a
  // similarity is kept in the BVH's leaves as a sphere in world space (sphere_image.h),
  // tested without a virtual call or a pointer to follow; its hits still name its
  // Instance. The scene must outlive the world. Throws LocatedError (checkWorld's).
  explicit World(const Scene& scene);
  World(const Scene& scene, const ShapeMaker& makeShape);

  const Scene& scene() const { return scene_; }
  const std::vector<std::unique_ptr<Shape>>& objects() const { return objects_; }
  // Every leaf instance, including those inside CSG nodes, in scene order.
  const std::vector<const Instance*>& instances() const { return instances_; }

  bool intersect(const Ray& ray, Hit& hit) const;
  // Whether an object that casts shadows crosses the ray (objects of shadows="false"
  // nodes are not asked, here and in every shadow query below).
  bool occluded(const Ray& ray) const;

  // A top-level object as occluder() names it: an index into directObjects(), then into
  // the BVH's leaf slots. kNoObject names none.
  using ObjectId = uint32_t;
  static constexpr ObjectId kNoObject = 0xffffffffu;
  // occluded(), also naming an object that blocks the ray (kNoObject if none does).
  // `first`, kNoObject or an id an earlier call on this world returned, is tested
  // before all others, by the same test the full search makes: a shadow cache passes
  // the object that blocked the previous ray towards the same light (as POV-Ray does).
  // Then the BVH, then the unbounded objects. The order of an any-hit search changes
  // how soon the answer is found, never what it is: occluder(ray, first) != kNoObject
  // equals occluded(ray) for every `first`.
  ObjectId occluder(const Ray& ray, ObjectId first = kNoObject) const;
  // The object an id names (an Instance or a CSG node), nullptr for kNoObject.
  const Shape* object(ObjectId id) const;

  // For shadow rays in scenes with transmissive materials. An object "may transmit" when
  // one of its leaves has a transmissive material and it casts shadows (the shadow
  // queries skip every object built from shadows="false" nodes). opaqueOccluder() is occluder()
  // over the other objects only: one of them in the way blocks the light whatever else the ray
  // crosses. intersectTransmissive() is intersect() over the objects that may transmit
  // only, with the same tests and so the same hits to the last bit: a shadow ray that no
  // opaque object blocks walks these alone.
  ObjectId opaqueOccluder(const Ray& ray, ObjectId first = kNoObject) const;
  bool intersectTransmissive(const Ray& ray, Hit& hit) const;
  // How many top-level objects may transmit light.
  size_t transmissiveObjectCount() const {
    return transmissive_.direct.size() + transmissive_.leafObjects.size();
  }

  // The top-level acceleration structure, for statistics.
  const Bvh& bvh() const { return all_.bvh; }
  // The objects tested one by one beside the BVH: unbounded ones, or a lone object.
  const std::vector<const Shape*>& directObjects() const { return all_.direct; }
  // How many of the BVH's objects are spheres kept in world space.
  size_t inlineSphereCount() const { return inlineSpheres_; }

  // The material of a hit's leaf (hit.shape is always an Instance).
  const Material& material(const Hit& hit) const {
    return scene_.materials[static_cast<const Instance*>(hit.shape)->tag()];
  }

 private:
  const Scene& scene_;
  std::vector<std::unique_ptr<Shape>> objects_;  // top level: instances and CSG nodes
  std::vector<const Instance*> instances_;
  // One entry per slot of a BVH's leaves, in leaf order, 32 bytes (two to a cache
  // line): a sphere in world space (centre and squared radius, r2 >= 0), or r2 < 0 for
  // any other object, which is tested through leafObjects.
  struct alignas(32) Leaf {
    double cx, cy, cz, r2;
  };
  // Objects a search tests: some one by one, the others in a BVH.
  struct Objects {
    std::vector<Leaf, CacheLineAllocator<Leaf>> leaves;
    std::vector<const Shape*> leafObjects;  // the same slots: the sphere's Instance, or the object
    std::vector<const Shape*> direct;       // never in the BVH
    Bvh bvh;
    // intersect() tests the BVH's objects one by one when they are at most this many.
    size_t linearSearch = 0;

    bool intersect(const Ray& ray, Hit& hit) const;
    // Any hit of the object in BVH leaf slot `slot`: the one test every search makes of it.
    bool slotOccluded(uint32_t slot, const Ray& ray) const;
    // Asks for the cache lines of leaves[first, first + count) (Bvh::candidates).
    void prefetchLeaves(uint32_t first, uint32_t count) const;
  };
  Objects all_;
  Objects transmissive_;  // the objects of all_ that may transmit, tested as all_ tests them
  // Per ObjectId of all_: kTransmits if the object may transmit (and casts shadows),
  // kShadowless if it casts none (shadows="false"). Empty when no object is either.
  static constexpr uint8_t kTransmits = 1, kShadowless = 2;
  std::vector<uint8_t> skip_;
  bool anyShadowless_ = false;
  size_t inlineSpheres_ = 0;

  // occluder(), skipping the objects with a flag of kSkip.
  template <uint8_t kSkip>
  ObjectId findOccluder(const Ray& ray, ObjectId first) const;
  template <uint8_t kSkip>
  bool skips(ObjectId id, std::integral_constant<uint8_t, kSkip>) const {
    if constexpr (kSkip == 0) return false;
    else return (skip_[id] & kSkip) != 0;
  }
};

}  // namespace lucent
