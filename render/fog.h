// What fog does to the colour seen along a stretch of ray, as POV-Ray 3.7's ComputeFog
// (source/core/render/trace.cpp in its sources): the colour C seen beyond the stretch becomes
//   C' = (1 − a)·F + a·((1 − filter) + filter·F)·C,   a = max(exp(−τ/distance), transmit)
// with F the fog colour and τ the stretch's optical depth: its length for constant fog,
// its length times the mean ground-fog density along it for ground fog, the length first
// shortened by the fog's turbulence if it has one. Several fogs combine as POV-Ray's: the
// shares kept multiply, the fog colours (1 − a)·F add. The tracer applies them to every
// stretch of a camera, reflected or transmitted ray that runs outside all solids or only
// inside hollow ones (POV-Ray's objects are not hollow by default: no fog inside them);
// shadow rays are fogged (kept shares only) for lights with media-attenuation, POV-Ray's
// media_attenuation on (off by default).
#pragma once

#include "scenegraph/fog.h"

#include <vector>

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

// All the fogs over the stretch, combined as POV-Ray's (the last declared first).
FogEffect fogsAlong(const std::vector<Fog>& fogs, const Vec3& origin, const Vec3& dir,
                    double length);

}  // namespace lucent
