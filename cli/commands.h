// The subcommands of `lucent`, each in its own file; main.cpp parses options and dispatches.
// Each returns its exit status or throws what reportFailure() (exit_status.h) maps to one.
#pragma once

#include "exit_status.h"

#include <functional>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lucent {
class Renderer;
struct PixelRect;
struct RenderControl;
struct RenderResult;
struct TileRenderResult;
}  // namespace lucent

namespace lucent::cli {

struct LoadedScene;
using TileExecutor = std::function<TileRenderResult(
    const Renderer&, const LoadedScene&, int, const std::vector<PixelRect>&,
    const std::vector<char>&, const RenderControl&, bool,
    const std::function<void(size_t, const RenderResult&)>&)>;

// The problem with a numeric override (-w, -h, -s, -t, --max-depth) named `name`, if any:
// below 1, or above the limit the scene's <render> has too (render_settings.h).
std::optional<std::string> overrideProblem(const std::string& name,
                                           const std::optional<int>& value);

// Options every command accepts.
struct CommonOptions {
  std::map<std::string, std::string> defines;  // -D name=value
  std::vector<std::string> allowPaths;         // --allow-path DIR[:DIR...]
  // --format pov|xml: the scene's language; empty: its extension decides (load_pov_scene.h).
  std::string format;
  // POV-Ray scenes only (docs/povray-import.md, "Commands"): --pov-library folders searched
  // by #include before the standard ones, --pov-ini FILE[SECTION], --skip-unsupported.
  std::vector<std::string> povLibrary;
  std::string povIni;
  bool skipUnsupported = false;
  std::vector<std::string> allowWrite;  // --allow-write DIR: where #fopen may write
  // --pov-max-tokens N: the most tokens an evaluation reads (none: sdl::Limits's default).
  std::optional<std::uint64_t> povMaxTokens;
};

struct RenderOptions {
  std::string scene;
  std::string output;  // empty: SCENE.png beside the scene (defaultRenderOutput)
  std::optional<int> width, height, samples, threads, maxDepth;
  std::string camera;
  bool quiet = false;
  bool stats = false;
  std::string frames;  // --frames F or A..B (frame_range.h); empty: every frame
  std::string region;  // --region X0,Y0,X1,Y1; empty: the whole image
  std::optional<int>
      tileSize;           // --tile-size (pixels a side); none: defaultTileSize (tile_render.h)
  std::string tileCosts;  // --tile-costs FILE: each tile's time, for bench/tile_schedule
  bool resume = false;    // --resume: continue from the output's checkpoint
  std::optional<double> checkpointInterval;  // --checkpoint-interval SECONDS; 0: none
};

// At most this long between two saves of a render's checkpoint.
constexpr double kDefaultCheckpointInterval = 60.0;

class LoadObserver;
// `executor`: how tiles are rendered (tile_executor.h); empty: on this process's threads.
// `observer`: told of each frame's load (load_scene.h); null: none.
int runRender(const RenderOptions& options, const CommonOptions& common,
              const TileExecutor& executor = {}, LoadObserver* observer = nullptr);
// The image `render` writes without -o: the scene's path with the extension .png.
std::string defaultRenderOutput(const std::string& scene);

// check takes the overrides render takes, so that it refuses what render would.
struct CheckOptions {
  std::string scene;
  std::optional<int> width, height, samples, maxDepth;
  std::string camera;
  bool stats = false;  // --stats: the CPU time of reading the scene, after the summary
};
int runCheck(const CheckOptions& options, const CommonOptions& common);
// The XML Schema of the scene language, to stdout or to `output`.
int runSchema(const std::string& output);

struct ExportPovOptions {
  std::string scene;
  std::string output;
  std::optional<int> width, height, maxDepth;  // the image the .pov file is written for
  std::string camera;
  std::optional<int> frame;  // of an animated scene; none: frame 1
};
int runExportPov(const ExportPovOptions& options, const CommonOptions& common);

struct ConvertOptions {
  std::string scene;
  std::string output;
  std::optional<int> frame;  // of an animated scene; none: frame 1
};
int runConvert(const ConvertOptions& options, const CommonOptions& common);

struct CompareOptions {
  std::string scene;
  std::string outputDir;
  std::string povFile;  // --pov: a hand-written POV-Ray scene instead of the export
  std::optional<int> width, height, samples, threads, maxDepth;
  std::string camera;
  std::optional<int> frame;  // of an animated scene; none: frame 1
};
int runCompare(const CompareOptions& options, const CommonOptions& common);

// lucent preview SCENE: a live render in the browser, again on every save (docs/preview.md).
struct PreviewOptions {
  std::string scene;
  std::optional<int> width, height, samples, threads, maxDepth;
  std::string camera;
  std::string bind = "127.0.0.1";  // --bind: the address the server listens on
  std::optional<int> port;         // --port; none: a free port
  bool open = false;               // --open: start the desktop's browser on the address
  bool compare = false;            // --compare: POV-Ray's render and the difference beside it
};
int runPreview(const PreviewOptions& options, const CommonOptions& common);

}  // namespace lucent::cli
