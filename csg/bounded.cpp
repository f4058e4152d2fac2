#include "bounded.h"

#include <algorithm>
#include <stdexcept>

namespace lucent {

Bounded::Bounded(std::unique_ptr<Shape> shape, std::vector<std::unique_ptr<Shape>> bounds)
    : shape_(std::move(shape)), bounds_(std::move(bounds)) {
  if (!shape_) throw std::invalid_argument("bounded_by without a shape");
  for (const auto& b : bounds_)
    if (!b || !b->isSolid()) throw std::invalid_argument("a bounding object must be a solid");
}

bool Bounded::admits(const Ray& ray) const {
  // The whole ray from its origin (rays start at t = 0, spawned off the surface), whatever
  // part of it the search is looking at now: POV-Ray asks the bounding object along the
  // full ray, and whether the ray's origin is inside it.
  const Ray whole(ray.o, ray.d, 0.0, kInf);
  return std::all_of(bounds_.begin(), bounds_.end(),
                     [&](const auto& b) { return b->occluded(whole) || b->inside(ray.o); });
}

void Bounded::crossings(const Ray& ray, CrossingList& out) const {
  const size_t first = out.items.size();
  shape_->crossings(ray, out);
  if (admits(ray)) return;
  for (size_t i = first; i < out.items.size(); ++i) out.items[i].hidden = true;
}

}  // namespace lucent
