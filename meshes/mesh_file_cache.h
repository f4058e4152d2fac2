// Mesh files read once and shared: by every element of one scene that names the file, and,
// when the caller keeps the cache (ParseOptions::meshCache), by every scene it parses, as
// the frames of an animation. A file whose size or modification time changed since it was
// read is read again (memory/file_cache.h).
#pragma once

#include "primitives/mesh_data.h"

#include "memory/file_cache.h"

#include <cstdint>
#include <memory>
#include <string>

namespace lucent {

class MeshFileCache {
 public:
  // The mesh in the file at `canonicalPath` (a key: callers resolve the path first).
  // `firstRead` tells whether this call read the file. Throws what loadMeshFile throws.
  std::shared_ptr<const MeshData> get(const std::string& canonicalPath, bool* firstRead = nullptr);

  // Files read so far (each re-read counts): what the tests observe.
  uint64_t reads() const { return files_.loads(); }

 private:
  FileCache<MeshData> files_;
};

}  // namespace lucent
