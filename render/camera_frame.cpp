#include "camera_frame.h"

#include <fmt/core.h>

namespace lucent {

CameraFrame makeCameraFrame(const Camera& camera) {
  const Mat4& m = camera.transform;
  Vec3 position = Vec3(m * Vec4(camera.position, 1.0));
  Vec3 lookAt = Vec3(m * Vec4(camera.lookAt, 1.0));
  Vec3 up = Mat3(m) * camera.up;

  Vec3 view = lookAt - position;
  double distance = glm::length(view);
  if (!(distance > 0.0) || !std::isfinite(distance))
    throw LocatedError(camera.loc, "camera look-at coincides with its position");
  CameraFrame f;
  f.origin = position;
  f.forward = view / distance;
  f.lookDistance = distance;
  Vec3 right = glm::cross(f.forward, up);
  double rightLength = glm::length(right);
  // sin of the angle between up and the view direction: below ~1e-9 the frame is noise.
  if (!(rightLength > 1e-9 * glm::length(up)))
    throw LocatedError(camera.loc, "camera up is parallel to the viewing direction");
  f.right = right / rightLength;
  f.up = glm::cross(f.right, f.forward);
  if (camera.mirror) f.right = -f.right;  // the image mirrored left to right
  return f;
}

}  // namespace lucent
