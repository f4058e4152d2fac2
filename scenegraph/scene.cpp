#include "scene.h"

namespace lucent {

double Animation::clockOf(int frame) const {
  if (frames <= 1) return clockFrom;
  double steps = cyclic ? frames : frames - 1;
  return clockFrom + (clockTo - clockFrom) * (frame - 1) / steps;
}

const Camera* Scene::findCamera(const std::string& name) const {
  if (name.empty()) return cameras.empty() ? nullptr : &cameras.front();
  for (const Camera& c : cameras)
    if (c.name == name) return &c;
  return nullptr;
}

const char* cameraTypeName(CameraType t) {
  switch (t) {
    case CameraType::Pinhole:
      return "pinhole";
    case CameraType::ThinLens:
      return "thin-lens";
    case CameraType::Orthographic:
      return "orthographic";
    case CameraType::Fisheye:
      return "fisheye";
    case CameraType::Panini:
      return "panini";
    case CameraType::Lenslet:
      return "lenslet";
    case CameraType::Octahedral:
      return "octahedral";
    case CameraType::Cubemap:
      return "cubemap";
    case CameraType::Fibonacci:
      return "fibonacci";
  }
  return "?";
}

}  // namespace lucent
