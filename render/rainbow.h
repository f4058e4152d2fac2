// POV-Ray's rainbows on a stretch of ray (scenegraph/rainbow.h; docs/scene-language.md,
// "<rainbow>"): the colour C seen at the stretch's end becomes keep·C + add, applied
// before the fogs, as POV-Ray applies them (its Trace::ComputeRainbow).
#pragma once

#include "scenegraph/rainbow.h"

#include <vector>

namespace lucent {

struct RainbowEffect {
  Color keep{1.0f};
  Color add{0.0f};
  Color apply(const Color& c) const { return keep * c + add; }
};

// The rainbows' effect on a stretch along the unit direction `dir`, `length` long (kInf for
// a ray that leaves the scene); `dir`'s bits choose the jitter, so a ray repeats its colour.
RainbowEffect rainbowsAlong(const std::vector<Rainbow>& rainbows, const Vec3& dir, double length);

}  // namespace lucent
