// Image textures loaded once and shared by the renderers built from it, as those of the
// frames of an animation: without one, each renderer loads the images its scene names.
// A file whose size or modification time changed since it was loaded is loaded again.
// One thread at a time (renderers are built one after another).
#pragma once

#include "texture.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <unordered_map>

namespace lucent {

class ImageMapCache {
 public:
  // The image at `path`, keyed by its canonical path. Throws what ImageMap throws.
  std::shared_ptr<const ImageMap> get(const std::string& path);

  // Files loaded so far (each reload counts): what the tests observe.
  uint64_t loads() const { return loads_; }

 private:
  struct Entry {
    std::shared_ptr<const ImageMap> map;
    std::filesystem::file_time_type modified;
    std::uintmax_t size = 0;
  };
  std::unordered_map<std::string, Entry> entries_;
  uint64_t loads_ = 0;
};

}  // namespace lucent
