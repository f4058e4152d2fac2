// The files a preview watches: the scene and every file it read (its includes, meshes,
// textures, fonts, height maps: what the parser lists), grouped by folder, because the
// folders are what is watched (an editor that writes a temporary file and renames it over
// the original replaces the file, and a watch on the old file would see nothing more).
#pragma once

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace lucent::preview {

class WatchList {
 public:
  // Adds a file, by its absolute, normalised path (it need not exist).
  void add(const std::filesystem::path& file);
  void add(const std::vector<std::filesystem::path>& files);
  // Every file of `other` too.
  void merge(const WatchList& other);

  // Folder -> the names of the watched files in it.
  const std::map<std::string, std::set<std::string>>& folders() const { return folders_; }
  // Whether a change to `name` in `folder` concerns the scene.
  bool watches(const std::string& folder, const std::string& name) const;
  size_t files() const;

  bool operator==(const WatchList& other) const { return folders_ == other.folders_; }
  bool operator!=(const WatchList& other) const { return !(*this == other); }

 private:
  std::map<std::string, std::set<std::string>> folders_;
};

}  // namespace lucent::preview
