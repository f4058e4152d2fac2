#include "projection.h"

#include "cubemap.h"
#include "fibonacci.h"
#include "fisheye.h"
#include "lenslet.h"
#include "octahedral.h"
#include "orthographic.h"
#include "panini.h"
#include "pinhole.h"
#include "thin_lens.h"

#include <fmt/core.h>

namespace lucent {

// The one table from camera type to ray generator (style: no self-registration).
std::unique_ptr<Projection> makeProjection(const Camera& camera, int width, int height) {
  if (width <= 0 || height <= 0)
    throw std::invalid_argument(fmt::format("image size {}x{} is empty", width, height));
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
  }
  throw std::logic_error(fmt::format("{}: camera type {} has no projection", camera.loc.str(),
                                     static_cast<int>(camera.type)));
}

}  // namespace lucent
