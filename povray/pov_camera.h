// The camera block: pinhole -> perspective, orthographic, fisheye (equidistant); other
// camera types have no POV-Ray equivalent and are errors.
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

// The full horizontal field of view (degrees) of a pinhole camera on a width x height
// image, whatever its fov-axis (POV-Ray's `angle` spans the `right` vector).
double horizontalFovDegrees(const Camera& camera, int width, int height);

// Writes `camera { ... }`. POV-Ray is left-handed; our world is right-handed with +y up, so
// `right -x*W/H` (negative handedness) makes look_at compute right = forward × sky, the
// renderer's frame, with every world coordinate unchanged.
void writeCamera(const Camera& camera, const RenderSettings& render, PovWriter& out,
                 PovIssues& issues);

}  // namespace lucent
