// A one-line progress display on a terminal: percentage, rays per second and time left.
#pragma once

#include "renderer.h"

#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

namespace lucent {

// Redraws the line a few times a second from its own thread while the renderer fills
// `progress`; stop() (or the destructor) erases the line. Only for terminals: the caller
// decides (isatty) and never starts one with --quiet.
class ProgressBar {
 public:
  ProgressBar(const RenderProgress& progress, std::FILE* out);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void stop();

 private:
  void run();
  void draw(double seconds);

  const RenderProgress& progress_;
  std::FILE* out_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

// "1:05", "12:00:03": for the ETA and the statistics.
std::string formatDuration(double seconds);

}  // namespace lucent
