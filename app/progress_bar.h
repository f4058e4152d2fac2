// A one-line progress display on a terminal: percentage, rays per second and time left.
#pragma once

#include "render/render_control.h"

#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace lucent {

// Where the frame being rendered stands among the frames of one run (an animation).
struct SequencePosition {
  int index = 1, count = 1;    // its place among the frames this run renders (1-based), how many
  int frame = 1, frames = 1;   // its number in the animation, and the animation's frames
  double secondsBefore = 0.0;  // the run's time until this frame's render began
};

// The progress line: "rendering [###...]  45%  1.23 Mrays/s  ETA 0:05", and in a sequence
// "frame 3/24 [###...]  45%  1.23 Mrays/s  ETA 0:05, all 1:12" where the second ETA is
// the whole run's (its frames so far averaged). `seconds`: this render's time so far.
std::string progressLine(double fraction, double raysPerSecond, double seconds,
                         const std::optional<SequencePosition>& sequence);

// Redraws the line a few times a second from its own thread while the renderer fills
// `progress`; stop() (or the destructor) erases the line. Only for terminals: the caller
// decides (isatty) and never starts one with --quiet.
class ProgressBar {
 public:
  ProgressBar(const RenderProgress& progress, std::FILE* out,
              std::optional<SequencePosition> sequence = std::nullopt);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void stop();

 private:
  void run();
  void draw(double seconds);

  const RenderProgress& progress_;
  std::FILE* out_;
  const std::optional<SequencePosition> sequence_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

// "1:05", "12:00:03": for the ETA and the statistics.
std::string formatDuration(double seconds);

}  // namespace lucent
