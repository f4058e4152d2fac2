#include "frame_range.h"

#include "exit_status.h"

#include <fmt/core.h>

#include <charconv>
#include <optional>

namespace lucent::cli {

namespace {

// A whole number written with digits only: no sign, no spaces, no "1e2".
std::optional<int> wholeNumber(std::string_view s) {
  if (s.empty()) return std::nullopt;
  for (char c : s)
    if (c < '0' || c > '9') return std::nullopt;
  int value = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return value;
}

}  // namespace

FrameRange parseFrameRange(const std::string& text) {
  const std::string_view s(text);
  const size_t dots = s.find("..");
  std::optional<int> first = wholeNumber(s.substr(0, dots));
  std::optional<int> last =
      dots == std::string_view::npos ? first : wholeNumber(s.substr(dots + 2));
  if (!first || !last)
    throw UsageError(
        fmt::format("--frames {}: expected a frame F or a range A..B of whole numbers "
                    "(as --frames 5 or --frames 1..24)",
                    text));
  if (*first < 1 || *last < 1)
    throw UsageError(fmt::format("--frames {}: frames are numbered from 1", text));
  if (*first > *last)
    throw UsageError(fmt::format("--frames {}: the first frame {} comes after the last {}", text,
                                 *first, *last));
  return FrameRange{*first, *last};
}

void checkFrameRange(const FrameRange& range, const std::string& asked, int frames, bool animated) {
  if (range.last <= frames) return;
  if (!animated)
    throw UsageError(fmt::format("{}: the scene has no <animation>, so only frame 1", asked));
  throw UsageError(fmt::format("{}: the animation has {} frame{} (1..{})", asked, frames,
                               frames == 1 ? "" : "s", frames));
}

FrameRange singleFrame(int frame) {
  if (frame < 1) throw UsageError(fmt::format("--frame {}: frames are numbered from 1", frame));
  return FrameRange{frame, frame};
}

}  // namespace lucent::cli
