// The value of a procedural pattern at a point, as POV-Ray 3.7 computes it for a pigment
// (pattern.cpp: Evaluate_TPat and the pattern functions; docs/patterns-noise.md).
#pragma once

#include "scenegraph/pattern.h"

namespace lucent {

// The pattern function alone at a pattern-space point (already warped): the raw value
// before frequency, phase and wave shape. Mostly in [0, 1]; marble and the spirals return
// unbounded values that shapeValue wraps.
double rawPatternValue(const PatternSpec& spec, const Vec3& patternPoint);

// POV-Ray's FLOOR (texture.h): one below floor(x) at negative integers.
double povFloor(double x);

// quilted's offset from the centre of p's unit cube, scaled by the cubic of its length
// (control0, control1): the pattern's value is its mean absolute coordinate, a normal is
// bent along it.
Vec3 quiltedOffset(const Vec3& p, const QuiltedParams& q);

// POV-Ray's Evaluate_TPat: the raw value shaped by frequency, phase and wave.
double patternValueAt(const PatternSpec& spec, const Vec3& patternPoint);

// The value at an object-space point: placement and turbulence, then patternValueAt.
// In [0, 1]; POV-Ray's wrap lets values up to 1.00001 through (never NaN, unlike
// POV-Ray's at points near 1e300). Pure, thread-safe, allocates nothing.
double patternValue(const PatternSpec& spec, const Vec3& objectPoint);

}  // namespace lucent
