#include "image_map_cache.h"

#include "working_gamma.h"

#include <filesystem>
#include <string>

namespace lucent {

std::shared_ptr<const ImageMap> ImageMapCache::get(const std::string& path, PixelDecoding decoding,
                                                   const std::optional<GammaCurve>& fileGamma) {
  std::error_code ec;
  const std::string key = std::filesystem::weakly_canonical(path, ec).string();
  // ImageMap reports a missing or unreadable file (naming `path` as the scene resolved it).
  if (fileGamma && decoding != PixelDecoding::AsStored) {
    // One cache per decoding and curve: the key is the path the cache stamps.
    auto& files =
        curveFiles_[std::to_string(static_cast<int>(decoding)) + " " + curveText(*fileGamma)];
    return files.get(key,
                     [&] { return std::make_shared<const ImageMap>(path, decoding, fileGamma); });
  }
  auto& files = decoding == PixelDecoding::Linear     ? files_
                : decoding == PixelDecoding::AsStored ? storedFiles_
                                                      : straightFiles_;
  return files.get(key, [&] { return std::make_shared<const ImageMap>(path, decoding); });
}

}  // namespace lucent
