// How much memory this process may still take, for refusing an image or a mesh that cannot
// fit with a clear error instead of being killed by the system half way (or swapping for
// hours).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace lucent {

// The least of: the kernel's estimate of memory available without swapping (MemAvailable in
// /proc/meminfo), what is left under a cgroup v2 memory limit (a container's), and what is
// left under RLIMIT_AS. Nothing when none of them can be read.
std::optional<std::uintmax_t> availableMemoryBytes();

// "1.5 GB" (decimal units, as `free -h` and file managers show them).
std::string formatBytes(std::uintmax_t bytes);

}  // namespace lucent
