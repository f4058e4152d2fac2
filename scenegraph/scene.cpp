#include "scene.h"

namespace lucent {

const Camera* Scene::findCamera(const std::string& name) const {
  if (name.empty()) return cameras.empty() ? nullptr : &cameras.front();
  for (const Camera& c : cameras)
    if (c.name == name) return &c;
  return nullptr;
}

const char* cameraTypeName(CameraType t) {
  switch (t) {
    case CameraType::Pinhole: return "pinhole";
    case CameraType::ThinLens: return "thin-lens";
    case CameraType::Orthographic: return "orthographic";
    case CameraType::Fisheye: return "fisheye";
    case CameraType::Panini: return "panini";
    case CameraType::Lenslet: return "lenslet";
    case CameraType::Octahedral: return "octahedral";
    case CameraType::Cubemap: return "cubemap";
    case CameraType::Fibonacci: return "fibonacci";
  }
  return "?";
}

}  // namespace lucent
