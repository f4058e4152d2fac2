// lucent render SCENE [-o OUT]: load the scene (load_scene.h: parse, overrides, the
// checks `check` makes too), build the world, render over every core, write the image
// atomically; without -o the image is SCENE.png beside the scene.
//
// An animated scene is rendered frame by frame, each parsed again for its frame (the
// scene graph differs), to the numbered files frame_names.h makes of OUT; --frames picks
// some. Files the frames read (meshes, image textures, the image plugin) are loaded once
// for the run. -D frame=F or -D clock=C renders that one moment to OUT itself.
//
// Exit statuses (the contract's): 1 for wrong usage, which includes option values out of
// range, a --frames range beyond the scene's frames and a --camera name the scene does not
// define (the scene itself is valid, the request is not; the message lists the scene's
// camera names); 2 for an invalid scene (parse errors, a camera that cannot form an image;
// in an animation the message names the frame); 3 for input/output and runtime failures
// (unwritable output, unknown output extension, unreadable texture, Ctrl-C).
#include "commands.h"

#include "checkpoint_identity.h"
#include "frame_loading.h"
#include "frame_names.h"
#include "frame_range.h"
#include "interrupt_catcher.h"
#include "load_scene.h"
#include "tile_executor.h"

#include "app/image_output.h"
#include "app/progress_bar.h"
#include "memory/system_memory.h"
#include "meshes/mesh_file_cache.h"
#include "render/image_map_cache.h"
#include "render/renderer.h"
#include "render/tile_render.h"
#include "scenegraph/gradient_report.h"
#include "scenegraph/shape_registry.h"

#include <fmt/core.h>
#include <fmt/format.h>
#include <tbb/global_control.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include <malloc.h>
#include <unistd.h>

