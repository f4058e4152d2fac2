// The orthonormal frame every projection shares: where the camera is and where it looks.
#pragma once

#include "scenegraph/camera.h"
#include "scenegraph/located_error.h"

namespace lucent {

// Right-handed: right = forward × up, so the default camera (looking down -z, +y up) has
// +x on the right of the image. All three axes are unit and mutually orthogonal.
struct CameraFrame {
  Vec3 origin{0.0};
  Vec3 right{1.0, 0.0, 0.0};
  Vec3 up{0.0, 1.0, 0.0};
  Vec3 forward{0.0, 0.0, -1.0};
  double lookDistance = 1.0;  // |look-at − position|, the thin lens's default focus distance

  // A camera-space direction (x right, y up, z forward) in the world.
  Vec3 toWorld(const Vec3& local) const {
    return local.x * right + local.y * up + local.z * forward;
  }
};

// The camera's transform is applied after position/look-at/up: position and look-at are
// carried through it as points and up as a vector, and the frame is built from the
// results (so a scaling transform moves the camera but never skews its frame).
CameraFrame makeCameraFrame(const Camera& camera);

}  // namespace lucent
