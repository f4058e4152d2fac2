// Saves that arrive as several file events (an editor writes a temporary file, renames it
// over the scene, touches a backup) give one render: the render starts once no event has
// come for a quiet interval after the last one.
#pragma once

#include <chrono>

namespace lucent::preview {

class Debouncer {
 public:
  using Clock = std::chrono::steady_clock;
  explicit Debouncer(Clock::duration quiet) : quiet_(quiet) {}

  // An event at `now`: the burst goes on until `quiet` after it.
  void event(Clock::time_point now) {
    deadline_ = now + quiet_;
    pending_ = true;
  }
  // Whether a burst is under way (an event came, and `due` has not yet said so).
  bool pending() const { return pending_; }
  // When the burst under way ends.
  Clock::time_point deadline() const { return deadline_; }
  // True once, at or after the end of a burst; the burst is then over.
  bool due(Clock::time_point now) {
    if (!pending_ || now < deadline_) return false;
    pending_ = false;
    return true;
  }

 private:
  // (A flag beside the time, not an optional: GCC 12 warns of the optional's time as
  // maybe uninitialised.)
  const Clock::duration quiet_;
  bool pending_ = false;
  Clock::time_point deadline_{};
};

}  // namespace lucent::preview
