// POV-Ray's number_of_waves is one setting for the whole scene (global_settings), where each
// of Lucent's ripples and waves patterns says how many sources it sums (`sources`).
#pragma once

#include "pov_writer.h"

#include "scenegraph/scene.h"

#include <optional>
#include <vector>

namespace lucent {

// The number of sources the ripples and waves of the exported scene share (those of the
// materials marked in `used`, the sky and the camera's normal), when it is not POV-Ray's
// default 10; an error where two of them differ, which one global setting cannot express.
std::optional<int> sharedWaveSources(const Scene& scene, const std::vector<bool>& used,
                                     const Camera& camera, PovIssues& issues);

}  // namespace lucent
