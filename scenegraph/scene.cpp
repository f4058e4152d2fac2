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

}  // namespace lucent
