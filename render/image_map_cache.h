// Image textures loaded once and shared by the renderers built from it, as those of the
// frames of an animation: without one, each renderer loads the images its scene names.
// A file whose size or modification time changed since it was loaded is loaded again
// (memory/file_cache.h).
// One thread at a time (renderers are built one after another).
#pragma once

#include "texture.h"

#include "memory/file_cache.h"

#include <cstdint>
#include <map>
#include <memory>
#include <string>

namespace lucent {

class ImageMapCache {
 public:
  // The image at `path`, keyed by its canonical path, the decoding and the file's gamma (a
  // file used both as an <image> and as a <bump-map> is kept twice). Throws what ImageMap
  // throws.
  std::shared_ptr<const ImageMap> get(const std::string& path,
                                      PixelDecoding decoding = PixelDecoding::Linear,
                                      const std::optional<GammaCurve>& fileGamma = std::nullopt);

  // Files loaded so far (each reload counts): what the tests observe.
  uint64_t loads() const {
    uint64_t n = files_.loads() + storedFiles_.loads() + straightFiles_.loads();
    for (const auto& [curve, files] : curveFiles_) n += files.loads();
    return n;
  }

 private:
  FileCache<ImageMap> files_;          // decoded to linear
  FileCache<ImageMap> storedFiles_;    // as stored
  FileCache<ImageMap> straightFiles_;  // linear, the colour divided by its alpha
  std::map<std::string, FileCache<ImageMap>> curveFiles_;  // by decoding and the file's gamma
};

}  // namespace lucent
