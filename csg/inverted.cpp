#include "inverted.h"

#include <stdexcept>

namespace lucent {

Inverted::Inverted(std::unique_ptr<Shape> solid) : solid_(std::move(solid)) {
  if (!solid_ || !solid_->isSolid()) throw std::invalid_argument("inverse needs a solid");
}

bool Inverted::intersect(const Ray& ray, Hit& hit) const {
  if (!solid_->intersect(ray, hit)) return false;
  hit.flip = !hit.flip;
  return true;
}

void Inverted::crossings(const Ray& ray, CrossingList& out) const {
  const size_t first = out.items.size();
  solid_->crossings(ray, out);
  out.startsInside = !out.startsInside;
  for (size_t i = first; i < out.items.size(); ++i) {
    Crossing& c = out.items[i];
    c.entering = !c.entering;
    c.hit.flip = !c.hit.flip;
  }
}

}  // namespace lucent
