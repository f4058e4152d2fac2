// Lucent's primitives: the interface every piece of geometry implements.
#pragma once

#include "aabb.h"
#include "crossing.h"
#include "hit.h"
#include "ray.h"

#include <cstddef>

namespace lucent {

class Transform;

// A shape answers geometric questions in its own coordinate system. It knows nothing of
// materials or of the world: scenegraph/ adds those, csg/ composes solids.
//
// Search contract: intersect() and occluded() consider only t strictly inside
// (ray.tmin, ray.tmax); ray.d need not be unit length.
class Shape {
 public:
  virtual ~Shape() = default;

  // The element name of the scene language ("sphere", "mesh", "union", ...).
  virtual const char* kind() const = 0;
  virtual AABB bounds() const = 0;
  // A box holding the part of the solid inside `clip`, within clip: meet(bounds(), clip),
  // or tighter where the shape can tell (a hyperboloid cut to a slab). An intersection's
  // bounds come from its children's (csg/csg_node.cpp).
  virtual AABB boundsWithin(const AABB& clip) const { return AABB::meet(bounds(), clip); }
  // A solid encloses a volume: it has an inside() and its crossings alternate.
  virtual bool isSolid() const = 0;

  // Closest hit in (ray.tmin, ray.tmax): fills hit.t, hit.shape and the payload.
  virtual bool intersect(const Ray& ray, Hit& hit) const = 0;
  // Is there any hit in (ray.tmin, ray.tmax)? Shadow rays ask only this.
  virtual bool occluded(const Ray& ray) const {
    Hit h;
    return intersect(ray, h);
  }
  // Every crossing in [ray.tmin, ray.tmax], ordered by t, each marked entering or leaving,
  // and whether ray.at(ray.tmin) is inside. For a non-solid surface every crossing is
  // marked entering and startsInside is false. Appends to out.items.
  virtual void crossings(const Ray& ray, CrossingList& out) const = 0;
  // Point membership for solids (points on the surface may go either way).
  virtual bool inside(const Vec3& p) const = 0;

  // Geometry of a hit this shape found on the same ray.
  virtual SurfaceInfo surface(const Ray& ray, const Hit& hit) const = 0;

  // POV-Ray 3.7's (u, v) at a hit (its UVCoord, which uv_mapping reads), in POV-Ray's
  // left-handed object space (pov_uv.h), given this shape's surface() `s` for the hit.
  // False where POV-Ray has none: its uv_mapping then reads the world point's x and y
  // (Instance gives them). Asked only for leaves whose material maps patterns at (u, v).
  virtual bool povUV(const SurfaceInfo& /*s*/, const Hit& /*hit*/, Vec2& /*uv*/) const {
    return false;
  }

  // The shading normal in world space where the shape blends its normals there, as POV-Ray
  // blends a smooth height field's vertex normals after transforming them (Instance asks;
  // false: the object-space shading normal of surface() is transformed as usual).
  virtual bool worldShadingNormal(const Ray& /*objectRay*/, const Hit& /*hit*/,
                                  const Transform& /*worldFromObject*/, Vec3& /*ns*/) const {
    return false;
  }

  // Statistics for `lucent check`.
  virtual size_t triangleCount() const { return 0; }
};

}  // namespace lucent
