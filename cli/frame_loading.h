// Loading one frame of an animated scene, for the commands that go through its frames:
// a frame that fails is named with its clock after the errors loadScene printed.
#pragma once

#include "load_scene.h"

namespace lucent::cli {

// -D frame=F or -D clock=C picks one moment: the commands then take that scene alone (a
// render writes it to -o itself, not to a numbered file).
bool picksOneMoment(const CommonOptions& common);

// loadScene of frame request.frame of `animation`. On failure it prints what loadScene's
// caller would (reportFailure), then "lucent: frame F of N (clock C) is invalid" (or
// "cannot be loaded" for an input/output failure, "cannot be rendered as asked" for a
// usage error), and throws ReportedFailure with the failure's status.
LoadedScene loadFrame(const SceneRequest& request, const CommonOptions& common,
                      const Animation& animation);

// export-pov and compare: loadScene of frame `frame` (--frame F; none: frame 1). Throws
// UsageError for a frame the scene does not have, or --frame given with -D frame/clock.
LoadedScene loadOneFrame(SceneRequest request, const CommonOptions& common,
                         const std::optional<int>& frame);

// "frame 3 of 24 (clock 0.0869565)": the clock in its shortest exact form.
std::string frameName(int frame, const Animation& animation);

}  // namespace lucent::cli
