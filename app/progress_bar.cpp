#include "progress_bar.h"

#include <fmt/core.h>

#include <chrono>
#include <cmath>

namespace lucent {

std::string formatDuration(double seconds) {
  long s = std::lround(std::max(0.0, seconds));
  if (s >= 3600) return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
  return fmt::format("{}:{:02}", s / 60, s % 60);
}

std::string progressLine(double fraction, double raysPerSecond, double seconds,
                         const std::optional<SequencePosition>& sequence) {
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(fraction * kWidth);
  const std::string bar = std::string(filled, '#') + std::string(kWidth - filled, '.');
  const std::string eta =
      fraction > 0.0 ? formatDuration(seconds * (1.0 - fraction) / fraction) : "?";
  const std::string line = fmt::format("[{}] {:3.0f}%  {:.2f} Mrays/s  ETA {}", bar,
                                       100.0 * fraction, raysPerSecond * 1e-6, eta);
  if (!sequence) return "rendering " + line;
  // The run's frames so far, this one counted by its fraction, give the time a frame takes.
  const double framesDone = (sequence->index - 1) + fraction;
  const double framesLeft = sequence->count - framesDone;
  const double elapsed = sequence->secondsBefore + seconds;
  const std::string all =
      framesDone > 0.0 ? formatDuration(elapsed / framesDone * framesLeft) : "?";
  return fmt::format("frame {}/{} {}, all {}", sequence->frame, sequence->frames, line, all);
}

ProgressBar::ProgressBar(const RenderProgress& progress, std::FILE* out,
                         std::optional<SequencePosition> sequence)
    : progress_(progress), out_(out), sequence_(sequence), thread_([this] { run(); }) {}

ProgressBar::~ProgressBar() { stop(); }

void ProgressBar::stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) {
    thread_.join();
    std::fputs("\r\033[K", out_);  // erase the line
    std::fflush(out_);
  }
}

void ProgressBar::run() {
  const auto start = std::chrono::steady_clock::now();
  std::unique_lock<std::mutex> lock(mutex_);
  // A frame of a sequence says at once which frame it is, however soon it ends.
  if (sequence_) draw(0.0);
  while (!wake_.wait_for(lock, std::chrono::milliseconds(250), [this] { return stopping_; })) {
    draw(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
}

void ProgressBar::draw(double seconds) {
  const uint64_t done = progress_.workDone.load(std::memory_order_relaxed);
  const uint64_t total = std::max<uint64_t>(1, progress_.workTotal.load(std::memory_order_relaxed));
  const double fraction = std::min(1.0, static_cast<double>(done) / total);
  const double raysPerSecond = seconds > 0.0 ? progress_.rays.load() / seconds : 0.0;
  fmt::print(out_, "\r\033[K{}", progressLine(fraction, raysPerSecond, seconds, sequence_));
  std::fflush(out_);
}

}  // namespace lucent
