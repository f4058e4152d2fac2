// The contract's file access rule: a scene reads files (includes, meshes, images) only
// inside the folder of the scene named on the command line and its sub-folders, plus the
// folders given with --allow-path. Paths are resolved through symbolic links and `..`
// before the check, so neither can leave the allowed folders.
#pragma once

#include <filesystem>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace lucent {

// One name a scene gave a file and where the access rule led it: `written` as in the scene,
// `base` the canonical folder it was relative to, `canonical` the file. A distributed
// render sends these with the files, so that the other processes resolve the same names
// to the copies they were sent (FileReplay) without a shared file system.
struct FileGrant {
  std::string written;
  std::filesystem::path base, canonical;
  bool operator==(const FileGrant& o) const {
    return written == o.written && base == o.base && canonical == o.canonical;
  }
};

// On a process that did not read the scene's files itself: each file is a copy under
// `root` (root / canonical), and a name resolves to that copy when `grants` holds it, the
// access rule having been applied where the files were read. `more`, if set, is asked
// for a name `grants` lacks: it waits for the next grants (and their copies) to arrive,
// adding them, and says false when no more will come (the files are streamed while
// both processes parse).
struct FileReplay {
  std::filesystem::path root;  // canonical
  std::vector<FileGrant> grants;
  std::function<bool()> more;
};

// Told of each name resolve() grants for the first time, as it is granted.
using GrantObserver = std::function<void(const FileGrant&)>;

class FileAccess {
 public:
  FileAccess(const std::filesystem::path& sceneFolder, const std::vector<std::string>& allowPaths,
             const FileReplay* replay = nullptr, GrantObserver onGrant = {});

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
  // Every name resolve() has granted, each once (FileGrant).
  std::vector<FileGrant> grants() const;

 private:
  bool allowed(const std::filesystem::path& canonical) const;
  Resolved replayed(const std::string& written, const std::filesystem::path& baseFolder) const;
  void grant(const std::string& written, const std::filesystem::path& base,
             const std::filesystem::path& c) const;
  std::vector<std::filesystem::path> roots_;
  const FileReplay* replay_ = nullptr;
  GrantObserver onGrant_;
  mutable std::mutex grantedMutex_;  // shapes may be read on several threads
  mutable std::vector<std::filesystem::path> granted_;
  mutable std::vector<FileGrant> grants_;
};

// The canonical form of an existing or not-yet-existing path (weakly_canonical of the
// absolute path, without a trailing separator); never throws.
std::filesystem::path canonicalPath(const std::filesystem::path& p);

}  // namespace lucent
