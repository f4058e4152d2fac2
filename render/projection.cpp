#include "projection.h"

#include "camera_normal.h"
#include "cubemap.h"
#include "cylinder_camera.h"
#include "fibonacci.h"
#include "fisheye.h"
#include "focal_blur.h"
#include "lenslet.h"
#include "mesh_camera.h"
#include "octahedral.h"
#include "omnimax.h"
#include "orthographic.h"
#include "panini.h"
#include "panoramic.h"
#include "pinhole.h"
#include "thin_lens.h"
#include "ultra_wide_angle.h"

#include <fmt/core.h>

#include <cmath>

namespace lucent {

namespace {

// The spherical camera, POV-Ray 3.7's `spherical`: a latitude-longitude (equirectangular)
// image. XML:
//   <camera type="spherical" h-angle="360" v-angle="180"/>
// Film x spans longitudes -h-angle/2 to +h-angle/2 from the left edge to the right, film y
// latitudes +v-angle/2 to -v-angle/2 from the top edge to the bottom; the image centre looks
// forward. The direction at longitude lon and latitude lat is
//   cos(lat) (cos(lon) forward + sin(lon) right) + sin(lat) up,
// POV-Ray's rotation of the view direction about right by -lat, then about up by lon: with
// the default 360 x 180, +right is at 3/4 of the width and up along the top row. The aspect
// ratio plays no part (a square image stretches longitude). Every pixel has a ray.
class SphericalProjection final : public Projection {
 public:
  SphericalProjection(const CameraFrame& frame, const Camera& camera, int width, int height)
      : Projection(frame, camera, width, height),
        lonPerPixel_(radians(camera.hAngle) / width),
        latPerPixel_(radians(camera.vAngle) / height) {}

  bool generateRay(const Vec2& film, const Vec2&, Ray& ray) const override {
    const double lon = (film.x - 0.5 * width_) * lonPerPixel_;
    const double lat = (0.5 * height_ - film.y) * latPerPixel_;
    const double c = std::cos(lat);
    const Vec3 local(c * std::sin(lon), std::sin(lat), c * std::cos(lon));
    ray = primaryRay(frame_.origin, glm::normalize(frame_.toWorld(local)));
    return true;
  }

 private:
  double lonPerPixel_, latPerPixel_;  // radians
};

}  // namespace

namespace {

// The one table from camera type to ray generator (style: no self-registration).
std::unique_ptr<Projection> projectionOfType(const Camera& camera, int width, int height) {
  CameraFrame frame = makeCameraFrame(camera);
  switch (camera.type) {
    case CameraType::Pinhole:
      return std::make_unique<PinholeProjection>(frame, camera, width, height);
    case CameraType::ThinLens:
      return std::make_unique<ThinLensProjection>(frame, camera, width, height);
    case CameraType::Orthographic:
      return std::make_unique<OrthographicProjection>(frame, camera, width, height);
    case CameraType::Fisheye:
      return std::make_unique<FisheyeProjection>(frame, camera, width, height);
    case CameraType::Panini:
      return std::make_unique<PaniniProjection>(frame, camera, width, height);
    case CameraType::Lenslet:
      return std::make_unique<LensletProjection>(frame, camera, width, height);
    case CameraType::Octahedral:
      return std::make_unique<OctahedralProjection>(frame, camera, width, height);
    case CameraType::Cubemap:
      return std::make_unique<CubemapProjection>(frame, camera, width, height);
    case CameraType::Fibonacci:
      return std::make_unique<FibonacciProjection>(frame, camera, width, height);
    case CameraType::Spherical:
      return std::make_unique<SphericalProjection>(frame, camera, width, height);
    case CameraType::UltraWideAngle:
      return std::make_unique<UltraWideAngleProjection>(frame, camera, width, height);
    case CameraType::Cylinder:
      return std::make_unique<CylinderProjection>(frame, camera, width, height);
    case CameraType::Panoramic:
      return std::make_unique<PanoramicProjection>(frame, camera, width, height);
    case CameraType::Omnimax:
      return std::make_unique<OmnimaxProjection>(frame, camera, width, height);
    case CameraType::Mesh:
      return std::make_unique<MeshCameraProjection>(frame, camera, width, height);
  }
  throw std::logic_error(fmt::format("{}: camera type {} has no projection", camera.loc.str(),
                                     static_cast<int>(camera.type)));
}

}  // namespace

std::unique_ptr<Projection> makeProjection(const Camera& camera, int width, int height) {
  if (width <= 0 || height <= 0)
    throw std::invalid_argument(fmt::format("image size {}x{} is empty", width, height));
  std::unique_ptr<Projection> projection = projectionOfType(camera, width, height);
  // POV-Ray's order: the ray is moved on the lens, then bent by the camera's normal.
  if (camera.focalBlur) projection = throughFocalBlurLens(std::move(projection), camera);
  if (camera.normal) return bentByCameraNormal(std::move(projection), camera, width, height);
  return projection;
}

}  // namespace lucent
