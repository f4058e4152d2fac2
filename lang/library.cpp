#include "library.h"

#include "library_files.h"

#include <algorithm>

namespace lucent {

std::optional<std::string_view> libraryFile(std::string_view name) {
  for (const auto& [file, text] : kLibraryFiles)
    if (file == name) return text;
  return std::nullopt;
}

std::vector<std::string_view> libraryFileNames() {
  std::vector<std::string_view> names;
  for (const auto& entry : kLibraryFiles) names.push_back(entry.first);
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace lucent
