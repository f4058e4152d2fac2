// The camera block, written through the camera table (scenegraph/camera.h): each type's row
// gives POV-Ray's keyword and the lines of its parameters; a type without a POV-Ray twin is
// an error that lists those that have one.
#pragma once

#include "pov_writer.h"

#include "scenegraph/camera.h"
#include "scenegraph/render_settings.h"

namespace lucent {

// Where the camera is and how it is oriented, after its transform, exactly as the renderer
// builds its frame (render/camera_frame.h: position and look-at carried through the
// transform as points, up as a vector). ok is false for a degenerate camera.
struct PovCameraFrame {
  Vec3 location{0.0};
  Vec3 lookAt{0.0, 0.0, -1.0};
  Vec3 sky{0.0, 1.0, 0.0};
  bool ok = false;
};
PovCameraFrame povCameraFrame(const Camera& camera);

// Writes `camera { ... }`: the row's keyword and lines, then location, sky and look_at.
// POV-Ray is left-handed; our world is right-handed with +y up, so the rows write
// `right -x*...` (negative handedness), which makes look_at compute right = forward × sky,
// the renderer's frame, with every world coordinate unchanged.
void writeCamera(const Camera& camera, const RenderSettings& render, PovWriter& out,
                 PovIssues& issues);

}  // namespace lucent
