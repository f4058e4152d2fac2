#include "output_file.h"

#include "exit_status.h"

#include <fmt/core.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace lucent::cli {

namespace fs = std::filesystem;

namespace {

fs::path folderOf(const fs::path& target) {
  return target.parent_path().empty() ? fs::path(".") : target.parent_path();
}

}  // namespace

// Before the scene is read: an output that can never be written is an error now.
void checkOutputPath(const std::string& path, const std::string& kind) {
  if (fs::is_directory(path)) throw IoFailure(fmt::format("'{}' is a folder, not {}", path, kind));
  const fs::path folder = folderOf(path);
  std::error_code ec;
  const fs::file_status status = fs::status(folder, ec);
  if (status.type() == fs::file_type::not_found)
    throw IoFailure(
        fmt::format("cannot write '{}': folder '{}' does not exist", path, folder.string()));
  if (!ec && status.type() != fs::file_type::directory)
    throw IoFailure(fmt::format("cannot write '{}': '{}' is not a folder", path, folder.string()));
}

void writeAtomically(const std::string& path, const std::string& text) {
  fs::path target(path);
  fs::path folder = folderOf(target);
  std::error_code ec;
  fs::path tmp = target.parent_path() / ("." + target.filename().string() + ".tmp");
  auto failed = [&](const std::string& reason) {
    fs::remove(tmp, ec);
    return IoFailure(fmt::format("cannot write '{}': {}", path, reason));
  };
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out)
      throw failed(fmt::format("cannot create a file in folder '{}': {}", folder.string(),
                               std::strerror(errno)));
    out << text;
    out.flush();
    if (!out) throw failed(std::strerror(errno));
  }
  fs::rename(tmp, target, ec);
  if (ec) throw failed(ec.message());
}

}  // namespace lucent::cli
