// What a pattern may read of the surface being shaded: POV-Ray's slope reads its normal
// (and, with point_at, its point). The pattern evaluator is a function of a point; the
// surface reaches it through a per-thread scope the tracer opens around a hit, only in a
// scene that holds such a pattern (usesPatternSurface), so no other scene pays for it.
#pragma once

#include "primitives/math.h"
#include "scenegraph/material.h"

namespace lucent {

struct PatternSurface {
  Vec3 normal{0.0, 1.0, 0.0};  // world space, unit, facing the ray (POV-Ray's PNormal)
  Vec3 point{0.0};             // world space
};

// The surface of the innermost open scope on this thread, or null: no surface (a sky,
// a function, an isosurface), where POV-Ray's slope is 0.
const PatternSurface* currentPatternSurface();

// POV-Ray's PNormal after a normal pattern bent it: the current surface (if a scope is
// open) takes `normal`, which the slopes evaluated later at this hit read (the same
// layer's pigment, the layers below, a map's lower entry).
void bendPatternSurface(const Vec3& normal);

// Makes `surface` current until destroyed, then restores the one before (a reflected ray
// shades other surfaces inside the first one's shading). Inactive: changes nothing.
class PatternSurfaceScope {
 public:
  PatternSurfaceScope(bool active, PatternSurface& surface);
  ~PatternSurfaceScope();
  PatternSurfaceScope(const PatternSurfaceScope&) = delete;
  PatternSurfaceScope& operator=(const PatternSurfaceScope&) = delete;

 private:
  bool active_;
  PatternSurface* previous_ = nullptr;
};

// Some texture, map pattern or normal of the material (its layers and map entries
// included) holds a pattern that reads the surface (slope).
bool usesPatternSurface(const Material& material);

}  // namespace lucent
