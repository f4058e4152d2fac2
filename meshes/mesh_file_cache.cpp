#include "mesh_file_cache.h"

#include "mesh_files.h"

namespace lucent {

std::shared_ptr<const MeshData> MeshFileCache::get(const std::string& canonicalPath, bool* firstRead) {
  if (firstRead) *firstRead = false;
  // Errors here (a file gone since it was resolved) leave the stamps empty: loadMeshFile
  // below reports the real problem.
  std::error_code ec;
  const auto modified = std::filesystem::last_write_time(canonicalPath, ec);
  const std::uintmax_t size = ec ? 0 : std::filesystem::file_size(canonicalPath, ec);
  if (auto it = entries_.find(canonicalPath); it != entries_.end()) {
    if (!ec && it->second.modified == modified && it->second.size == size) return it->second.data;
    entries_.erase(it);
  }
  std::shared_ptr<const MeshData> data = loadMeshFile(canonicalPath);
  ++reads_;
  if (firstRead) *firstRead = true;
  if (!ec) entries_.emplace(canonicalPath, Entry{data, modified, size});
  return data;
}

}  // namespace lucent
