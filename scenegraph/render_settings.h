// Image and tracing settings of the contract's <render>.
#pragma once

#include "gamma_curve.h"
#include "source_loc.h"

#include "primitives/math.h"

#include <optional>

namespace lucent {

// How `adaptive` refines (docs/scene-language.md, <render>): Centres compares pixel centres
// and adds Halton samples; Corners is POV-Ray's antialiasing method 2 (+AM2): pixel corners
// shared by neighbouring pixels, squares split where their corners differ.
enum class AdaptiveMode { Centres, Corners };

// POV-Ray's +R range (it clips Antialias_Depth to 1..9): corners mode splits a pixel at most
// adaptiveDepth - 1 times, into a grid of 2^(depth-1) + 1 samples a side.
constexpr int kMaxAdaptiveDepth = 9;

// POV-Ray's assumed_gamma (<render working-gamma>): the scene's colour numbers, and so the
// values the renderer computes, are light encoded with this curve. The output image holds
// them decoded to linear light (what POV-Ray writes), and an image texture's linear texels
// are encoded with it to meet the colours they mix with (render/working_gamma.h).
// sRGB's curve for assumed_gamma srgb and POV-Ray's gamma-off scenes.
using WorkingGamma = GammaCurve;

struct RenderSettings {
  SourceLoc loc;
  int width = 640;
  int height = 480;
  int samples = 1;
  double adaptive = 0.0;
  AdaptiveMode adaptiveMode = AdaptiveMode::Centres;
  int adaptiveDepth = 3;  // corners mode only; POV-Ray's +R
  int maxDepth = 5;
  double minWeight = 0.0039;
  Color background{0.0f};
  Color ambient{1.0f};
  std::optional<double> epsilon;  // none: the renderer's robust automatic offset
  WorkingGamma workingGamma;      // linear: the colours are linear light (Lucent's own)
};

}  // namespace lucent
