// Runs the lucent binary (lucentBinaryPath()) as a user would, for the tests of the command line.
#pragma once

#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include "../support/paths.h"

namespace lucent::test {

struct LucentRun {
  int status = -1;
  std::string out;  // stdout and stderr, stderr lines prefixed "E: "
  std::string err;  // stderr alone
};

// `args` is pasted into a shell command line: quote paths with '...'.
inline LucentRun runLucent(const std::string& args) {
  namespace fs = std::filesystem;
  static int counter = 0;
  fs::path errFile = fs::temp_directory_path() / ("lucent-cli-test-" + std::to_string(::getpid()) +
                                                  "-" + std::to_string(++counter) + ".err");
  std::string cmd = std::string("'") + lucentBinaryPath() + "' " + args + " 2>'" +
                    errFile.string() + "' </dev/null";
  LucentRun r;
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p);
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  int raw = pclose(p);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  FILE* e = fopen(errFile.string().c_str(), "r");
  if (e) {
    char line[4096];
    while (fgets(line, sizeof line, e)) {
      r.out += std::string("E: ") + line;
      r.err += line;
    }
    fclose(e);
  }
  fs::remove(errFile);
  return r;
}

inline std::string sourcePath(const std::string& rel) {
  return (std::filesystem::path(lucentSourceDir()) / rel).string();
}

// A fresh empty folder under the system's temporary folder, removed with the object.
class TempFolder {
 public:
  explicit TempFolder(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::string str(const std::string& rel = "") const {
    return rel.empty() ? path_.string() : (path_ / rel).string();
  }

 private:
  std::filesystem::path path_;
};

}  // namespace lucent::test
