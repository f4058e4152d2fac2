#include "pov_runner.h"

#include <fmt/core.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace lucent {

namespace fs = std::filesystem;

std::optional<std::string> findPovray() {
  if (const char* env = std::getenv("LUCENT_POVRAY"); env && *env) {
    if (::access(env, X_OK) == 0) return std::string(env);
    return std::nullopt;
  }
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) dir = ".";
    fs::path candidate = fs::path(dir) / "povray";
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0)
      return candidate.string();
  }
  return std::nullopt;
}

const char* povrayInstallHint() {
  return "POV-Ray 3.7 is needed for this command: install it with `sudo apt-get install "
         "povray` (Debian, Ubuntu), `sudo dnf install povray` (Fedora) or `brew install povray` "
         "(macOS), or set LUCENT_POVRAY to the povray executable";
}

std::string cornerThresholdFlag(double threshold) {
  // Fixed notation (POV-Ray's switch reads no exponent), trailing zeros dropped: "+A0.3",
  // "+A0.0" (a bare +A would mean its default, 0.3).
  std::string t = fmt::format("{:.6f}", threshold);
  while (t.size() > 1 && t.back() == '0' && t[t.size() - 2] != '.') t.pop_back();
  return "+A" + t;
}

std::string povrayPathOption(const std::string& flag, const std::string& path) {
  // POV-Ray splits an option at its spaces unless the path is quoted.
  if (path.find_first_of(" \t") == std::string::npos) return flag + path;
  return flag + "\"" + path + "\"";
}

std::vector<std::string> povrayArguments(const PovrayRender& r) {
  std::vector<std::string> args = {povrayPathOption("+I", r.input),
                                   povrayPathOption("+O", r.output),
                                   fmt::format("+W{}", r.width),
                                   fmt::format("+H{}", r.height),
                                   "-D",
                                   "-V",
                                   "-GS",
                                   "-GR",
                                   "+FN16",
                                   "File_Gamma=" + r.fileGamma};
  if (r.corners) {
    args.insert(args.end(), {"+AM2", cornerThresholdFlag(r.cornerThreshold), "-J",
                             fmt::format("+R{}", r.cornerDepth)});
  } else if (r.samples <= 1) {
    args.push_back("-A");
  } else {
    // Threshold 0 supersamples every pixel, -J keeps the grid regular: an R×R grid plus the
    // centre, the closest POV-Ray has to a fixed number of samples per pixel.
    int grid = std::max(2, static_cast<int>(std::lround(std::sqrt(r.samples))));
    args.insert(args.end(), {"+A0.0", "-J", "+AM1", fmt::format("+R{}", grid)});
  }
  if (r.threads > 0) args.push_back(fmt::format("+WT{}", r.threads));
  // The shortest text that reads back as the same double.
  if (r.clock != 0.0) args.push_back(fmt::format("+K{}", r.clock));
  args.insert(args.end(), r.extra.begin(), r.extra.end());
  return args;
}

ProcessResult runProcess(const std::string& program, const std::vector<std::string>& arguments,
                         const std::string& workingDirectory, const std::string& logPath) {
  ProcessResult result;
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(program.c_str()));
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);

  auto start = std::chrono::steady_clock::now();
  pid_t pid = ::fork();
  if (pid < 0) return result;
  if (pid == 0) {
    // Child: only async-signal-safe calls until exec.
    int log = ::open(logPath.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (log >= 0) {
      ::dup2(log, STDOUT_FILENO);
      ::dup2(log, STDERR_FILENO);
      ::close(log);
    }
    int devnull = ::open("/dev/null", O_RDONLY);
    if (devnull >= 0) ::dup2(devnull, STDIN_FILENO);
    if (!workingDirectory.empty() && ::chdir(workingDirectory.c_str()) != 0) ::_exit(127);
    ::execv(program.c_str(), argv.data());
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return result;
  }
  result.started = true;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (WIFEXITED(status)) result.exitStatus = WEXITSTATUS(status);
  return result;
}

std::string commandLine(const std::string& program, const std::vector<std::string>& arguments) {
  auto quote = [](const std::string& s) {
    if (s.find_first_of(" \t'\"$\\") == std::string::npos) return s;
    std::string q = "'";
    for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  };
  std::string out = quote(program);
  for (const std::string& a : arguments) out += " " + quote(a);
  return out;
}

}  // namespace lucent
