#include "load_pov_scene.h"

#include "lang/file_access.h"
#include "sdl/console_text.h"
#include "sdl/pov_ini.h"
#include "sdl/scene_reader.h"

#include "scenegraph/located_error.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iostream>

namespace lucent::cli {

namespace fs = std::filesystem;

bool isPovScene(const std::string& scene, const std::string& format) {
  if (!format.empty()) return format == "pov";
  std::string ext = fs::path(scene).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".pov" || ext == ".inc";
}

namespace {

// -D values: numbers, declared as POV-Ray's Declare= declares them; `clock` and `frame`
// choose the moment, as they do for an XML scene.
void takeDefines(const CommonOptions& common, sdl::Options& options, std::optional<double>& clock,
                 std::optional<int>& frame) {
  for (const auto& [name, value] : common.defines) {
    size_t used = 0;
    double v = 0;
    try {
      v = std::stod(value, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != value.size())
      throw UsageError(fmt::format(
          "-D {}={}: a POV-Ray scene is given numbers (as POV-Ray's Declare=), not '{}'", name,
          value, value));
    if (name == "clock") clock = v;
    else if (name == "frame") frame = static_cast<int>(v);
    else options.declared[name] = v;
  }
}

// The animation an INI file describes, as Lucent's frames 1..N (POV-Ray's Initial_Frame
// is frame 1).
Animation animationOf(const sdl::PovIni& ini) {
  Animation a;
  if (!ini.animated()) return a;
  a.present = true;
  a.frames = *ini.finalFrame - ini.initialFrame.value_or(1) + 1;
  a.clockFrom = ini.initialClock.value_or(0.0);
  a.clockTo = ini.finalClock.value_or(1.0);
  a.cyclic = ini.cyclic;
  return a;
}

// The frame identifiers POV-Ray declares for frame `frame` of `animation` (clock,
// clock_delta, frame_number, initial/final frame and clock, clock_on).
void setMoment(const sdl::PovIni& ini, const Animation& animation, int frame,
               std::optional<double> clock, sdl::Options& options) {
  const int first = ini.initialFrame.value_or(1);
  options.initialFrame = first;
  options.finalFrame = ini.finalFrame.value_or(first);
  options.initialClock = ini.initialClock.value_or(0.0);
  options.finalClock = ini.finalClock.value_or(animation.present ? 1.0 : 0.0);
  options.frameNumber = animation.present ? first + frame - 1 : 0;
  options.clockOn = animation.present;
  if (animation.present) {
    const double steps = animation.cyclic ? animation.frames : animation.frames - 1;
    options.clockDelta = steps > 0 ? (animation.clockTo - animation.clockFrom) / steps : 0.0;
  }
  options.clock = clock               ? *clock
                  : animation.present ? animation.clockOf(frame)
                                      : ini.clock.value_or(0.0);
}

// #debug printed at once, as POV-Ray prints it; warnings kept as the load's diagnostics, so
// that the command prints them as it prints an XML scene's (once over an animation's
// frames, not at all on the workers of a distributed render).
class LoadOutput : public sdl::Output {
 public:
  void debug(const std::string& text) override { std::cerr << printer_.add(text) << std::flush; }
  void warning(const SourceLoc& loc, const std::string& message) override {
    warnings.warning(loc, message);
  }
  Diagnostics warnings;

 private:
  sdl::DebugPrinter printer_;
};

}  // namespace

sdl::PovIni readIniOption(const CommonOptions& common) {
  if (common.povIni.empty()) return {};
  std::string file = common.povIni, section;
  // POV-Ray's FILE[SECTION] names a part of the file.
  if (!file.empty() && file.back() == ']') {
    const size_t open = file.rfind('[');
    if (open != std::string::npos) {
      section = file.substr(open + 1, file.size() - open - 2);
      file.resize(open);
    }
  }
  try {
    return sdl::readPovIni(file, section);
  } catch (const LocatedError& e) {
    throw UsageError(fmt::format("--pov-ini: {}: error: {}", e.loc().str(), e.message()));
  }
}

ParseResult parsePovScene(const SceneRequest& request, const CommonOptions& common) {
  ParseResult result;
  if (!std::ifstream(request.scene) || fs::is_directory(request.scene)) {
    result.diagnostics.error(SourceLoc{request.scene, 0, 0}, "cannot read the scene file");
    result.ioFailure = true;
    return result;
  }
  const sdl::PovIni ini = readIniOption(common);
  const fs::path folder = fs::path(request.scene).parent_path();
  FileAccess access(folder.empty() ? fs::path(".") : folder, common.allowPaths);
  sdl::Options options;
  options.access = &access;
  options.skipUnsupported = common.skipUnsupported;
  options.writeFolders.assign(common.allowWrite.begin(), common.allowWrite.end());
  if (common.povMaxTokens) options.limits.tokens = *common.povMaxTokens;
  // The image POV-Ray would render: -w/-h, else the INI file's, else its own 800x600.
  options.imageWidth = request.width.value_or(ini.width.value_or(800));
  options.imageHeight = request.height.value_or(ini.height.value_or(600));
  // Include folders: --pov-library in order, the INI file's, then the standard ones.
  std::vector<fs::path> library(common.povLibrary.begin(), common.povLibrary.end());
  library.insert(library.end(), ini.library.begin(), ini.library.end());
  options.includeFolders.insert(options.includeFolders.begin(), library.begin(), library.end());
  options.declared = ini.declared;  // the command line's -D override the INI file's
  std::optional<double> clock;
  std::optional<int> frame;
  takeDefines(common, options, clock, frame);
  result.animation = animationOf(ini);
  result.frame = frame.value_or(request.frame);
  setMoment(ini, result.animation, result.frame, clock, options);
  result.clock = options.clock;
  LoadOutput output;
  options.output = &output;
  sdl::SceneLoad load = sdl::loadScene(request.scene, options);
  result.scene = std::move(load.scene);
  if (result.scene) {
    result.scene->animation = result.animation;
    result.scene->frame = result.frame;
    result.scene->clock = result.clock;
  }
  result.diagnostics = std::move(output.warnings);
  for (const Diagnostic& d : load.diagnostics.all()) {
    if (d.severity == Severity::Error) result.diagnostics.error(d.loc, d.message);
    else result.diagnostics.warning(d.loc, d.message);
  }
  result.sources.push_back(canonicalPath(request.scene));
  for (const fs::path& f : access.granted())
    if (std::find(result.sources.begin(), result.sources.end(), f) == result.sources.end())
      result.sources.push_back(f);
  return result;
}

}  // namespace lucent::cli
