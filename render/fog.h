// What fog does to the colour seen along a stretch of ray, as POV-Ray 3.7's Trace::ComputeFog:
// the colour C seen beyond the stretch becomes
//   C' = (1 − a)·F + a·((1 − filter) + filter·F)·C,   a = max(exp(−τ/distance), transmit)
// with F the fog colour and τ the stretch's optical depth: its length for constant fog,
// its length times the mean ground-fog density along it for ground fog. The tracer applies
// it to every stretch of a camera, reflected or transmitted ray that runs outside all
// solids (POV-Ray's objects are not hollow by default: no fog inside them); shadow rays
// are not fogged (POV-Ray's lights default to media_attenuation off).
#pragma once

#include "scenegraph/fog.h"

namespace lucent {

struct FogEffect {
  Color keep{1.0f};  // multiplies the colour seen beyond the stretch
  Color add{0.0f};   // the fog's own colour, added

  Color apply(const Color& beyond) const { return add + keep * beyond; }
};

// τ of the stretch from `origin` along the unit direction `dir` for `length` (kInf: a ray
// that leaves the scene).
double fogDepth(const Fog& fog, const Vec3& origin, const Vec3& dir, double length);

FogEffect fogAlong(const Fog& fog, const Vec3& origin, const Vec3& dir, double length);

}  // namespace lucent
