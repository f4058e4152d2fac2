// Watches the folders of a WatchList with inotify and says when one of its files changed
// (written, replaced by a rename, created or removed). Folders, not files: an editor that
// saves by writing a temporary file and renaming it over the original replaces the file.
#pragma once

#include "watch_list.h"

#include <chrono>
#include <map>
#include <mutex>
#include <string>

namespace lucent::preview {

class FileWatcher {
 public:
  // Throws std::runtime_error when inotify cannot be used.
  FileWatcher();
  ~FileWatcher();
  FileWatcher(const FileWatcher&) = delete;
  FileWatcher& operator=(const FileWatcher&) = delete;

  // Watches exactly the folders of `list` from now on (may be called from another thread
  // than wait's). A folder that cannot be watched (gone) is left out.
  void watch(const WatchList& list);

  // Waits up to `timeout` for events; true if any of them concerns a watched file.
  bool wait(std::chrono::milliseconds timeout);

 private:
  int fd_ = -1;
  std::mutex mutex_;
  WatchList list_;
  std::map<int, std::string> folders_;  // watch descriptor -> folder
};

}  // namespace lucent::preview
