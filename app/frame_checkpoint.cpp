#include "frame_checkpoint.h"

#include <utility>

namespace lucent {

FrameCheckpoint::FrameCheckpoint(CheckpointWriter& writer, int frame, IdentityOf identity,
                                 double interval)
    : writer_(writer), frame_(frame), identity_(std::move(identity)), interval_(interval) {}

void FrameCheckpoint::begin() {
  if (begun_) return;
  writer_.beginFrame(frame_, identity_());
  begun_ = true;
}

void FrameCheckpoint::save(const RenderJob& job) {
  begin();
  for (size_t i : unsaved_) writer_.addTile(frame_, job.tiles()[i], job.tilePixels(i));
  unsaved_.clear();
  writer_.save();
  lastSave_ = std::chrono::steady_clock::now();
}

void FrameCheckpoint::tileFinished(const RenderJob& job, size_t index, const RenderResult&) {
  unsaved_.push_back(index);
  const double since =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - lastSave_).count();
  if (since >= interval_) save(job);
}

void FrameCheckpoint::jobEnded(const RenderJob& job, const TileRenderResult& result) {
  if (result.cancelled) save(job);
}

void FrameCheckpoint::imageWritten() {
  unsaved_.clear();
  begin();
  writer_.frameWritten(frame_);
  writer_.save();
}

}  // namespace lucent
