#include "omnimax.h"

#include <cmath>

namespace lucent {

namespace {
// The lens's own numbers (POV-Ray 3.7's omnimax camera).
constexpr double kWideFrame = 1.283458;
const double kBelowAxis = std::tan(135.0 * kPi / 180.0);
double lensAngle(double r) { return 1.411269 * r - 0.09439 * r * r * r + 0.25674 * std::pow(r, 5); }
}  // namespace

OmnimaxProjection::OmnimaxProjection(const CameraFrame& frame, const Camera& camera, int width,
                                     int height)
    : Projection(frame, camera, width, height) {
  double w = 0.0, h = 0.0;
  frameProportions(camera, width, height, w, h);
  aspect_ = w / h;
}

bool OmnimaxProjection::generateRay(const Vec2& film, const Vec2&, Ray& ray) const {
  double u = 2.0 * film.x / width_ - 1.0;
  double v = 1.0 - 2.0 * film.y / height_;
  if (aspect_ > kWideFrame) {
    u *= aspect_ / kWideFrame;
    v = (v - 1.0) / kWideFrame + 1.0;
  } else if (aspect_ > 1.0) {
    v = (v - 1.0) / aspect_ + 1.0;
  } else {
    v /= aspect_;
  }
  const double r = std::sqrt(u * u + v * v);
  if (r > 1.0) return false;
  const double theta = lensAngle(r);
  const double cosPhi = r > 0.0 ? u / r : 1.0, sinPhi = r > 0.0 ? v / r : 0.0;
  const double side = std::sin(theta), along = std::cos(theta);
  // Below 45 degrees under the axis (POV-Ray's test, with its tan(135 degrees)).
  if (sinPhi * side < kBelowAxis * along) return false;
  const Vec3 local(cosPhi * side, sinPhi * side, along);
  ray = primaryRay(frame_.origin, glm::normalize(frame_.toWorld(local)));
  return true;
}

}  // namespace lucent
