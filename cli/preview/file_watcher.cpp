#include "file_watcher.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

namespace lucent::preview {

namespace {

// Every way a file in a folder can come to differ: written (modified, or closed after
// writing), renamed into or out of place, created, removed.
constexpr uint32_t kEvents =
    IN_MODIFY | IN_CLOSE_WRITE | IN_MOVED_TO | IN_MOVED_FROM | IN_CREATE | IN_DELETE;

}  // namespace

FileWatcher::FileWatcher() : fd_(::inotify_init1(IN_NONBLOCK | IN_CLOEXEC)) {
  if (fd_ < 0)
    throw std::runtime_error(std::string("cannot watch the scene's files (inotify: ") +
                             std::strerror(errno) + ")");
}

FileWatcher::~FileWatcher() { ::close(fd_); }

void FileWatcher::watch(const WatchList& list) {
  std::lock_guard lock(mutex_);
  for (auto it = folders_.begin(); it != folders_.end();) {
    if (list.folders().count(it->second) == 0) {
      ::inotify_rm_watch(fd_, it->first);
      it = folders_.erase(it);
    } else {
      ++it;
    }
  }
  for (const auto& entry : list.folders()) {
    // Adding a folder watched already returns its descriptor again.
    const int wd = ::inotify_add_watch(fd_, entry.first.c_str(), kEvents);
    if (wd >= 0) folders_[wd] = entry.first;
  }
  list_ = list;
}

bool FileWatcher::wait(std::chrono::milliseconds timeout) {
  pollfd p{fd_, POLLIN, 0};
  if (::poll(&p, 1, static_cast<int>(timeout.count())) <= 0) return false;
  alignas(inotify_event) char buffer[16384];
  bool relevant = false;
  for (;;) {
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n <= 0) break;
    std::lock_guard lock(mutex_);
    for (ssize_t at = 0; at < n;) {
      const auto* e = reinterpret_cast<const inotify_event*>(buffer + at);
      at += static_cast<ssize_t>(sizeof(inotify_event) + e->len);
      // The event queue overflowed: something may have changed.
      if (e->mask & IN_Q_OVERFLOW) relevant = true;
      const auto folder = folders_.find(e->wd);
      if (folder != folders_.end() && e->len > 0 && list_.watches(folder->second, e->name))
        relevant = true;
    }
  }
  return relevant;
}

}  // namespace lucent::preview
