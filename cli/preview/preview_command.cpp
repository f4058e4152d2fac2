// lucent preview SCENE: a live render of the scene in the browser, rendered again on every
// save (docs/preview.md). A web server (http_server.h, a plugin) serves one page and the
// board of what it shows (preview_board.h); each render loads the scene as `render` does
// (load_scene.h), sends the coarse passes and tiles (preview_render.h), then the scene's
// files are watched (change_relay.h) until the next save or Ctrl-C.
#include "commands.h"

#include "browser_open.h"
#include "change_relay.h"
#include "compare_arguments.h"
#include "file_watcher.h"
#include "http_server.h"
#include "json_text.h"
#include "last_image.h"
#include "pov_comparison.h"
#include "preview_board.h"
#include "preview_controls.h"
#include "preview_render.h"
#include "preview_routes.h"
#include "preview_status.h"
#include "preview_token.h"
#include "watch_list.h"

#include "frame_loading.h"
#include "interrupt_catcher.h"
#include "load_pov_scene.h"
#include "load_scene.h"
#include "render_run.h"
#include "render_stats.h"

#include "meshes/mesh_file_cache.h"

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include <malloc.h>

namespace lucent::cli {

namespace {

namespace fs = std::filesystem;
using namespace lucent::preview;

SceneRequest previewRequest(const PreviewOptions& options) { return sceneRequestOf(options); }

// Bad options, a missing scene: refused before anything is served.
void checkPreviewOptions(const PreviewOptions& options, const SceneRequest& request) {
  checkOverrides(request);
  if (options.port && (*options.port < 1 || *options.port > 65535))
    throw UsageError(
        fmt::format("--port {}: must be 1 to 65535 (or none: a free port)", *options.port));
  std::error_code ec;
  if (!fs::is_regular_file(options.scene, ec))
    throw IoFailure(fmt::format("cannot read the scene '{}': {}", options.scene,
                                fs::exists(options.scene, ec) ? "not a file" : "no such file"));
}

std::string addressOf(const std::string& host, int port, const std::string& token) {
  const bool v6 = host.find(':') != std::string::npos;
  return fmt::format("http://{}{}{}:{}/?token={}", v6 ? "[" : "", host, v6 ? "]" : "", port, token);
}

// The files that decide the render besides those the scene reads: the scene itself (even
// when it does not load) and --pov-ini's file.
WatchList alwaysWatched(const PreviewOptions& options, const CommonOptions& common) {
  WatchList list;
  list.add(options.scene);
  std::error_code ec;
  const fs::path real = fs::canonical(options.scene, ec);
  if (!ec) list.add(real);
  if (!common.povIni.empty()) list.add(common.povIni.substr(0, common.povIni.find('[')));
  return list;
}

struct Session {
  const PreviewOptions& options;
  const CommonOptions& common;
  PreviewBoard& board;
  LastImage& last;
  PreviewControls& controls;
  std::atomic<bool>& cancel;
  std::string compareDir;  // --compare: the folder of its reports
  PreviewStatus status;
};

// --compare, after a finished render of the whole image: POV-Ray's render and the
// difference, sent to the page (or why they could not be made).
void compareForPage(Session& s, const CommonOptions& common) {
  s.status.phase = "comparing";
  s.board.publishStatus(s.status.json());
  PreviewOptions options = s.options;
  options.samples = s.status.samples;
  const Comparison c = runComparison(
      compareArguments(options, common, s.status.width, s.status.height), s.compareDir, s.cancel);
  s.status.phase = "done";
  if (c.cancelled) return;
  s.board.publishComparison(fmt::format(
      "{{\"generation\":{},\"povray\":\"{}\",\"diff\":\"{}\",\"report\":{},\"error\":{}}}",
      s.status.generation, base64(c.povrayPng), base64(c.diffPng), jsonString(c.report),
      jsonString(c.error)));
}

// The sliders' values over the command line's -D values; the status told what they are.
CommonOptions withControls(Session& s) {
  s.status.parameters = isPovScene(s.options.scene, s.common.format)
                            ? std::vector<SceneParameter>{}
                            : numericParameters(s.options.scene);
  // Only what the scene still has: a parameter removed by a save is no longer set.
  CommonOptions common = s.common;
  for (const auto& [name, value] : s.controls.values())
    if (name == "samples") continue;  // not a -D value (previewRequest takes it)
    else if (name == "frame" ||
             std::any_of(s.status.parameters.begin(), s.status.parameters.end(),
                         [&](const SceneParameter& p) { return p.name == name; }))
      common.defines[name] = value;
  s.status.values.clear();
  for (const SceneParameter& p : s.status.parameters) {
    const auto given = common.defines.find(p.name);
    s.status.values.push_back(given != common.defines.end() ? given->second
                                                            : fmt::format("{}", p.declared));
  }
  const auto frame = common.defines.find("frame");
  s.status.frame = frame != common.defines.end() ? std::atoi(frame->second.c_str()) : 1;
  return common;
}

// The frames the page may choose among: none when -D fixes the moment.
int framesToChoose(const Session& s, const LoadedScene& loaded) {
  if (!loaded.scene->animation.present || picksOneMoment(s.common)) return 0;
  return loaded.scene->animation.frames;
}

// Loads and renders the scene once for the page; the files it read.
WatchList renderOnce(Session& s, int generation) {
  PreviewRun run{s.board,
                 s.status,
                 s.cancel,
                 s.options.threads.value_or(0),
                 std::chrono::steady_clock::now(),
                 std::nullopt,
                 nullptr,
                 {}};
  s.status.generation = generation;
  s.status.phase = "loading";
  s.status.done = s.status.total = 0;
  s.status.seconds = 0.0;
  const CommonOptions common = withControls(s);
  run.region = s.controls.region();
  run.previous = s.last.get();
  s.status.region = run.region ? fmt::format("{},{},{},{}", run.region->x0, run.region->y0,
                                             run.region->x1, run.region->y1)
                               : "";
  s.board.publishStatus(s.status.json());
  std::vector<std::string> messages;  // as `check` prints them
  SceneRequest request = previewRequest(s.options);
  if (const auto values = s.controls.values(); values.count("samples"))
    request.samples = std::atoi(values.at("samples").c_str());
  request.heldMessages = &messages;
  request.meshCache = std::make_shared<MeshFileCache>();
  WatchList read;
  try {
    LoadedScene loaded = loadScene(request, common);
    read.add(loaded.sources);
    read.add(loaded.dataFiles);
    s.status.frames = framesToChoose(s, loaded);
    s.status.samples = loaded.scene->render.samples;
    s.controls.offer(s.status.parameters, s.status.frames);
    s.status.messages = fmt::format("{}", fmt::join(messages, "\n"));
    PreviewOutcome out = renderForPage(loaded, run);
    s.status.phase = out.cancelled ? "cancelled" : "done";
    if (!out.cancelled) {
      s.status.stats = renderStatsText(out.stats, out.seconds, threadsShown(run.threads));
      s.last.set(std::move(out.image), loaded.scene->render.workingGamma);
      if (s.options.compare && s.status.region.empty()) compareForPage(s, common);
    }
  } catch (...) {
    const Failure failure = describeFailure(std::current_exception());
    if (!failure.message.empty()) messages.push_back(failure.message);
    s.status.phase = "invalid";
    s.status.messages = fmt::format("{}", fmt::join(messages, "\n"));
    fmt::print(stderr, "{}\n", s.status.messages);
  }
  s.status.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - run.start).count();
  s.board.publishStatus(s.status.json());
  // What the render freed goes back to the system: a preview runs for hours of saves.
  ::malloc_trim(0);
  return read;
}

// Renders, then waits for a save or a slider, until Ctrl-C.
void previewLoop(Session& s, FileWatcher& watcher, ChangeRelay& relay) {
  const WatchList always = alwaysWatched(s.options, s.common);
  watcher.watch(always);
  for (int generation = 1;; ++generation) {
    relay.renderStarts();
    WatchList watched = renderOnce(s, generation);
    watched.merge(always);
    watcher.watch(watched);
    if (!relay.waitForChange()) return;
  }
}

// The server on the options' address; IoFailure when it cannot listen there.
std::unique_ptr<HttpServer> startServer(const PreviewOptions& options, HttpHandler handler) {
  try {
    return startHttpServer({options.bind, options.port.value_or(0), std::move(handler)});
  } catch (const std::runtime_error& e) {
    throw IoFailure(fmt::format("cannot serve the preview on {} port {}: {}", options.bind,
                                options.port ? std::to_string(*options.port) : "(any)", e.what()));
  }
}

}  // namespace