namespace lucent::cli {

namespace {

// The image in memory: the renderer's linear float pixels, the encoded copy handed to the
// writer (at most float RGB), and the copy read back to prove the file complete.
constexpr std::uintmax_t kImageBytesPerPixel = 3 * sizeof(Color);

// An image too large for the memory left is refused before the render, not after hours.
std::optional<std::string> imageMemoryProblem(const PixelRect& area) {
  const std::uintmax_t need =
      std::uintmax_t(area.width()) * std::uintmax_t(area.height()) * kImageBytesPerPixel;
  const std::optional<std::uintmax_t> available = availableMemoryBytes();
  if (!available || need <= *available) return std::nullopt;
  return fmt::format("a {}x{} image needs about {} of memory, more than the {} available",
                     area.width(), area.height(), formatBytes(need), formatBytes(*available));
}

void printStats(const RenderResult& r, int threads) {
  const RayStats& s = r.stats;
  fmt::print("rays:      {:>14}  (primary {}, shadow {}, reflected {}, refracted {})\n", s.rays(),
             s.primary, s.shadow, s.reflected, s.refracted);
  fmt::print("searches:  {:>14}  (closest-hit and any-hit queries of the world)\n", s.queries);
  fmt::print(
      "cache hits:{:>14}  (shadow rays blocked by the object that blocked the light's "
      "previous one, tested first)\n",
      s.shadowCacheHits);
  // Intersection tests by kind, the kinds the scene has only.
  uint64_t tests = 0;
  std::string byKind;
  for (size_t k = 0; k < kTestSlots; ++k) {
    const uint64_t n = s.tests[k];
    if (n == 0) continue;
    tests += n;
    byKind += fmt::format("{}{} {}", byKind.empty() ? "" : ", ", testSlotName(k), n);
  }
  fmt::print("tests:     {:>14}  ({})\n", tests, byKind.empty() ? "none" : byKind);
  fmt::print("time:      {:>14.3f}  s ({})\n", r.seconds, formatDuration(r.seconds));
  fmt::print("speed:     {:>14.3f}  Mrays/s on {} threads\n",
             r.seconds > 0.0 ? s.rays() / r.seconds * 1e-6 : 0.0, threads);
}

int threadsShown(int threads) {
  return threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// What the run keeps from one frame to the next.
struct RenderRun {
  RenderRun(const RenderOptions& o, const TileExecutor& e) : options(o), executor(e) {}
  const RenderOptions& options;
  const TileExecutor& executor;  // empty: renderTiles
  int threads = 0;               // 0: every core
  ImageMapCache textures;
  std::set<std::string> printed;  // after-render warnings, each once for all the frames
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  std::optional<PixelRect> region;  // --region; none: the whole image
  std::optional<int> tileSize;      // --tile-size; none: defaultTileSize of each frame
  double checkpointInterval = kDefaultCheckpointInterval;  // seconds; 0: no checkpoint
  std::optional<CheckpointWriter> checkpoint;
  std::optional<CheckpointContents> resumed;  // --resume: the checkpoint as read
  std::string checkpointPath;
  // A test's stand-in for Ctrl-C: SIGTERM after this many tiles
  // (LUCENT_TEST_INTERRUPT_AFTER_TILES).
  long interruptAfterTiles = 0;
  long tilesFinished = 0;
};

// The rectangle a frame renders: --region, checked against the frame's image size.
PixelRect frameArea(const RenderRun& run, const RenderSettings& r) {
  const PixelRect whole = wholeImage(r.width, r.height);
  if (!run.region) return whole;
  if (!whole.contains(*run.region))
    throw UsageError(
        fmt::format("--region {}: outside the {}x{} image", run.options.region, r.width, r.height));
  return *run.region;
}

// One line per tile, for bench/tile_schedule (docs/distributed.md).
void writeTileCosts(const std::string& path, const std::vector<std::pair<PixelRect, double>>& costs,
                    const RenderSettings& r, int tileSize, int threads, const std::string& scene,
                    double loadSeconds) {
  std::ofstream out(path);
  out << "# lucent tile costs 1\n";
  out << fmt::format("# image {} {} tile {} threads {} samples {} load {:.6f} scene {}\n", r.width,
                     r.height, tileSize, threads, r.samples, loadSeconds, scene);
  out << "x0 y0 x1 y1 seconds\n";
  for (const auto& [t, seconds] : costs)
    out << fmt::format("{} {} {} {} {:.9f}\n", t.x0, t.y0, t.x1, t.y1, seconds);
  out.close();
  if (!out) throw IoFailure(fmt::format("cannot write the tile costs '{}'", path));
}

// Renders the loaded scene (frame `frame`) tile by tile and writes it to `output`, keeping
// a checkpoint as it goes (app/checkpoint.h) and taking the tiles a resumed checkpoint
// holds. The scene is freed before the image is written. `cancelled` in the result:
// nothing was written (the checkpoint holds the finished tiles).
RenderResult renderToFile(LoadedScene loaded, const std::string& output, RenderRun& run,
                          const std::optional<SequencePosition>& position, int frame,
                          double loadSeconds) {
  Scene& scene = *loaded.scene;
  const PixelRect area = frameArea(run, scene.render);
  if (auto problem = imageMemoryProblem(area)) throw IoFailure(*problem);
  const int tileSize = run.tileSize.value_or(defaultTileSize(scene.render));
  const std::vector<PixelRect> tiles = tilesOf(area, tileSize);
  std::vector<char> skip(tiles.size(), 0);
  RenderResult result;
  result.image = Image(area.width(), area.height());
  auto place = [&](const PixelRect& t, const Image& pixels) {
    for (int y = 0; y < t.height(); ++y)
      std::copy_n(&pixels.at(0, y), t.width(),
                  &result.image.at(t.x0 - area.x0, t.y0 - area.y0 + y));
  };

  std::optional<Identity> identity;  // made when first needed: it reads every file again
  auto frameId = [&]() -> const Identity& {
    if (!identity) identity = frameIdentity(loaded, frame, tileSize);
    return *identity;
  };
  bool begun = false;  // the checkpoint has this frame's start record
  if (run.resumed) {
    if (auto it = run.resumed->frames.find(frame);
        it != run.resumed->frames.end() && !it->second.identity.empty()) {
      const std::vector<std::string> differ = identityDifferences(it->second.identity, frameId());
      if (!differ.empty())
        throw UsageError(fmt::format(
            "--resume: the checkpoint '{}' was made for another scene or other files; {}",
            run.checkpointPath, fmt::join(differ, "; ")));
      begun = true;
      size_t taken = 0;
      for (const auto& [rect, pixels] : it->second.tiles)
        for (size_t i = 0; i < tiles.size(); ++i)
          if (tiles[i] == rect && !skip[i]) {
            place(rect, pixels);
            skip[i] = 1;
            ++taken;
          }
      if (!run.options.quiet)
        fmt::print(stderr, "lucent: resuming '{}': {} of {} tiles from the checkpoint\n", output,
                   taken, tiles.size());
    }
  }

  std::vector<size_t> unsaved;  // finished tiles not yet in the checkpoint
  auto lastSave = std::chrono::steady_clock::now();
  auto saveCheckpoint = [&] {
    if (!run.checkpoint) return;
    if (!begun) {
      run.checkpoint->beginFrame(frame, frameId());
      begun = true;
    }
    for (size_t i : unsaved) {
      const PixelRect& t = tiles[i];
      Image pixels(t.width(), t.height());
      for (int y = 0; y < t.height(); ++y)
        std::copy_n(&result.image.at(t.x0 - area.x0, t.y0 - area.y0 + y), t.width(),
                    &pixels.at(0, y));
      run.checkpoint->addTile(frame, t, pixels);
    }
    unsaved.clear();
    run.checkpoint->save();
    lastSave = std::chrono::steady_clock::now();
  };
  std::vector<std::pair<PixelRect, double>> costs;
  const bool recordCosts = !run.options.tileCosts.empty();

  {
    World world(scene);
    Renderer renderer(world, *loaded.camera, &run.textures);

    RenderProgress progress;
    RenderControl control;
    control.threads = run.threads;
    control.cancel = &InterruptCatcher::flag();
    control.progress = &progress;
    std::optional<ProgressBar> bar;
    if (!run.options.quiet && ::isatty(STDERR_FILENO)) bar.emplace(progress, stderr, position);
    const TileFinished finished = [&](size_t i, const RenderResult& tile) {
      place(tiles[i], tile.image);
      unsaved.push_back(i);
      if (recordCosts) costs.emplace_back(tiles[i], tile.seconds);
      if (run.interruptAfterTiles > 0 && ++run.tilesFinished == run.interruptAfterTiles)
        std::raise(SIGTERM);
      if (run.checkpoint && secondsSince(lastSave) >= run.checkpointInterval) saveCheckpoint();
    };
    const TileRenderResult r =
        run.executor
            ? run.executor(renderer, loaded, frame, tiles, skip, control, recordCosts, finished)
            : renderTiles(renderer, tiles, skip, control, recordCosts, finished);
    result.stats = r.stats;
    result.seconds = r.seconds;
    result.cancelled = r.cancelled;
  }
  if (recordCosts)
    writeTileCosts(run.options.tileCosts, costs, scene.render, tileSize, threadsShown(run.threads),
                   run.options.scene, loadSeconds);
  if (result.cancelled) {
    if (run.checkpoint) {
      saveCheckpoint();
      fmt::print(stderr,
                 "lucent: the checkpoint '{}' keeps the finished tiles; run again with --resume to "
                 "go on\n",
                 run.checkpoint->path());
    }
    return result;
  }
  // Printed even with -q, like every warning.
  for (const std::string& w : gradientWarnings(scene))
    if (run.printed.insert(w).second) fmt::print(stderr, "{}\n", w);
  // A frame of an animation: its identity is kept with the record that it was written, so
  // that a resumed run can tell the frame is this scene's before it skips it.
  if (run.checkpoint && position) frameId();

  // The world is gone and the scene goes too before the image is written: writing an EXR,
  // TIFF, HDR or JPEG loads OpenImageIO (images/image_plugin.h, 130 MB of libraries), and
  // the two need not be in memory at once. (PNG and PPM are written without it.)
  loaded.scene.reset();
  // glibc keeps freed blocks for reuse (in each thread's arena, and below the top of
  // the heap); hand them back to the system, or they would count twice.
  ::malloc_trim(0);
  writeImageFile(result.image, output);
  if (run.checkpoint) {
    if (position) {
      unsaved.clear();  // the image is written: its tiles need not be kept
      if (!begun) run.checkpoint->beginFrame(frame, *identity);
      run.checkpoint->frameWritten(frame);
      run.checkpoint->save();
    } else {
      run.checkpoint->remove();
    }
  }
  if (!run.options.quiet) {
    const std::string frameText =
        position ? fmt::format("frame {}/{}, ", position->frame, position->frames) : "";
    fmt::print(stderr, "lucent: wrote '{}' ({}{}x{}, {})\n", output, frameText, area.width(),
               area.height(), formatDuration(result.seconds));
  }
  return result;
}

// Every frame of `range` of `animation`, each parsed again for its frame, to the numbered
// files. `first`, if it holds a scene, is the range's first frame, already loaded (in
// `firstLoadSeconds`).
int renderFrames(LoadedScene first, double firstLoadSeconds, const Animation& animation,
                 const FrameRange& range, const SceneRequest& request, const CommonOptions& common,
                 const std::string& output, RenderRun& run) {
  SceneRequest frameRequest = request;
  RayStats totalStats;
  double totalRender = 0.0;
  int written = 0;
  for (int f = range.first; f <= range.last; ++f) {
    const std::string name = frameOutputPath(output, f, animation.frames);
    if (InterruptCatcher::interrupted()) {
      fmt::print(stderr, "lucent: interrupted; {} of {} frames written, '{}' not started\n",
                 written, range.count(), name);
      return kRuntimeFailure;
    }
    auto frameStart = std::chrono::steady_clock::now();
    double loadSeconds = 0.0;
    RenderResult result;
    try {
      LoadedScene loaded;
      if (f == range.first && first.scene) {
        loaded = std::move(first);
        loadSeconds = firstLoadSeconds;
        frameStart -= std::chrono::duration_cast<std::chrono::steady_clock::duration>(
            std::chrono::duration<double>(loadSeconds));
      } else {
        frameRequest.frame = f;
        loaded = loadFrame(frameRequest, common, animation);
        loadSeconds = secondsSince(frameStart);
      }
      // A frame the checkpoint says was written, and whose file is there, is skipped once
      // it is shown to be this scene's frame.
      if (run.resumed) {
        const auto it = run.resumed->frames.find(f);
        if (it != run.resumed->frames.end() && it->second.written &&
            std::filesystem::exists(name)) {
          const std::vector<std::string> differ = identityDifferences(
              it->second.identity,
              frameIdentity(loaded, f,
                            run.tileSize.value_or(defaultTileSize(loaded.scene->render))));
          if (!differ.empty())
            throw UsageError(fmt::format(
                "--resume: the checkpoint '{}' was made for another scene or other files; {}",
                run.checkpointPath, fmt::join(differ, "; ")));
          if (!run.options.quiet)
            fmt::print(stderr, "lucent: frame {}: '{}' was written before; skipped\n", f, name);
          ++written;
          continue;
        }
      }
      SequencePosition position{written + 1, range.count(), f, animation.frames,
                                secondsSince(run.start)};
      result = renderToFile(std::move(loaded), name, run, position, f, loadSeconds);
    } catch (...) {
      // Reported here, so that the frames written are said after the failure.
      const int status = reportFailure(std::current_exception());
      fmt::print(stderr, "lucent: stopped at frame {}; {} of {} frames written\n", f, written,
                 range.count());
      throw ReportedFailure{status};
    }
    if (result.cancelled) {
      fmt::print(stderr,
                 "lucent: interrupted in frame {}; '{}' left unchanged, {} of {} frames written\n",
                 f, name, written, range.count());
      return kRuntimeFailure;
    }
    ++written;
    totalStats += result.stats;
    totalRender += result.seconds;
    if (run.options.stats) {
      const double seconds = secondsSince(frameStart);
      fmt::print(
          "frame {:>5}: {:10.4f}  s (load {:.4f} s, render {:.4f} s, write and the rest {:.4f} "
          "s)\n",
          f, seconds, loadSeconds, result.seconds,
          std::max(0.0, seconds - loadSeconds - result.seconds));
    }
  }
  // Every frame is written: the checkpoint has served.
  if (run.checkpoint) run.checkpoint->remove();
  if (run.options.stats) {
    RenderResult sum;
    sum.stats = totalStats;
    sum.seconds = totalRender;
    printStats(sum, threadsShown(run.threads));
    const double total = secondsSince(run.start);
    fmt::print("frames:    {:>14}  in {:.3f} s ({}; {:.3f} s a frame, render {:.3f} s of it)\n",
               written, total, formatDuration(total), total / written, totalRender / written);
    // Each file is read once for the run, not once a frame.
    fmt::print("files:     {:>14}  mesh files read, {} image textures loaded, for {} frames\n",
               request.meshCache->reads(), run.textures.loads(), written);
  }
  return kOk;
}

// --region X0,Y0,X1,Y1: four whole numbers, X0 < X1 and Y0 < Y1, none negative.
PixelRect parseRegion(const std::string& text) {
  PixelRect r;
  char c1 = 0, c2 = 0, c3 = 0;
  std::istringstream in(text);
  if (!(in >> r.x0 >> c1 >> r.y0 >> c2 >> r.x1 >> c3 >> r.y1) || c1 != ',' || c2 != ',' ||
      c3 != ',' || !(in >> std::ws).eof())
    throw UsageError(
        fmt::format("--region {}: expected X0,Y0,X1,Y1 (pixel bounds, e.g. 0,0,320,240)", text));
  if (r.x0 < 0 || r.y0 < 0 || r.x1 <= r.x0 || r.y1 <= r.y0)
    throw UsageError(
        fmt::format("--region {}: needs 0 <= X0 < X1 and 0 <= Y0 < Y1 (the right and bottom "
                    "bounds are not part of the region)",
                    text));
  return r;
}

// --region, --tile-size, --checkpoint-interval and --resume.
void setUpTiles(RenderRun& run, const RenderOptions& options, const CommonOptions& common,
                const std::string& output) {
  if (!options.region.empty()) run.region = parseRegion(options.region);
  if (options.tileSize) {
    if (*options.tileSize < 1 || *options.tileSize > kMaxTileSize)
      throw UsageError(
          fmt::format("--tile-size {}: must be 1 to {}", *options.tileSize, kMaxTileSize));
    run.tileSize = *options.tileSize;
  }
  if (options.checkpointInterval) {
    if (!(*options.checkpointInterval >= 0.0) || *options.checkpointInterval > 1e9)
      throw UsageError(
          fmt::format("--checkpoint-interval {}: must be 0 (no checkpoint) or a number of seconds",
                      *options.checkpointInterval));
    run.checkpointInterval = *options.checkpointInterval;
  }
  if (const char* n = std::getenv("LUCENT_TEST_INTERRUPT_AFTER_TILES"))
    run.interruptAfterTiles = std::atol(n);
  run.checkpointPath = checkpointPathFor(output);
  if (options.resume && run.checkpointInterval == 0.0)
    throw UsageError("--resume needs a checkpoint, and --checkpoint-interval 0 keeps none");
  if (run.checkpointInterval == 0.0) return;
  const bool exists = std::filesystem::exists(run.checkpointPath);
  if (options.resume && exists) {
    try {
      run.resumed = readCheckpoint(run.checkpointPath);
    } catch (const CheckpointError& e) {
      throw IoFailure(e.what());
    }
    // The frames' identities are checked as each is loaded.
    const std::vector<std::string> differ =
        identityDifferences(run.resumed->run, runIdentity(options, common, run.region));
    if (!differ.empty())
      throw UsageError(fmt::format("--resume: the checkpoint '{}' was made for another render; {}",
                                   run.checkpointPath, fmt::join(differ, "; ")));
    run.checkpoint.emplace(CheckpointWriter::continuing(run.checkpointPath, *run.resumed));
    return;
  } else if (options.resume) {
    if (!options.quiet)
      fmt::print(stderr, "lucent: no checkpoint '{}' to resume; rendering from the start\n",
                 run.checkpointPath);
  } else if (exists && !options.quiet) {
    fmt::print(stderr,
               "lucent: '{}' holds the checkpoint of an earlier render; it is replaced when this "
               "render saves its own (--resume continues it instead)\n",
               run.checkpointPath);
  }
  run.checkpoint.emplace(run.checkpointPath, runIdentity(options, common, run.region));
}

}  // namespace

std::string defaultRenderOutput(const std::string& scene) {
  return std::filesystem::path(scene).replace_extension(".png").string();
}

int runRender(const RenderOptions& options, const CommonOptions& common,
              const TileExecutor& executor, LoadObserver* observer) {
  // From the start, so a Ctrl-C during parsing still stops the render at its first row.
  InterruptCatcher interrupts;
  const std::string output =
      options.output.empty() ? defaultRenderOutput(options.scene) : options.output;
  SceneRequest request = renderSceneRequest(options);
  checkOverrides(request);
  std::optional<FrameRange> range;
  if (!options.frames.empty()) {
    range = parseFrameRange(options.frames);
    if (picksOneMoment(common))
      throw UsageError(fmt::format("--frames {} and -D {} both choose what to render; give one",
                                   options.frames,
                                   common.defines.count("frame") ? "frame" : "clock"));
  }
  // Before a long render: an output that can never be written is an error now.
  checkImageOutputPath(output);

  RenderRun run{options, executor};
  run.threads = options.threads.value_or(0);
  setUpTiles(run, options, common, output);
  // --threads bounds every parallel step, building the world's BVHs too, not only the
  // tracing: `-t 1` is one thread from start to end.
  std::optional<tbb::global_control> threadLimit;
  if (run.threads > 0)
    threadLimit.emplace(tbb::global_control::max_allowed_parallelism,
                        static_cast<size_t>(run.threads));

  request.meshCache = std::make_shared<MeshFileCache>();
  std::set<std::string> printed;  // the first frame's warnings, not repeated per frame
  request.printed = &printed;
  request.observer = observer;
  // Frame 1 (or the moment -D picks) tells how many frames there are.
  LoadedScene loaded = loadScene(request, common);
  const double firstLoadSeconds = secondsSince(run.start);
  const Animation animation = loaded.scene->animation;
  const bool sequence = animation.present && !picksOneMoment(common);
  if (range)
    checkFrameRange(*range, "--frames " + options.frames, sequence ? animation.frames : 1,
                    sequence);
  if (!options.tileCosts.empty() && sequence && (!range || range->count() != 1))
    throw UsageError("--tile-costs records the tiles of one frame: give --frames F or -D frame=F");
  if (sequence) {
    const FrameRange frames = range.value_or(FrameRange{1, animation.frames});
    // The numbered names must be writable too (a '#' run may change the extension's place).
    checkImageOutputPath(frameOutputPath(output, frames.first, animation.frames));
    if (frames.first != 1) loaded = {};
    return renderFrames(std::move(loaded), firstLoadSeconds, animation, frames, request, common,
                        output, run);
  }

  RenderResult result =
      renderToFile(std::move(loaded), output, run, std::nullopt, 1, firstLoadSeconds);
  if (result.cancelled) {
    // The output is left as it was (docs/security.md: a render writes only its output
    // image, that image's temporary file and its checkpoint).
    fmt::print(stderr, "lucent: interrupted; '{}' left unchanged\n", output);
    return kRuntimeFailure;
  }
  if (options.stats) printStats(result, threadsShown(run.threads));
  return kOk;
}

}  // namespace lucent::cli
