#include "system_memory.h"

#include <fmt/format.h>

#include <sys/resource.h>

#include <algorithm>
#include <fstream>
#include <string>

namespace lucent {

namespace {

std::optional<std::uintmax_t> memAvailable() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  std::uintmax_t kb = 0;
  std::string unit;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024;
  return std::nullopt;
}

std::optional<std::uintmax_t> readNumber(const char* path) {
  std::ifstream in(path);
  std::uintmax_t v = 0;
  if (in >> v) return v;
  return std::nullopt;  // also "max": no limit
}

std::optional<std::uintmax_t> cgroupLeft() {
  auto max = readNumber("/sys/fs/cgroup/memory.max");
  if (!max) return std::nullopt;
  auto current = readNumber("/sys/fs/cgroup/memory.current").value_or(0);
  return *max > current ? *max - current : 0;
}

std::optional<std::uintmax_t> addressSpaceLeft() {
  struct rlimit limit {};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
  std::uintmax_t used = 0;
  std::ifstream in("/proc/self/statm");
  std::uintmax_t pages = 0;
  if (in >> pages) used = pages * 4096;
  return limit.rlim_cur > used ? limit.rlim_cur - used : 0;
}

}  // namespace

std::optional<std::uintmax_t> availableMemoryBytes() {
  std::optional<std::uintmax_t> least;
  for (auto v : {memAvailable(), cgroupLeft(), addressSpaceLeft()})
    if (v) least = least ? std::min(*least, *v) : *v;
  return least;
}

std::string formatBytes(std::uintmax_t bytes) {
  const double b = static_cast<double>(bytes);
  if (b >= 1e9) return fmt::format("{:.1f} GB", b / 1e9);
  if (b >= 1e6) return fmt::format("{:.1f} MB", b / 1e6);
  if (b >= 1e3) return fmt::format("{:.1f} kB", b / 1e3);
  return fmt::format("{} bytes", bytes);
}

}  // namespace lucent
