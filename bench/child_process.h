// Runs another program as a child process and measures it as a whole: wall time, user
// CPU time and peak resident memory (getrusage of the child, as the kernel counts it).
#pragma once

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace lucent::bench {

struct ChildRun {
  bool ok = false;          // exited with status 0
  double seconds = 0.0;     // wall time, fork to exit
  double cpuSeconds = 0.0;  // user + system time of the child
  double peakMB = 0.0;      // ru_maxrss of the child
};

// Runs `program` with `args`; its standard output (and standard error unless keepStderr)
// goes to /dev/null.
inline ChildRun runChild(const std::string& program, const std::vector<std::string>& args,
                         bool keepStderr = true) {
  auto t0 = std::chrono::steady_clock::now();
  pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv{const_cast<char*>(program.c_str())};
    for (auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    int devnull = open("/dev/null", O_WRONLY);
    dup2(devnull, 1);
    if (!keepStderr) dup2(devnull, 2);
    execv(program.c_str(), argv.data());
    std::perror("exec");
    _exit(127);
  }
  int status = 0;
  struct rusage usage;
  std::memset(&usage, 0, sizeof usage);
  wait4(pid, &status, 0, &usage);
  ChildRun run;
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  run.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  run.cpuSeconds = double(usage.ru_utime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec) +
                   double(usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_stime.tv_usec);
  run.peakMB = double(usage.ru_maxrss) / 1024.0;
  return run;
}

}  // namespace lucent::bench
