#include "worker.h"

#include "file_bundle.h"
#include "messages.h"
#include "tile_message.h"

#include "interrupt_catcher.h"
#include "load_scene.h"

#include "meshes/mesh_file_cache.h"
#include "render/image_map_cache.h"
#include "render/renderer.h"

#include <fmt/core.h>
#include <tbb/global_control.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>

namespace fs = std::filesystem;

namespace lucent::mpi {

namespace {

// The folder this worker keeps its copies in, removed when the worker ends.
class PrivateFolder {
 public:
  PrivateFolder() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = (tmp && *tmp ? std::string(tmp) : std::string("/tmp")) + "/lucent-mpi-XXXXXX";
    if (!::mkdtemp(pattern.data()))
      throw cli::IoFailure(fmt::format("cannot make a temporary folder '{}' for the scene's files", pattern));
    path_ = canonicalPath(pattern);
  }
  ~PrivateFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::vector<char> text(const std::string& s) {
  Writer w;
  w.putString(s);
  return std::move(w.bytes);
}

// Renders the frame's tiles until rank 0 has no more; false if the run ends meanwhile.
bool renderFrame(const cli::LoadedScene& loaded, int frame, ImageMapCache& textures) {
  World world(*loaded.scene);
  Renderer renderer(world, *loaded.camera, &textures);
  RenderControl control;
  control.cancel = &cli::InterruptCatcher::flag();
  send(0, kReady, {});
  for (Message m;;) {
    if (!receive(0, m, control.cancel)) return false;
    if (m.tag == kNoMore) return true;
    if (m.tag == kStop) return false;
    const TileOrder order = unpackOrder(m.bytes);
    TileResult t{frame, order.index, renderer.renderRect(order.rect, control)};
    if (t.result.cancelled) return false;
    send(0, kResult, pack(t));
  }
}

}  // namespace

int runWorker(const cli::RenderOptions& options, const cli::CommonOptions& common) {
  // mpirun ends a job that lost a rank with SIGTERM: the folder is removed on the way out.
  cli::InterruptCatcher interrupts;
  std::optional<tbb::global_control> threadLimit;
  if (options.threads && *options.threads > 0)
    threadLimit.emplace(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(*options.threads));
  PrivateFolder folder;
  auto meshes = std::make_shared<MeshFileCache>();
  ImageMapCache textures;
  std::vector<FileGrant> grants;
  for (Message m;;) {
    if (!receive(0, m, &cli::InterruptCatcher::flag())) return cli::kRuntimeFailure;
    if (m.tag == kStop) return cli::kOk;
    if (m.tag != kFrame) continue;  // a late kNoMore of a cancelled frame
    cli::LoadedScene loaded;
    int frame = 1;
    try {
      const FileBundle bundle = unpack(m.bytes);
      frame = bundle.frame;
      materialise(bundle, folder.path());
      auto replay = std::make_shared<FileReplay>();
      replay->root = folder.path();
      replay->grants = bundle.grants;
      cli::SceneRequest request = cli::renderSceneRequest(options);
      request.scene = (folder.path() / bundle.scene.relative_path()).string();
      request.frame = frame;
      request.meshCache = meshes;
      request.replay = replay;
      request.quiet = true;
      loaded = cli::loadScene(request, common);
    } catch (const cli::ReportedFailure&) {
      send(0, kFailed, text("its messages are above"));
      continue;
    } catch (const std::exception& e) {
      send(0, kFailed, text(e.what()));
      continue;
    }
    if (!renderFrame(loaded, frame, textures)) return cli::kRuntimeFailure;
  }
}

}  // namespace lucent::mpi
