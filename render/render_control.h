// What the caller of a render hands it besides the scene: how many threads, a flag that
// cancels it, and counters it fills for a progress display.
#pragma once

#include <atomic>
#include <cstdint>

namespace lucent {

// Live counters another thread may read while rendering (the progress bar).
struct RenderProgress {
  std::atomic<uint64_t> workDone{0};   // pixel passes finished
  std::atomic<uint64_t> workTotal{0};  // pixel passes planned (2 per pixel when adaptive)
  std::atomic<uint64_t> rays{0};
};

struct RenderControl {
  int threads = 0;  // 0: every core
  // Polled before every row of every tile: once true, rendering stops within a row.
  const std::atomic<bool>* cancel = nullptr;
  RenderProgress* progress = nullptr;
};

}  // namespace lucent
