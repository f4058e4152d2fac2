#include "instance.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucent {

namespace {

// The rounding error a world point picks up when a ray starting at it is carried into
// object space (rayToObject: gamma(3) per row of objectFromWorld), expressed in the world
// through the linear part of worldFromObject. A secondary ray's origin makes exactly this
// trip, so its object-space origin may land that much closer to the surface than
// offsetRayOrigin placed it in the world; adding the bound to pError makes the offset
// cover it (pbrt-v3 §3.9.4 covers the same error by moving the transformed ray origin;
// folding it into pError instead keeps every t exactly in world units).
Vec3 worldToObjectRoundTripError(const Transform& t, const Vec3& pWorld) {
  const Mat4& inv = t.objectFromWorld();
  const Mat4& m = t.worldFromObject();
  Vec3 errObject(0.0);
  for (int r = 0; r < 3; ++r) {
    double mag = std::abs(inv[3][r]);
    for (int c = 0; c < 3; ++c) mag += std::abs(inv[c][r] * pWorld[c]);
    errObject[r] = gamma(3) * mag;
  }
  Vec3 err(0.0);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) err[r] += std::abs(m[c][r]) * errObject[c];
  return (1.0 + gamma(3)) * err;
}

// How far a point of the object's box, carried to the world and back, may land from itself
// because objectFromWorld is not exactly worldFromObject's inverse (a composed transform's
// inverse is the product of its parts' inverses, whose translations can cancel: a child
// moved by 0.5 in a parent scaled by 80 and moved by 40.5 comes back off by 1e-17, eight
// times the rounding bound above), in world units. Axes without a finite extent count 0.
double inverseMismatch(const Transform& t, const AABB& box) {
  const Mat4& m = t.worldFromObject();
  const Mat4 d = t.objectFromWorld() * m;
  Vec3 errObject(0.0);
  for (int r = 0; r < 3; ++r) {
    double e = std::abs(d[3][r]);
    for (int c = 0; c < 3; ++c) {
      const double extent = std::max(std::abs(box.lo[c]), std::abs(box.hi[c]));
      if (std::isfinite(extent)) e += std::abs(d[c][r] - (r == c ? 1.0 : 0.0)) * extent;
    }
    errObject[r] = e;
  }
  double world = 0.0;
  for (int r = 0; r < 3; ++r) {
    double e = 0.0;
    for (int c = 0; c < 3; ++c) e += std::abs(m[c][r]) * errObject[c];
    world = std::max(world, e);
  }
  return 2.0 * world;
}

}  // namespace

Instance::Instance(std::shared_ptr<const Shape> shape, const Transform& worldFromObject,
                   uint32_t tag, size_t testSlot)
    : shape_(std::move(shape)), tag_(tag), testSlot_(static_cast<uint8_t>(testSlot)) {
  if (!worldFromObject.isIdentity()) {
    placed_ = std::make_unique<Placement>(Placement{worldFromObject});
    placed_->surfaceError = inverseMismatch(worldFromObject, shape_->bounds());
  }
  bounds_ = transformBounds(worldFromObject.worldFromObject(), shape_->bounds());
}

const Transform Instance::kIdentity;

AABB Instance::boundsWithin(const AABB& clip) const {
  if (!placed_) return shape_->boundsWithin(clip);
  const Transform& t = placed_->transform;
  const AABB objectClip = transformBounds(t.objectFromWorld(), clip);
  const AABB part = transformBounds(t.worldFromObject(), shape_->boundsWithin(objectClip));
  return AABB::meet(AABB::meet(part, bounds_), clip);
}

// An identity transform (every shape placed by its own parameters, as spheres by their
// center) hands the ray over as it is: multiplying by the identity matrix would give the
// same numbers (except that it turns -0 into +0) for two matrix products per test.
Ray Instance::toObject(const Ray& ray) const {
  return placed_ ? placed_->transform.rayToObject(ray) : ray;
}

void Instance::widenSurfaceError(double distance) {
  if (!placed_ || !(distance >= 0.0))
    throw std::logic_error("Instance::widenSurfaceError: needs a transform and a distance >= 0");
  placed_->surfaceError += distance;
}

bool Instance::intersect(const Ray& ray, Hit& hit) const {
  ++threadTestCounts[testSlot_];
  if (!shape_->intersect(toObject(ray), hit)) return false;
  hit.shape = this;
  hit.tag = tag_;
  return true;
}

bool Instance::occluded(const Ray& ray) const {
  ++threadTestCounts[testSlot_];
  return shape_->occluded(toObject(ray));
}

void Instance::crossings(const Ray& ray, CrossingList& out) const {
  ++threadTestCounts[testSlot_];
  size_t first = out.items.size();
  shape_->crossings(toObject(ray), out);
  for (size_t i = first; i < out.items.size(); ++i) {
    out.items[i].hit.shape = this;
    out.items[i].hit.tag = tag_;
  }
}

bool Instance::inside(const Vec3& p) const {
  return shape_->inside(placed_ ? placed_->transform.pointToObject(p) : p);
}

SurfaceInfo Instance::surface(const Ray& ray, const Hit& hit, bool mappedUV) const {
  Hit local = hit;
  local.shape = shape_.get();
  // The ray the hit was found with (toObject); the rest goes through the matrices even
  // for the identity, whose error bound (errorToWorld) the offsets of secondary rays use.
  const Transform& t = transform();
  SurfaceInfo s = shape_->surface(toObject(ray), local);
  SurfaceInfo w = s;
  w.p = t.pointToWorld(s.p);
  w.pError = t.errorToWorld(s.p, s.pError);
  if (placed_) w.pError += worldToObjectRoundTripError(t, w.p) + Vec3(placed_->surfaceError);
  w.ng = t.normalToWorld(s.ng);
  w.ns = t.normalToWorld(s.ns);
  if (Vec3 ns; shape_->worldShadingNormal(toObject(ray), local, t, ns)) w.ns = ns;
  w.pObject = s.p;  // solid textures are evaluated in the leaf's object space
  if (mappedUV) {
    w.hasMappedUV = true;
    if (!shape_->povUV(s, local, w.mappedUV)) w.mappedUV = Vec2(w.p.x, w.p.y);
  }
  if (hit.flip) {
    w.ng = -w.ng;
    w.ns = -w.ns;
  }
  return w;
}

}  // namespace lucent
