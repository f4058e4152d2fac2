#include "instance.h"

namespace lucent {

Instance::Instance(std::shared_ptr<const Shape> shape, const Transform& worldFromObject,
                   uint32_t tag)
    : shape_(std::move(shape)), transform_(worldFromObject), tag_(tag) {
  bounds_ = transformBounds(transform_.worldFromObject(), shape_->bounds());
}

bool Instance::intersect(const Ray& ray, Hit& hit) const {
  if (!shape_->intersect(transform_.rayToObject(ray), hit)) return false;
  hit.shape = this;
  return true;
}

bool Instance::occluded(const Ray& ray) const {
  return shape_->occluded(transform_.rayToObject(ray));
}

void Instance::crossings(const Ray& ray, CrossingList& out) const {
  size_t first = out.items.size();
  shape_->crossings(transform_.rayToObject(ray), out);
  for (size_t i = first; i < out.items.size(); ++i) out.items[i].hit.shape = this;
}

bool Instance::inside(const Vec3& p) const { return shape_->inside(transform_.pointToObject(p)); }

SurfaceInfo Instance::surface(const Ray& ray, const Hit& hit) const {
  Hit local = hit;
  local.shape = shape_.get();
  SurfaceInfo s = shape_->surface(transform_.rayToObject(ray), local);
  SurfaceInfo w = s;
  w.p = transform_.pointToWorld(s.p);
  w.pError = transform_.errorToWorld(s.p, s.pError);
  w.ng = transform_.normalToWorld(s.ng);
  w.ns = transform_.normalToWorld(s.ns);
  w.pObject = s.p;  // solid textures are evaluated in the leaf's object space
  if (hit.flip) {
    w.ng = -w.ng;
    w.ns = -w.ns;
  }
  return w;
}

}  // namespace lucent
