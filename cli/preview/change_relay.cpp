#include "change_relay.h"

#include "interrupt_catcher.h"

namespace lucent::preview {

namespace {

// How often Ctrl-C's flag is looked at when no file event comes.
constexpr std::chrono::milliseconds kPoll{10};

}  // namespace

ChangeRelay::ChangeRelay(FileWatcher& watcher, std::atomic<bool>& cancel)
    : watcher_(watcher), cancel_(cancel), thread_([this] { run(); }) {}

ChangeRelay::~ChangeRelay() {
  quit_ = true;
  thread_.join();
}

void ChangeRelay::renderStarts() {
  std::lock_guard lock(mutex_);
  changed_ = false;
  cancel_ = interrupted_;
}

bool ChangeRelay::waitForChange() {
  std::unique_lock lock(mutex_);
  wake_.wait(lock, [this] { return changed_ || interrupted_; });
  return !interrupted_;
}

void ChangeRelay::poke() {
  {
    std::lock_guard lock(mutex_);
    changed_ = true;
    cancel_ = true;
  }
  wake_.notify_all();
}

void ChangeRelay::run() {
  Debouncer debouncer(kQuiet);
  while (!quit_) {
    const bool changed = watcher_.wait(kPoll);
    const auto now = Debouncer::Clock::now();
    if (changed) {
      debouncer.event(now);
      cancel_ = true;
    }
    const bool due = debouncer.due(now);
    const bool interrupted = cli::InterruptCatcher::interrupted();
    if (interrupted) cancel_ = true;
    if (!due && !interrupted) continue;
    {
      std::lock_guard lock(mutex_);
      changed_ = changed_ || due;
      interrupted_ = interrupted_ || interrupted;
    }
    wake_.notify_all();
  }
}

}  // namespace lucent::preview
