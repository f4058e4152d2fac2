// --compare: after each finished render, `lucent compare` of the same scene and options
// (POV-Ray's render and the difference heat map, as compare's report shows them), run as a
// child process that a save stops at once.
#pragma once

#include <atomic>
#include <string>
#include <vector>

namespace lucent::preview {

struct Comparison {
  bool cancelled = false;
  std::string error;               // why it failed (its messages), or ""
  std::string report;              // the metrics compare printed
  std::string povrayPng, diffPng;  // the files' bytes
};

// Runs `lucent compare ARGUMENTS -o DIR` (this program) in `dir`, stopping it (SIGTERM)
// once `cancel` is set.
Comparison runComparison(const std::vector<std::string>& arguments, const std::string& dir,
                         const std::atomic<bool>& cancel);

}  // namespace lucent::preview
