// The warning for a camera inside an opaque solid (scenegraph/camera_inside.h), at the
// solid and naming the camera, with how to turn a plane inside out.
#pragma once

#include "diagnostics.h"

#include "scenegraph/scene.h"

namespace lucent {

void warnCamerasInsideOpaqueSolids(const Scene& scene, Diagnostics& diags);

}  // namespace lucent
