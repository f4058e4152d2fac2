#include "browser_open.h"

#include <fmt/core.h>

#include <cstring>
#include <thread>

#include <spawn.h>
#include <sys/wait.h>

extern char** environ;

namespace lucent::preview {

void openInBrowser(const std::string& url) {
  std::string program = "xdg-open";
  char* argv[] = {program.data(), const_cast<char*>(url.c_str()), nullptr};
  pid_t pid = 0;
  const int error = ::posix_spawnp(&pid, "xdg-open", nullptr, nullptr, argv, environ);
  if (error != 0) {
    fmt::print(stderr, "lucent: warning: cannot start xdg-open ({}); open the address yourself\n",
               std::strerror(error));
    return;
  }
  // Reaped when it ends (it hands the address to the browser and returns), so that it
  // leaves no zombie behind.
  std::thread([pid] { ::waitpid(pid, nullptr, 0); }).detach();
}

}  // namespace lucent::preview
