// The geometry side of a world: the objects placed in world space (leaf instances and CSG
// nodes) in one search structure that answers the ray queries of a tracer, closest hit
// and any hit. It knows nothing of materials or lights: each object carries a mask of bits
// whose meaning is the caller's (scenegraph/world.h: "may transmit light", "casts no
// shadow"), and a query names the bits of the objects it leaves out.
#pragma once

#include "bvh.h"
#include "shape.h"
#include "test_counts.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lucent {

class Aggregate {
 public:
  // An object as anyHit() names it: an index into directObjects(), then into the BVH's
  // leaf slots. kNoObject names none.
  using ObjectId = uint32_t;
  static constexpr ObjectId kNoObject = 0xffffffffu;
  using Mask = uint8_t;

  struct Object {
    // In world space. Not const: a sphere kept in world space widens its Instance's
    // surface error (Instance::widenSurfaceError).
    Shape* shape = nullptr;
    Mask mask = 0;
  };

  struct Options {
    // The objects closestSelected() searches: those whose mask has one of these bits.
    Mask selected = 0;
    // closestSelected() tests its objects one by one, without their BVH, when they are at
    // most this many.
    size_t linearSelected = 0;
    // What --stats counts a test of a sphere kept in world space as (test_counts.h).
    size_t sphereTestSlot = kOtherTestSlot;
    // closestIn(v) searches the objects whose mask has no bit of hidden[v].
    std::array<Mask, 2> hidden{0, 0};
  };

  Aggregate() = default;
  // The objects with a finite box go into a BVH; the others (planes), or a lone object,
  // are tested one by one. An Instance of a Sphere whose transform is a similarity is
  // kept in the BVH's leaves as a sphere in world space (sphere_image.h), tested without a
  // virtual call or a pointer to follow; its hits still name its Instance.
  Aggregate(const std::vector<Object>& objects, const Options& options);

  // The closest hit over every object.
  bool closest(const Ray& ray, Hit& hit) const { return all_.closest(ray, hit); }
  // closest() over the selected objects only, with the same tests and so the same hits to
  // the last bit.
  bool closestSelected(const Ray& ray, Hit& hit) const { return selected_.closest(ray, hit); }
  // closest() over the objects of view v (Options::hidden), with the same tests: the whole
  // search itself when no object is hidden from the view, else one built for it.
  bool closestIn(size_t v, const Ray& ray, Hit& hit) const {
    return (viewOf_[v] < 0 ? all_ : views_[size_t(viewOf_[v])]).closest(ray, hit);
  }

  // An object that the ray hits, leaving out the objects whose mask has a bit of kSkip;
  // kNoObject if none. `first`, kNoObject or an id an earlier call on this aggregate
  // returned, is tested before all others, by the same test the full search makes (a
  // shadow cache passes the object that blocked the previous ray towards the same light,
  // as POV-Ray does). Then the BVH, then the unbounded objects. The order of an any-hit
  // search changes how soon the answer is found, never what it is: whether the answer is
  // kNoObject does not depend on `first`. (The mask is a template argument, and the
  // search is defined below, in the header: each query a caller makes is compiled with
  // its mask as a constant, as the world's shadow queries were before the aggregate was
  // split out of it; a shadow ray's any-hit search is most of a render's work.)
  template <Mask kSkip = 0>
  ObjectId anyHit(const Ray& ray, ObjectId first = kNoObject) const;
  // Whether some object's mask has a bit of `bits` (if none has, anyHit<0>() answers as
  // anyHit<bits>(), without reading the masks).
  bool anyMasked(Mask bits) const { return (anyMask_ & bits) != 0; }

  // The object an id names, nullptr for kNoObject.
  const Shape* object(ObjectId id) const;
  size_t objectCount() const { return all_.direct.size() + all_.leafObjects.size(); }
  // How many objects closestSelected() searches.
  size_t selectedCount() const { return selected_.direct.size() + selected_.leafObjects.size(); }

