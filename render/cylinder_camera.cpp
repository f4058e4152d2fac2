#include "cylinder_camera.h"

#include <cmath>

namespace lucent {

CylinderProjection::CylinderProjection(const CameraFrame& frame, const Camera& camera, int width,
                                       int height)
    : Projection(frame, camera, width, height),
      type_(camera.cylinderType),
      angle_(radians(camera.sweep)),
      axisLength_(cylinderAxisLength(camera, width, height)) {}

bool CylinderProjection::generateRay(const Vec2& film, const Vec2&, Ray& ray) const {
  const double s = film.x / width_ - 0.5, t = 0.5 - film.y / height_;
  Vec3 origin = frame_.origin, local;
  switch (type_) {
    case 1:
      local = Vec3(std::sin(s * angle_), t * axisLength_, std::cos(s * angle_));
      break;
    case 2:
      local = Vec3(s * axisLength_, std::sin(t * angle_), std::cos(t * angle_));
      break;
    case 3:
      local = Vec3(std::sin(s * angle_), 0.0, std::cos(s * angle_));
      origin += t * axisLength_ * frame_.up;
      break;
    default:  // 4 (the parser accepts 1 to 4)
      local = Vec3(0.0, std::sin(t * angle_), std::cos(t * angle_));
      origin += s * axisLength_ * frame_.right;
      break;
  }
  ray = primaryRay(origin, glm::normalize(frame_.toWorld(local)));
  return true;
}

}  // namespace lucent
