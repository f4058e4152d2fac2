// A scene's <fog> as POV-Ray's fog: fog_type 1 (constant) or 2 (ground, with fog_offset,
// fog_alt and up), the colour as rgbft with the fog's filter and transmit, and its
// turbulence (turbulence, octaves, omega, lambda, turb_depth). POV-Ray layers every fog of
// a scene as Lucent does.
#pragma once

#include "pov_writer.h"

#include "scenegraph/fog.h"

namespace lucent {

void writeFog(const Fog& fog, PovWriter& out, PovIssues& issues);

}  // namespace lucent
