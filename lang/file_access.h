// The contract's file access rule: a scene reads files (includes, meshes, images) only
// inside the folder of the scene named on the command line and its sub-folders, plus the
// folders given with --allow-path. Paths are resolved through symbolic links and `..`
// before the check, so neither can leave the allowed folders.
#pragma once

#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

namespace lucent {

class FileAccess {
 public:
  FileAccess(const std::filesystem::path& sceneFolder, const std::vector<std::string>& allowPaths);

  struct Resolved {
    std::filesystem::path path;  // canonical (symbolic links and `..` resolved); empty on error
    std::string error;           // names the path as written and where it leads
  };
  // `written` is absolute or relative to `baseFolder` (the folder of the file that names it).
  // The file must exist and be a regular file.
  Resolved resolve(const std::string& written, const std::filesystem::path& baseFolder) const;

  const std::vector<std::filesystem::path>& roots() const { return roots_; }

  // Every path resolve() has granted, each once, in the order first granted: the files the
  // scene reads (a checkpoint's digest covers them; a distributed render sends them).
  std::vector<std::filesystem::path> granted() const;

 private:
  bool allowed(const std::filesystem::path& canonical) const;
  std::vector<std::filesystem::path> roots_;
  mutable std::mutex grantedMutex_;  // shapes may be read on several threads
  mutable std::vector<std::filesystem::path> granted_;
};

// The canonical form of an existing or not-yet-existing path (weakly_canonical of the
// absolute path, without a trailing separator); never throws.
std::filesystem::path canonicalPath(const std::filesystem::path& p);

}  // namespace lucent
