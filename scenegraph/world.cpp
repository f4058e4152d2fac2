#include "world.h"

#include "shape_registry.h"

namespace lucent {

namespace {

// The walk of a shadow ray through the objects that may transmit tests each in turn, when
// they are at most this many, instead of traversing their BVH: they are few (glass
// spheres and lenses), and the BVH's set-up per ray cost more than the box tests save
// (docs/performance-history.md, "Figures behind comments in the code").
constexpr size_t kLinearTransmissive = 4;

}  // namespace

World::World(const Scene& scene) : World(scene, makeShape) {}

World::World(const Scene& scene, const ShapeMaker& make) : scene_(scene) {
  FlatScene flat = flattenScene(scene, make);
  objects_ = std::move(flat.objects);
  leaves_ = std::move(flat.leaves);
  std::vector<Aggregate::Object> items;
  items.reserve(objects_.size());
  for (const WorldObject& o : objects_) {
    Aggregate::Mask mask = 0;
    if (o.castsShadow && o.transmits) mask |= kTransmits;
    if (!o.castsShadow) mask |= kShadowless;
    items.push_back({o.shape.get(), mask});
  }
  Aggregate::Options options;
  options.selected = kTransmits;
  options.linearSelected = kLinearTransmissive;
  options.sphereTestSlot = slotOf<SphereSpec>();
  aggregate_ = Aggregate(items, options);
}

}  // namespace lucent
