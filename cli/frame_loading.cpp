#include "frame_loading.h"

#include "frame_range.h"

#include <fmt/core.h>

#include <cstdio>
#include <set>

namespace lucent::cli {

bool picksOneMoment(const CommonOptions& common) {
  return common.defines.count("frame") > 0 || common.defines.count("clock") > 0;
}

std::string frameName(int frame, const Animation& animation) {
  return fmt::format("frame {} of {} (clock {})", frame, animation.frames,
                     animation.clockOf(frame));
}

LoadedScene loadFrame(const SceneRequest& request, const CommonOptions& common,
                      const Animation& animation) {
  try {
    return loadScene(request, common);
  } catch (...) {
    const int status = reportFailure(std::current_exception());
    const char* what = status == kInvalidScene ? "is invalid"
                       : status == kUsage      ? "cannot be rendered as asked"
                                               : "cannot be loaded";
    fmt::print(stderr, "lucent: {} {}\n", frameName(request.frame, animation), what);
    throw ReportedFailure{status};
  }
}

LoadedScene loadOneFrame(SceneRequest request, const CommonOptions& common,
                         const std::optional<int>& frame) {
  if (!frame) return loadScene(request, common);
  const FrameRange range = singleFrame(*frame);
  const std::string asked = fmt::format("--frame {}", *frame);
  if (picksOneMoment(common))
    throw UsageError(fmt::format("{} and -D {} both choose the moment; give one", asked,
                                 common.defines.count("frame") ? "frame" : "clock"));
  std::set<std::string> printed;  // frame 1's warnings, not repeated for frame F
  if (!request.printed) request.printed = &printed;
  // Frame 1 tells how many frames there are: a frame beyond them is wrong usage, not an
  // invalid scene (which the parser would say of it).
  LoadedScene loaded = loadScene(request, common);
  const Animation animation = loaded.scene->animation;
  checkFrameRange(range, asked, animation.present ? animation.frames : 1, animation.present);
  if (*frame == 1) return loaded;
  loaded = {};
  request.frame = *frame;
  return loadFrame(request, common, animation);
}

}  // namespace lucent::cli
