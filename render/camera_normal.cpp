#include "camera_normal.h"

#include "patterns/normal_perturbation.h"

#include <algorithm>
#include <cmath>

namespace lucent {

namespace {

// POV-Ray's angle of the image point about the view, from the direction's parts along
// right and up: asin(y/r) on the right half, π − asin(y/r) on the left, 0 at the centre.
double angleAboutView(double x, double y) {
  const double r = std::sqrt(x * x + y * y);
  if (r == 0.0) return 0.0;
  const double a = std::asin(std::clamp(y / r, -1.0, 1.0));
  return x < 0.0 ? kPi - a : a;
}

class BentProjection final : public Projection {
 public:
  BentProjection(std::unique_ptr<Projection> inner, const Camera& camera, int width, int height)
      : Projection(inner->frame(), camera, width, height),
        inner_(std::move(inner)),
        camera_(camera),
        normal_(*camera.normal) {}

  bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const override {
    if (!inner_->generateRay(film, lens, ray)) return false;
    const Vec3 p = cameraNormalPoint(camera_, frame_, film, ray.d, width_, height_);
    ray.d = glm::normalize(perturbNormal(normal_, p, ray.d));
    return true;
  }

 private:
  std::unique_ptr<Projection> inner_;
  Camera camera_;
  NormalSpec normal_;
};

}  // namespace

Vec3 cameraNormalPoint(const Camera& camera, const CameraFrame& frame, const Vec2& film,
                       const Vec3& direction, int width, int height) {
  const double s = film.x / width - 0.5, t = 0.5 - film.y / height;
  switch (camera.type) {
    case CameraType::Spherical:
      return Vec3(s * radians(camera.hAngle), t * radians(camera.vAngle), 0.0);
    case CameraType::UltraWideAngle: {
      double across = 0.0, down = 0.0;
      ultraWideAngles(camera, width, height, across, down);
      return Vec3(s * radians(across), t * radians(down), 0.0);
    }
    case CameraType::Cylinder: {
      const double axis = cylinderAxisLength(camera, width, height);
      const double sweep = radians(camera.sweep);
      const bool alongUp = camera.cylinderType == 1 || camera.cylinderType == 3;
      return alongUp ? Vec3(s * sweep, t * axis, 0.0) : Vec3(s * axis, t * sweep, 0.0);
    }
    case CameraType::Panoramic:
      return Vec3((1.0 - (s + 0.5)) * kPi, 2.0 * t * (0.5 * kPi), 0.0);
    case CameraType::Fisheye:
    case CameraType::Omnimax: {
      const double x = glm::dot(direction, frame.right), y = glm::dot(direction, frame.up);
      const double fromView = std::acos(std::clamp(glm::dot(direction, frame.forward), -1.0, 1.0));
      return Vec3(angleAboutView(x, y), fromView, 0.0);
    }
    case CameraType::Pinhole:
    case CameraType::ThinLens:
    case CameraType::Orthographic:
    case CameraType::Panini:
    case CameraType::Lenslet:
    case CameraType::Octahedral:
    case CameraType::Cubemap:
    case CameraType::Fibonacci:
    case CameraType::Mesh:  // takes no normal (lang/camera_parser.cpp)
      break;
  }
  return Vec3(s, t, 0.0);
}

std::unique_ptr<Projection> bentByCameraNormal(std::unique_ptr<Projection> projection,
                                               const Camera& camera, int width, int height) {
  return std::make_unique<BentProjection>(std::move(projection), camera, width, height);
}

}  // namespace lucent
