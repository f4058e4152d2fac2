#include "interrupt_catcher.h"

namespace lucent::cli {

namespace {

std::atomic<bool> gInterrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

extern "C" void onInterrupt(int signal) {
  gInterrupted.store(true, std::memory_order_relaxed);
  std::signal(signal, SIG_DFL);  // the second one ends the process
}

}  // namespace

InterruptCatcher::InterruptCatcher() {
  gInterrupted.store(false);
  struct sigaction sa {};
  sa.sa_handler = onInterrupt;
  sigemptyset(&sa.sa_mask);
  for (int i = 0; i < 2; ++i) installed_[i] = sigaction(kSignals[i], &sa, &previous_[i]) == 0;
}

InterruptCatcher::~InterruptCatcher() {
  for (int i = 0; i < 2; ++i)
    if (installed_[i]) sigaction(kSignals[i], &previous_[i], nullptr);
}

const std::atomic<bool>& InterruptCatcher::flag() { return gInterrupted; }

}  // namespace lucent::cli
