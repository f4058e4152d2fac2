#include "watch_list.h"

namespace lucent::preview {

namespace fs = std::filesystem;

void WatchList::add(const fs::path& file) {
  const fs::path full = fs::absolute(file).lexically_normal();
  folders_[full.parent_path().string()].insert(full.filename().string());
}

void WatchList::add(const std::vector<fs::path>& files) {
  for (const fs::path& f : files) add(f);
}

void WatchList::merge(const WatchList& other) {
  for (const auto& [folder, names] : other.folders_)
    folders_[folder].insert(names.begin(), names.end());
}

bool WatchList::watches(const std::string& folder, const std::string& name) const {
  const auto it = folders_.find(folder);
  return it != folders_.end() && it->second.count(name) > 0;
}

size_t WatchList::files() const {
  size_t n = 0;
  for (const auto& entry : folders_) n += entry.second.size();
  return n;
}

}  // namespace lucent::preview
