// What the page's sliders set: the value of a numeric parameter (as `-D name=value`) and the
// frame of an animation (as `-D frame=F`). A change re-renders as a save does. Set by the
// server's threads, read by the render loop.
#pragma once

#include "scene_parameters.h"

#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace lucent::preview {

class PreviewControls {
 public:
  // What the page may set, from the render that starts: the scene's parameters, and its
  // frames (0: not an animation, or the moment is fixed by -D).
  void offer(std::vector<SceneParameter> parameters, int frames);
  // Sets `name` ("frame" or a parameter offered) to `value`: "" or why not.
  std::string set(const std::string& name, const std::string& value);
  // The -D values the page set, to apply over the command line's.
  std::map<std::string, std::string> values() const;

 private:
  mutable std::mutex mutex_;
  std::vector<SceneParameter> parameters_;
  int frames_ = 0;
  std::map<std::string, std::string> values_;
};

}  // namespace lucent::preview
