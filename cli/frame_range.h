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
// the scene has no <animation> and only frame 1. `asked` is the option as given
// ("--frames 2..30", "--frame 3"), which the message starts with.
void checkFrameRange(const FrameRange& range, const std::string& asked, int frames, bool animated);

// --frame F of export-pov and compare: F >= 1, or UsageError.
FrameRange singleFrame(int frame);

}  // namespace lucent::cli
