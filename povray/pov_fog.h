// The scene's <fog> as POV-Ray's fog: fog_type 1 (constant) or 2 (ground, with fog_offset,
// fog_alt and up), the colour as rgbft with the fog's filter and transmit.
#pragma once

#include "pov_writer.h"

#include "scenegraph/fog.h"

namespace lucent {

void writeFog(const Fog& fog, PovWriter& out);

}  // namespace lucent
