#include "pov_comparison.h"

#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

extern char** environ;

namespace lucent::preview {

namespace {

namespace fs = std::filesystem;

std::string fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// The child started with stdout and stderr to files in `dir`; -1 (and `error`) if not.
pid_t start(std::vector<std::string> arguments, const fs::path& dir, std::string& error) {
  std::error_code ec;
  const std::string self = fs::read_symlink("/proc/self/exe", ec).string();
  arguments.insert(arguments.begin(), {self, "compare"});
  arguments.insert(arguments.end(), {"-o", (dir / "report").string()});
  std::vector<char*> argv;
  for (std::string& a : arguments) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  const std::string out = (dir / "compare.out").string(), err = (dir / "compare.err").string();
  posix_spawn_file_actions_addopen(&files, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&files, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int failed = posix_spawn(&pid, self.c_str(), &files, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  if (failed != 0) error = std::string("cannot start lucent compare: ") + std::strerror(failed);
  return failed == 0 ? pid : -1;
}

}  // namespace

Comparison runComparison(const std::vector<std::string>& arguments, const std::string& dir,
                         const std::atomic<bool>& cancel) {
  Comparison result;
  const pid_t pid = start(arguments, dir, result.error);
  if (pid < 0) return result;
  int status = 0;
  // Polled, so that a save stops it within a few milliseconds.
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (cancel.load()) {
      ::kill(pid, SIGTERM);
      ::waitpid(pid, &status, 0);
      result.cancelled = true;
      return result;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const fs::path folder(dir);
  result.report = fileBytes(folder / "compare.out");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    result.error = "lucent compare failed:\n" + fileBytes(folder / "compare.err");
    return result;
  }
  result.povrayPng = fileBytes(folder / "report" / "povray.png");
  result.diffPng = fileBytes(folder / "report" / "diff.png");
  return result;
}

}  // namespace lucent::preview
