// One render of a loaded scene for the preview page: the coarse passes (coarse_passes.h),
// each sent whole as a small image the page scales up, then the full image tile by tile,
// each tile sent as it is finished, then the whole image; or, with a region, the region's
// tiles alone. The status goes with each step.
// The cancel flag (a save, Ctrl-C) stops it within a row.
#pragma once

#include "preview_board.h"
#include "preview_status.h"

#include "load_scene.h"

#include "render/image.h"
#include "render/pixel_rect.h"
#include "render/ray_stats.h"

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>

namespace lucent::preview {

struct PreviewRun {
  PreviewBoard& board;
  PreviewStatus& status;  // updated and published as the render goes
  const std::atomic<bool>& cancel;
  int threads = 0;                              // 0: every core
  std::chrono::steady_clock::time_point start;  // the save's time
  // A region dragged in the page: only its tiles are rendered (no coarse pass), over
  // `previous` (the last finished image, when it has this size; else black).
  std::optional<PixelRect> region;
  std::shared_ptr<const Image> previous;
  // The scene's (set by renderForPage): the pictures sent are its values decoded to light.
  WorkingGamma gamma;
};

struct PreviewOutcome {
  bool cancelled = false;
  Image image;  // the full image, when not cancelled
  RayStats stats;
  double seconds = 0.0;  // of the full pass
};

PreviewOutcome renderForPage(const cli::LoadedScene& loaded, PreviewRun& run);

}  // namespace lucent::preview
