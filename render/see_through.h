// A see-through texture at one point (scenegraph/pattern.h, FilterTransmit): the colour
// there has a filter f and a transmit t, and the surface is the material with its own
// light scaled by the opacity 1 - f - t and the light from behind let through, as POV-Ray
// 3.7 weighs a pigment's filter and transmit (docs/scene-language.md, "Filter and
// transmit"). A later layered texture can fold each layer in with these two functions.
#pragma once

#include "scenegraph/material.h"

namespace lucent {

// What the surface lets through at a point of colour c: k_t·(1 - f - t) + C·f + t, per
// channel (not clamped: POV-Ray's does not clamp either).
Color transmittedThrough(const Material& m, const PigmentColor& c);

// The material as it is at a point of colour c: emissive, ambient and diffuse scaled by
// 1 - f - t, transmissive as transmittedThrough. The highlights and the mirror ray are
// not scaled (as POV-Ray's).
Material materialThrough(const Material& m, const PigmentColor& c);

}  // namespace lucent
