#include "projection.h"

#include "pinhole.h"

#include <fmt/core.h>

namespace lucent {

std::unique_ptr<Projection> makeProjection(const Camera& camera, int width, int height) {
  if (width <= 0 || height <= 0)
    throw std::invalid_argument(fmt::format("image size {}x{} is empty", width, height));
  CameraFrame frame = makeCameraFrame(camera);
  switch (camera.type) {
    case CameraType::Pinhole:
      return std::make_unique<PinholeProjection>(frame, camera, width, height);
    case CameraType::ThinLens:
    case CameraType::Orthographic:
    case CameraType::Fisheye:
    case CameraType::Panini:
    case CameraType::Lenslet:
    case CameraType::Octahedral:
    case CameraType::Cubemap:
    case CameraType::Fibonacci:
      break;
  }
  throw std::runtime_error(fmt::format("{}: error: camera type '{}' is not implemented yet",
                                       camera.loc.str(), cameraTypeName(camera.type)));
}

}  // namespace lucent
