#include "frame_names.h"

#include <fmt/core.h>

#include <algorithm>
#include <filesystem>

namespace lucent::cli {

namespace {

constexpr int kDefaultDigits = 4;

int digitsOf(int n) { return static_cast<int>(std::to_string(std::max(n, 0)).size()); }

}  // namespace

std::string frameOutputPath(const std::string& output, int frame, int frames) {
  namespace fs = std::filesystem;
  const fs::path path(output);
  const std::string name = path.filename().string();
  const int needed = digitsOf(frames);
  // The last run of '#' in the file name (not in its folders).
  const size_t end = name.find_last_of('#');
  if (end != std::string::npos) {
    size_t begin = end;
    while (begin > 0 && name[begin - 1] == '#') --begin;
    const int width = std::max(static_cast<int>(end - begin + 1), needed);
    const std::string numbered =
        name.substr(0, begin) + fmt::format("{:0{}}", frame, width) + name.substr(end + 1);
    return (path.parent_path() / numbered).string();
  }
  const int width = std::max(kDefaultDigits, needed);
  const std::string numbered =
      path.stem().string() + fmt::format("{:0{}}", frame, width) + path.extension().string();
  return (path.parent_path() / numbered).string();
}

}  // namespace lucent::cli
