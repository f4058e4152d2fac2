#include "preview_controls.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace lucent::preview {

void PreviewControls::offer(std::vector<SceneParameter> parameters, int frames) {
  std::lock_guard lock(mutex_);
  parameters_ = std::move(parameters);
  frames_ = frames;
}

std::string PreviewControls::set(const std::string& name, const std::string& value) {
  double number = 0.0;
  if (!readNumber(value, number)) return fmt::format("'{}' is not a number", value);
  std::lock_guard lock(mutex_);
  if (name == "frame") {
    if (frames_ == 0) return "the scene is not an animation (or -D picks its moment)";
    if (number != std::floor(number) || number < 1 || number > frames_)
      return fmt::format("frame {}: the scene has frames 1 to {}", value, frames_);
  } else if (std::none_of(parameters_.begin(), parameters_.end(),
                          [&](const SceneParameter& p) { return p.name == name; })) {
    return fmt::format("'{}' is not a numeric parameter of the scene", name);
  }
  values_[name] = value;
  return "";
}

std::map<std::string, std::string> PreviewControls::values() const {
  std::lock_guard lock(mutex_);
  return values_;
}

}  // namespace lucent::preview
