#include "mesh_file_cache.h"

#include "mesh_files.h"

namespace lucent {

std::shared_ptr<const MeshData> MeshFileCache::get(const std::string& canonicalPath,
                                                   bool* firstRead) {
  return files_.get(
      canonicalPath, [&] { return loadMeshFile(canonicalPath); }, firstRead);
}

}  // namespace lucent
