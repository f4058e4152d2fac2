// What the page's sliders set: the value of a numeric parameter (as `-D name=value`), the
// frame of an animation (as `-D frame=F`) and the samples per pixel (as -s). A change re-renders as
// a save does. Set by the server's threads, read by the render loop.
#pragma once

#include "scene_parameters.h"

#include "render/pixel_rect.h"

#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace lucent::preview {

// The samples slider's end (-s on the command line may be more).
constexpr int kMaxPreviewSamples = 64;

class PreviewControls {
 public:
  // What the page may set, from the render that starts: the scene's parameters, and its
  // frames (0: not an animation, or the moment is fixed by -D).
  void offer(std::vector<SceneParameter> parameters, int frames);
  // Sets `name` ("samples", "frame" or a parameter offered) to `value`: "" or why not.
  std::string set(const std::string& name, const std::string& value);
  // The -D values the page set, to apply over the command line's.
  std::map<std::string, std::string> values() const;

  // The region dragged ("x0,y0,x1,y1" in pixels, bounds excluded, as --region) or "" for
  // the whole image: "" or why not.
  std::string setRegion(const std::string& text);
  std::optional<PixelRect> region() const;

 private:
  mutable std::mutex mutex_;
  std::vector<SceneParameter> parameters_;
  int frames_ = 0;
  std::map<std::string, std::string> values_;
  std::optional<PixelRect> region_;
};

}  // namespace lucent::preview
