// --frames A..B or --frames F: which frames of an animation a render writes, so that a
// batch system can give each job its own range.
#pragma once

#include <string>

namespace lucent::cli {

struct FrameRange {
  int first = 1, last = 1;  // 1-based, inclusive
  int count() const { return last - first + 1; }
};

// Reads "F" or "A..B" (whole numbers, 1 <= A <= B). Throws UsageError naming the option.
FrameRange parseFrameRange(const std::string& text);

// Throws UsageError when the range goes beyond the scene's frames: `animated` false means
// the scene has no <animation> and only frame 1.
void checkFrameRange(const FrameRange& range, const std::string& text, int frames, bool animated);

}  // namespace lucent::cli
