// One frame's part of a render's checkpoint (checkpoint.h), kept as its job renders: the
// finished tiles are appended at most every `interval` seconds, and once more when the
// render is cancelled, so that `--resume` goes on from them; once the frame's image is
// written, that is recorded instead (an animation's later frames go on).
#pragma once

#include "checkpoint.h"
#include "render_job.h"

#include <chrono>
#include <functional>
#include <vector>

namespace lucent {

class FrameCheckpoint : public RenderObserver {
 public:
  // The frame's identity, made when first needed: it may read every file of the scene again.
  using IdentityOf = std::function<const Identity&()>;

  FrameCheckpoint(CheckpointWriter& writer, int frame, IdentityOf identity, double interval);

  // The checkpoint holds this frame's start already (the frame is resumed).
  void resumed() { begun_ = true; }

  void tileFinished(const RenderJob& job, size_t index, const RenderResult& tile) override;
  // A cancelled render saves the tiles finished so far.
  void jobEnded(const RenderJob& job, const TileRenderResult& result) override;

  // The frame's image is written: recorded, its tiles no longer kept.
  void imageWritten();

 private:
  // Appends the frame's start (the first time) and the tiles not yet saved, and flushes.
  void save(const RenderJob& job);
  void begin();

  CheckpointWriter& writer_;
  const int frame_;
  const IdentityOf identity_;
  const double interval_;
  bool begun_ = false;           // the checkpoint has this frame's start record
  std::vector<size_t> unsaved_;  // finished tiles not yet in the checkpoint
  std::chrono::steady_clock::time_point lastSave_ = std::chrono::steady_clock::now();
};

}  // namespace lucent
