// The preview's watchman, on a thread of its own: it reads the file watcher's events, and
// Ctrl-C's flag (interrupt_catcher.h), and relays them to the render loop: the cancel flag
// the render polls is set at the first event of a save (the render in flight stops within
// a row), and a change is announced once the save's burst of events is over (debounce.h).
#pragma once

#include "debounce.h"
#include "file_watcher.h"

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace lucent::preview {

class ChangeRelay {
 public:
  // How long a save's events may keep coming: editors write, rename and touch within it.
  static constexpr std::chrono::milliseconds kQuiet{50};

  ChangeRelay(FileWatcher& watcher, std::atomic<bool>& cancel);
  ~ChangeRelay();
  ChangeRelay(const ChangeRelay&) = delete;
  ChangeRelay& operator=(const ChangeRelay&) = delete;

  // A render starts: the changes announced so far are taken, and the cancel flag cleared.
  void renderStarts();
  // Waits for a change (true) or Ctrl-C (false).
  bool waitForChange();
  // A change now (a slider of the page): the render in flight is cancelled, the next starts.
  void poke();

 private:
  void run();

  FileWatcher& watcher_;
  std::atomic<bool>& cancel_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool changed_ = false, interrupted_ = false;
  std::atomic<bool> quit_{false};
  std::thread thread_;
};

}  // namespace lucent::preview
