// Image and tracing settings of the contract's <render>.
#pragma once

#include "source_loc.h"

#include "primitives/math.h"

#include <optional>

namespace lucent {

struct RenderSettings {
  SourceLoc loc;
  int width = 640;
  int height = 480;
  int samples = 1;
  double adaptive = 0.0;
  int maxDepth = 5;
  double minWeight = 0.0039;
  Color background{0.0f};
  Color ambient{1.0f};
  std::optional<double> epsilon;  // none: the renderer's robust automatic offset
};

}  // namespace lucent
