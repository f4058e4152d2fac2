#include "load_scene.h"

#include "exit_status.h"
#include "load_pov_scene.h"

#include "lang/parser.h"
#include "register.h"
#include "render/scene_check.h"

#include <fmt/core.h>

#include <cstdio>

namespace lucent::cli {

namespace {

std::string cameraNames(const Scene& scene) {
  std::string names;
  for (const Camera& c : scene.cameras) {
    if (c.name.empty()) continue;
    names += (names.empty() ? "" : ", ") + c.name;
  }
  return names.empty() ? "the scene's cameras have no names" : "cameras: " + names;
}

}  // namespace

void checkOverrides(const SceneRequest& request) {
  for (auto [value, name] :
       {std::pair{request.width, "--width"}, std::pair{request.height, "--height"},
        std::pair{request.samples, "--samples"}, std::pair{request.threads, "--threads"},
        std::pair{request.maxDepth, "--max-depth"}})
    if (auto problem = overrideProblem(name, value)) throw UsageError(*problem);
}

LoadedScene loadScene(const SceneRequest& request, const CommonOptions& common) {
  checkOverrides(request);
  registerPovLibrary();  // `pov:` names in XML scenes

  ParseOptions options;
  options.defines = common.defines;
  options.allowPaths = common.allowPaths;
  options.frame = request.frame;
  options.meshCache = request.meshCache;
  options.replay = request.replay;
  if (request.observer) {
    request.observer->loading(request.frame, request.scene);
    options.onGrant = [o = request.observer](const FileGrant& g) { o->granted(g); };
  }
  auto say = [&](const std::string& line) {
    if (request.heldMessages) request.heldMessages->push_back(line);
    else fmt::print(stderr, "{}\n", line);
  };
  ParseResult parsed = isPovScene(request.scene, common.format)
                           ? parsePovScene(request, common)
                           : parseSceneFile(request.scene, options);
  for (const Diagnostic& d : parsed.diagnostics.all()) {
    if (request.quiet && d.severity != Severity::Error) continue;
    std::string line = d.str();
    if (request.printed && !request.printed->insert(line).second) continue;
    say(line);
  }
  if (parsed.ioFailure) throw ReportedFailure{kRuntimeFailure};  // the scene file is unreadable
  if (!parsed.scene) {
    const size_t n = parsed.diagnostics.errorCount();
    say(fmt::format("{}: {} error{}; the scene is invalid", request.scene, n, n == 1 ? "" : "s"));
    // Later frames are named by the caller (frame_loading.cpp); the first one read, here.
    if (parsed.animation.present && request.frame == 1)
      say(fmt::format("lucent: frame {} of {} (clock {}) is invalid", parsed.frame,
                      parsed.animation.frames, parsed.clock));
    throw ReportedFailure{kInvalidScene};
  }

  LoadedScene loaded;
  loaded.scene = std::move(parsed.scene);
  loaded.sources = std::move(parsed.sources);
  loaded.dataFiles = std::move(parsed.dataFiles);
  loaded.grants = std::move(parsed.grants);
  loaded.xmlDigest = parsed.xmlDigest;
  Scene& scene = *loaded.scene;
  RenderSettings& r = scene.render;
  if (request.width) r.width = *request.width;
  if (request.height) r.height = *request.height;
  if (request.samples) {
    r.samples = *request.samples;
    // -s asks for that many samples a pixel: corner sampling, which chooses its own (and
    // whose threshold is on another scale), gives way to plain supersampling.
    if (r.adaptiveMode == AdaptiveMode::Corners) {
      r.adaptiveMode = AdaptiveMode::Centres;
      r.adaptive = 0.0;
    }
  }
  if (request.maxDepth) r.maxDepth = *request.maxDepth;

  loaded.camera = scene.findCamera(request.camera);
  if (!loaded.camera)  // the parser requires a camera: only a --camera name can miss
    throw UsageError(fmt::format("--camera {}: no camera of that name in '{}' ({})", request.camera,
                                 request.scene, cameraNames(scene)));

  checkRenderable(scene, *loaded.camera);
  return loaded;
}

}  // namespace lucent::cli
