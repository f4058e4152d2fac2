// Writes a Lucent scene as an equivalent POV-Ray 3.7 scene file (`lucent export-pov`).
//
// What POV-Ray cannot express is an error naming the element; what it expresses only
// approximately is a warning. The mapping follows POV-Ray 3.7's documented semantics,
// each checked by rendering:
//   header         `#version 3.7;` (without it POV-Ray applies 3.62 rules) and
//                  global_settings { assumed_gamma 1.0 max_trace_level adc_bailout ambient_light }
//   camera         pov_camera.h     lights      pov_lights.h
//   materials      pov_materials.h  images      pov_image_map.h
//   geometry, CSG and transforms    pov_geometry.h
// World coordinates and matrices are written unchanged; only the camera's `right -x*W/H`
// accounts for POV-Ray's left-handedness.
#pragma once

#include "pov_writer.h"

#include "scenegraph/scene.h"

#include <string>
#include <vector>

namespace lucent {

struct PovExportOptions {
  std::string camera;  // by name; empty: the scene's first camera
};

struct PovExport {
  std::string text;              // the .pov file; empty when there are errors
  std::vector<PovIssue> issues;  // errors and warnings, in the order found
  bool ok() const;
};

// The scene's render settings (size, depth, min-weight, background, ambient) are used as
// they are, so apply command-line overrides to the scene first.
PovExport exportPov(const Scene& scene, const PovExportOptions& options = {});

}  // namespace lucent
