// A scene's <rainbow> as POV-Ray's rainbow: direction, angle, width, distance, jitter, up,
// arc_angle, falloff_angle and its colour_map as rgbft entries. POV-Ray averages the
// rainbows a ray meets as Lucent does.
#pragma once

#include "pov_writer.h"

#include "scenegraph/rainbow.h"

namespace lucent {

void writeRainbow(const Rainbow& rainbow, PovWriter& out, PovIssues& issues);

}  // namespace lucent
