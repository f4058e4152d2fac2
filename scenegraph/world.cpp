#include "world.h"

#include "shape_registry.h"

#include <algorithm>

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
  componentMaterials_ = std::move(flat.componentMaterials);  // the leaves point into it
  std::vector<Aggregate::Object> items;
  items.reserve(objects_.size());
  for (const WorldObject& o : objects_) {
    Aggregate::Mask mask = 0;
    if (o.castsShadow && o.transmits) mask |= kTransmits;
    if (!o.castsShadow) mask |= kShadowless;
    if (!o.seenByImage) mask |= kNoImage;
    if (!o.seenByReflection) mask |= kNoReflection;
    items.push_back({o.shape.get(), mask});
  }
  Aggregate::Options options;
  options.selected = kTransmits;
  options.linearSelected = kLinearTransmissive;
  options.sphereTestSlot = slotOf<SphereSpec>();
  options.hidden = {kNoImage, kNoReflection};  // the views intersectSeen() searches
  aggregate_ = Aggregate(items, options);
  occluderSkips_ = aggregate_.anyMasked(kShadowless);
  opaqueSkips_ = aggregate_.anyMasked(kTransmits | kShadowless);
  const std::vector<Light>& lights = scene.lights;
  if (std::any_of(lights.begin(), lights.end(), [](const Light& l) { return l.projectedThrough; }))
    for (const Light& l : lights) projections_.push_back(buildProjection(scene, l, make));
}

// The queries of the ray path are calls here rather than inline in the tracer: with one
// call more between the tracer writing a ray and the search copying it whole, the copy
// no longer stalls on the ray's stores (a profile of the showcase put 5 % of its time
// there when they were inline; docs/performance-history.md, "The world split by job").
bool World::intersect(const Ray& ray, Hit& hit) const { return aggregate_.closest(ray, hit); }

bool World::intersect(const Ray& ray, WorldHit& hit) const {
  hit.leaves_ = leaves_.data();
  return aggregate_.closest(ray, hit.hit);
}

bool World::intersectSeen(const Ray& ray, WorldHit& hit, bool reflected) const {
  hit.leaves_ = leaves_.data();
  // A scene without the flags searches as intersect() does.
  if (!aggregate_.anyMasked(kNoImage | kNoReflection)) return aggregate_.closest(ray, hit.hit);
  return aggregate_.closestIn(reflected ? 1 : 0, ray, hit.hit);
}

bool World::intersectTransmissive(const Ray& ray, Hit& hit) const {
  return aggregate_.closestSelected(ray, hit);
}

bool World::intersectTransmissive(const Ray& ray, WorldHit& hit) const {
  hit.leaves_ = leaves_.data();
  return aggregate_.closestSelected(ray, hit.hit);
}

// The world's any-hit searches, each compiled here with its mask (Aggregate::anyHit);
// whether the mask leaves anything out was decided when the world was built.
World::ObjectId World::occluder(const Ray& ray, ObjectId first) const {
  if (!occluderSkips_) return aggregate_.anyHit<0>(ray, first);
  return aggregate_.anyHit<kShadowless>(ray, first);
}

World::ObjectId World::opaqueOccluder(const Ray& ray, ObjectId first) const {
  if (!opaqueSkips_) return aggregate_.anyHit<0>(ray, first);
  return aggregate_.anyHit<kTransmits | kShadowless>(ray, first);
}

}  // namespace lucent
