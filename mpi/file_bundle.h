// What rank 0 sends with each frame so that a worker can parse the same scene without a
// shared file system: the scene file's path, every name the scene gave a file and where it
// led (FileGrant), and the bytes of each file not sent before. A worker writes the files
// under a private folder (root / canonical path) and parses the copy of the scene with a
// FileReplay, so the same names lead to the copies.
#pragma once

#include "lang/file_access.h"

#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace lucent::mpi {

struct FileBundle {
  int frame = 1;
  std::filesystem::path scene;  // canonical, on rank 0
  std::vector<FileGrant> grants;
  std::vector<std::pair<std::filesystem::path, std::string>> files;  // canonical path, bytes
};

// The bundle of `frame`: reads each of `files` not in `sent` (and adds it there). Throws
// IoFailure for a file that cannot be read.
FileBundle makeBundle(int frame, const std::filesystem::path& scene,
                      const std::vector<FileGrant>& grants,
                      const std::vector<std::filesystem::path>& files,
                      std::set<std::filesystem::path>& sent);

std::vector<char> pack(const FileBundle& bundle);
FileBundle unpack(const std::vector<char>& bytes);

// Writes each file to root / its canonical path. Throws IoFailure if one cannot be written.
void materialise(const FileBundle& bundle, const std::filesystem::path& root);

}  // namespace lucent::mpi