  // The BVH, for statistics.
  const Bvh& bvh() const { return all_.bvh; }
  // The objects tested one by one beside the BVH: unbounded ones, or a lone object.
  const std::vector<const Shape*>& directObjects() const { return all_.direct; }
  // How many of the BVH's objects are spheres kept in world space.
  size_t inlineSphereCount() const { return inlineSpheres_; }

 private:
  // One entry per slot of a BVH's leaves, in leaf order, 32 bytes (two to a cache
  // line): a sphere in world space (centre and squared radius, r2 >= 0), or r2 < 0 for
  // any other object, which is tested through leafObjects.
  struct alignas(32) Leaf {
    double cx, cy, cz, r2;
  };
  // Objects a search tests: some one by one, the others in a BVH.
  struct Search {
    std::vector<Leaf, CacheLineAllocator<Leaf>> leaves;
    std::vector<const Shape*> leafObjects;  // the same slots: the sphere's Instance, or the object
    std::vector<uint32_t> sphereTags;       // the same slots: the sphere's Instance's tag, or 0
    std::vector<const Shape*> direct;       // never in the BVH
    Bvh bvh;
    // closest() tests the BVH's objects one by one when they are at most this many.
    size_t linearSearch = 0;
    size_t sphereTestSlot = kOtherTestSlot;

    bool closest(const Ray& ray, Hit& hit) const;
    // Any hit of the object in BVH leaf slot `slot`: the one test every search makes of it.
    bool slotOccluded(uint32_t slot, const Ray& ray) const;
    // Asks for the cache lines of leaves[first, first + count) (Bvh::candidates).
    void prefetchLeaves(uint32_t first, uint32_t count) const {
      const char* p = reinterpret_cast<const char*>(leaves.data() + first);
      const char* end = reinterpret_cast<const char*>(leaves.data() + first + count);
      // From the cache line holding the first record (the records are 32 bytes, aligned).
      for (p -= reinterpret_cast<uintptr_t>(p) & 63; p < end; p += 64) __builtin_prefetch(p);
    }
  };

  // Whether anyHit<kSkip>() leaves the object out.
  template <Mask kSkip>
  bool leftOut(ObjectId id) const {
    if constexpr (kSkip == 0) return false;
    else return (masks_[id] & kSkip) != 0;
  }

  Search all_;
  Search selected_;  // the objects of all_ that are selected, tested as all_ tests them
  // The searches of the views that hide some object; viewOf_: a view's, or -1 for all_.
  std::vector<Search> views_;
  std::array<int, 2> viewOf_{-1, -1};
  // Per ObjectId: the object's mask. Empty when every mask is 0.
  std::vector<Mask> masks_;
  Mask anyMask_ = 0;  // the union of every mask
  size_t inlineSpheres_ = 0;
};

template <Aggregate::Mask kSkip>
Aggregate::ObjectId Aggregate::anyHit(const Ray& ray, ObjectId first) const {
  const auto& direct = all_.direct;
  const auto directCount = static_cast<ObjectId>(direct.size());
  if (first != kNoObject && !leftOut<kSkip>(first) &&
      (first < directCount ? direct[first]->occluded(ray)
                           : all_.slotOccluded(first - directCount, ray)))
    return first;
  // The BVH before the unbounded objects (an any-hit search may take them in any
  // order): a floor plane is tested by every shadow ray and blocks few, and this order
  // made such scenes markedly faster, which was measured, not explained
  // (docs/performance-history.md, "Shadow rays").
  ObjectId found = kNoObject;
  auto blocks = [&](uint32_t slot, const Ray& r) {
    const ObjectId id = directCount + slot;
    // `first` missed already
    if (id == first || leftOut<kSkip>(id) || !all_.slotOccluded(slot, r)) return false;
    found = id;
    return true;
  };
  all_.bvh.any(ray, blocks,
               [this](uint32_t first, uint32_t count) { all_.prefetchLeaves(first, count); });
  if (found != kNoObject) return found;
  for (ObjectId k = 0; k < directCount; ++k)
    if (k != first && !leftOut<kSkip>(k) && direct[k]->occluded(ray)) return k;
  return kNoObject;
}

}  // namespace lucent
