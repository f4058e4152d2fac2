// The sequence every command that reads a scene starts with, written once: parse it,
// print its diagnostics, check and apply the command-line overrides, pick the camera and
// check what rendering would refuse, so that `check` refuses what `render` refuses.
#pragma once

#include "commands.h"

#include "lang/file_access.h"
#include "scenegraph/scene.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace lucent {
class MeshFileCache;
}

namespace lucent::cli {

class LoadObserver {
 public:
  virtual ~LoadObserver() = default;
  virtual void loading(int frame, const std::filesystem::path& scene) = 0;
  virtual void granted(const FileGrant& grant) = 0;
};

struct SceneRequest {
  std::string scene;
  // Each replaces the scene's <render> value; -t is checked only (it is not in the scene).
  std::optional<int> width, height, samples, threads, maxDepth;
  std::string camera;  // --camera; empty: the scene's first camera
  int frame = 1;       // of an animated scene (ParseOptions::frame)
  // Shared by the loads of one process (the frames of an animation); null: none.
  std::shared_ptr<MeshFileCache> meshCache;
  // Diagnostics already printed (by an earlier frame's load), not to be printed again;
  // null: print all.
  std::set<std::string>* printed = nullptr;
  // A process of a distributed render: the scene's files are copies (ParseOptions::replay),
  // and its warnings are the first process's to print (`quiet`).
  std::shared_ptr<const FileReplay> replay;
  bool quiet = false;
  // Set: the messages a failed load prints are kept here instead (a worker of lucent-mpi
  // sends them to rank 0, or drops them when rank 0 failed the same way).
  std::vector<std::string>* heldMessages = nullptr;
  // Told when the parse starts and of each file name it is granted (ParseOptions::onGrant):
  // lucent-mpi's rank 0 streams the files to the workers while all of them parse.
  LoadObserver* observer = nullptr;
};

struct LoadedScene {
  std::unique_ptr<Scene> scene;
  const Camera* camera = nullptr;  // in *scene
  // What the scene was made of (ParseResult::sources, dataFiles and xmlDigest): a
  // checkpoint's identity, and what a distributed render sends to the other processes.
  std::vector<std::filesystem::path> sources, dataFiles;
  std::vector<FileGrant> grants;  // the names they were read by (ParseResult::grants)
  uint64_t xmlDigest = 0;
};

// The scene request a command makes of its options (the scene, its overrides): render's,
// compare's and preview's options share these fields.
template <class Options>
SceneRequest sceneRequestOf(const Options& options) {
  SceneRequest request;
  request.scene = options.scene;
  request.width = options.width;
  request.height = options.height;
  request.samples = options.samples;
  request.threads = options.threads;
  request.maxDepth = options.maxDepth;
  request.camera = options.camera;
  return request;
}
inline SceneRequest renderSceneRequest(const RenderOptions& options) {
  return sceneRequestOf(options);
}

// Throws UsageError for an override out of range (the first thing loadScene does, and
// callable before it, to refuse a bad option before an output is looked at).
void checkOverrides(const SceneRequest& request);

// Warnings are always printed (-q hides progress, not what is wrong with the scene).
// Throws UsageError (an override out of range, an unknown --camera), ReportedFailure
// (parse errors, printed), LocatedError (a camera that cannot form an image at this size,
// transforms beyond range, an image texture whose header cannot be read).
LoadedScene loadScene(const SceneRequest& request, const CommonOptions& common);

}  // namespace lucent::cli