int runPreview(const PreviewOptions& options, const CommonOptions& common) {
  InterruptCatcher interrupts;
  const SceneRequest request = previewRequest(options);
  checkPreviewOptions(options, request);
  PreviewBoard board;
  LastImage last(defaultRenderOutput(options.scene));
  PreviewControls controls;
  std::atomic<bool> cancel{false};
  FileWatcher watcher;
  ChangeRelay relay(watcher, cancel);
  const std::string token = makeToken();
  std::unique_ptr<HttpServer> server = startServer(
      options, previewRoutes(token, {board, last, controls, [&relay] { relay.poke(); }}));
  const std::string address = addressOf(options.bind, server->port(), token);
  fmt::print("lucent: preview of '{}' at {}\n", options.scene, address);
  fmt::print(
      "lucent: rendered again on every save of the scene or a file it reads; Ctrl-C stops\n");
  std::fflush(stdout);
  if (options.open) openInBrowser(address);
  // However the loop ends: the page's streams end, then the server's threads.
  struct Closing {
    PreviewBoard& board;
    HttpServer& server;
    ~Closing() {
      board.close();
      server.stop();
    }
  } closing{board, *server};
  // --compare's reports, in a folder of this run's own, removed at the end.
  struct CompareFolder {
    std::string path;
    ~CompareFolder() {
      std::error_code ec;
      if (!path.empty()) fs::remove_all(path, ec);
    }
  } compareFolder;
  if (options.compare) {
    std::string pattern = (fs::temp_directory_path() / "lucent-preview-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw IoFailure("cannot make a folder for --compare's reports");
    compareFolder.path = pattern;
  }
  Session session{options, common, board, last, controls, cancel, compareFolder.path, {}};
  session.status.scene = options.scene;
  previewLoop(session, watcher, relay);
  fmt::print(stderr, "lucent: preview stopped\n");
  return kOk;
}

}  // namespace lucent::cli
