#include "image_map_cache.h"

#include <filesystem>

namespace lucent {

std::shared_ptr<const ImageMap> ImageMapCache::get(const std::string& path,
                                                   PixelDecoding decoding) {
  std::error_code ec;
  const std::string key = std::filesystem::weakly_canonical(path, ec).string();
  // ImageMap reports a missing or unreadable file (naming `path` as the scene resolved it).
  auto& files = decoding == PixelDecoding::Linear     ? files_
                : decoding == PixelDecoding::AsStored ? storedFiles_
                                                      : straightFiles_;
  return files.get(key, [&] { return std::make_shared<const ImageMap>(path, decoding); });
}

}  // namespace lucent
