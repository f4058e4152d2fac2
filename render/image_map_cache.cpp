#include "image_map_cache.h"

namespace lucent {

std::shared_ptr<const ImageMap> ImageMapCache::get(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const std::string key = fs::weakly_canonical(path, ec).string();
  const auto modified = fs::last_write_time(key, ec);
  const std::uintmax_t size = ec ? 0 : fs::file_size(key, ec);
  if (auto it = entries_.find(key); it != entries_.end()) {
    if (!ec && it->second.modified == modified && it->second.size == size) return it->second.map;
    entries_.erase(it);
  }
  // ImageMap reports a missing or unreadable file (naming `path` as the scene resolved it).
  auto map = std::make_shared<const ImageMap>(path);
  ++loads_;
  if (!ec) entries_.emplace(key, Entry{map, modified, size});
  return map;
}

}  // namespace lucent
