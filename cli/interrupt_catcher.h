// Ctrl-C (SIGINT) and SIGTERM (kill, a batch system's stop) during a render: the first sets
// a flag the renderer polls before every row of every tile, and that the frame loop checks
// between frames; a second one ends the process at once, as users expect when a stop hangs.
#pragma once

#include <atomic>
#include <csignal>

namespace lucent::cli {

// Catches SIGINT and SIGTERM while it lives (even where the shell started us with SIGINT
// ignored, as it does for background jobs); restores the previous dispositions after.
class InterruptCatcher {
 public:
  InterruptCatcher();
  ~InterruptCatcher();
  InterruptCatcher(const InterruptCatcher&) = delete;
  InterruptCatcher& operator=(const InterruptCatcher&) = delete;

  // Set once a signal came.
  static const std::atomic<bool>& flag();
  static bool interrupted() { return flag().load(std::memory_order_relaxed); }

 private:
  static constexpr int kSignals[2] = {SIGINT, SIGTERM};
  struct sigaction previous_[2]{};
  bool installed_[2] = {false, false};
};

}  // namespace lucent::cli
