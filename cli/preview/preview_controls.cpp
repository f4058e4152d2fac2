#include "preview_controls.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

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
  if (name == "samples") {
    if (number != std::floor(number) || number < 1 || number > kMaxPreviewSamples)
      return fmt::format("samples {}: 1 to {}", value, kMaxPreviewSamples);
  } else if (name == "frame") {
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

std::string PreviewControls::setRegion(const std::string& text) {
  std::optional<PixelRect> region;
  if (!text.empty()) {
    PixelRect r;
    char c1 = 0, c2 = 0, c3 = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c%d%c%d%c", &r.x0, &c1, &r.y0, &c2, &r.x1, &c3, &r.y1,
                    &extra) != 7 ||
        c1 != ',' || c2 != ',' || c3 != ',' || r.x0 < 0 || r.y0 < 0 || r.x1 <= r.x0 || r.y1 <= r.y0)
      return fmt::format("region '{}': expected X0,Y0,X1,Y1 with 0 <= X0 < X1 and 0 <= Y0 < Y1",
                         text);
    region = r;
  }
  std::lock_guard lock(mutex_);
  region_ = region;
  return "";
}

std::optional<PixelRect> PreviewControls::region() const {
  std::lock_guard lock(mutex_);
  return region_;
}

std::map<std::string, std::string> PreviewControls::values() const {
  std::lock_guard lock(mutex_);
  return values_;
}

}  // namespace lucent::preview
