// The page's status line and panels, sent as the "status" event: which render, how far it
// is, how long it has taken, the figures of `render --stats`, and the scene's messages.
#pragma once

#include "scene_parameters.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lucent::preview {

struct PreviewStatus {
  std::string scene;
  int generation = 0;  // the render's number: 1, then one more per save
  // "loading", "coarse" (a coarse pass), "tiles", "done", "cancelled" or "invalid" (the
  // scene did not load: `messages` says why, the page keeps the last image, dimmed).
  std::string phase;
  int step = 0;  // the coarse pass's step
  int width = 0, height = 0;
  uint64_t done = 0, total = 0;  // tiles of the full pass
  double seconds = 0.0;          // since the save that started it
  std::string stats;             // the figures of the last finished render
  std::string messages;          // errors and warnings, as `lucent check` prints them
  // The sliders: the scene's numeric parameters with the values rendered, and its frames
  // (0: none to choose) with the frame rendered.
  std::vector<SceneParameter> parameters;
  std::vector<std::string> values;  // one per parameter
  int frames = 0, frame = 1;
  int samples = 1;     // per pixel, as rendered
  std::string region;  // "x0,y0,x1,y1" of the region rendered, or "" for the whole image

  std::string json() const;
};

}  // namespace lucent::preview
