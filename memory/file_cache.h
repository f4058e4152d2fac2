// Files loaded once and shared, keyed by path: a file whose size or modification time
// changed since it was loaded is loaded again. The mesh files of a parse and the image
// textures of a renderer keep one each, so that the frames of an animation share them.
// One thread at a time.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <unordered_map>

namespace lucent {

template <class T>
class FileCache {
 public:
  // The value for the file at `key` (a path the caller has made canonical), from `load()`
  // when the file is new or changed; `loaded` tells which. What load throws passes through.
  template <class Load>
  std::shared_ptr<const T> get(const std::string& key, Load&& load, bool* loaded = nullptr) {
    if (loaded) *loaded = false;
    // A file gone since it was resolved leaves the stamps empty: load() reports the problem.
    std::error_code ec;
    const auto modified = std::filesystem::last_write_time(key, ec);
    const std::uintmax_t size = ec ? 0 : std::filesystem::file_size(key, ec);
    if (auto it = entries_.find(key); it != entries_.end()) {
      if (!ec && it->second.modified == modified && it->second.size == size)
        return it->second.value;
      entries_.erase(it);
    }
    std::shared_ptr<const T> value = load();
    ++loads_;
    if (loaded) *loaded = true;
    if (!ec) entries_.emplace(key, Entry{value, modified, size});
    return value;
  }

  // Files loaded so far (each reload counts): what the tests observe.
  uint64_t loads() const { return loads_; }

 private:
  struct Entry {
    std::shared_ptr<const T> value;
    std::filesystem::file_time_type modified;
    std::uintmax_t size = 0;
  };
  std::unordered_map<std::string, Entry> entries_;
  uint64_t loads_ = 0;
};

}  // namespace lucent
