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
    std::string pattern =
        (tmp && *tmp ? std::string(tmp) : std::string("/tmp")) + "/lucent-mpi-XXXXXX";
    if (!::mkdtemp(pattern.data()))
      throw cli::IoFailure(
          fmt::format("cannot make a temporary folder '{}' for the scene's files", pattern));
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
  PendingSend result;
  for (Message m;;) {
    if (!receive(0, m, control.cancel)) return false;
    if (m.tag == kNoMore) return true;
    const TileOrder order = unpackOrder(m.bytes);
    TileResult t{frame, order.index, renderer.renderRect(order.rect, control)};
    if (t.result.cancelled) return false;
    result.start(0, kResult, pack(t));
  }
}

// The files of the frame being loaded, as rank 0 streams them (messages.h): each message
// adds names (and copies) to the replay the parse resolves names by, until kLoaded
// completes them, or kNoMore (rank 0 does not render the frame) or kStop ends the wait.
class StreamedFiles {
 public:
  enum class State { Loading, Loaded, Abandoned, Stopped };

  StreamedFiles(const fs::path& root, std::shared_ptr<FileReplay> replay)
      : root_(root), replay_(std::move(replay)) {}

  // Takes the next message from rank 0; false once the frame's files are complete or the
  // wait has ended.
  bool next() {
    if (state_ != State::Loading) return false;
    Message m;
    receiveBroadcast(m);
    if (m.tag != kFile && m.tag != kLoaded) {
      state_ = m.tag == kNoMore ? State::Abandoned : State::Stopped;  // kStop
      return false;
    }
    const FileBundle b = unpack(m.bytes);
    materialise(b, root_);
    replay_->grants.insert(replay_->grants.end(), b.grants.begin(), b.grants.end());
    if (m.tag == kLoaded) state_ = State::Loaded;
    return true;
  }
  State state() const { return state_; }

 private:
  fs::path root_;
  std::shared_ptr<FileReplay> replay_;
  State state_ = State::Loading;
};

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines) out += "\n" + l;
  return out;
}

}  // namespace

int runWorker(const cli::RenderOptions& options, const cli::CommonOptions& common) {
  // mpirun ends a job that lost a rank with SIGTERM: the folder is removed on the way out.
  cli::InterruptCatcher interrupts;
  std::optional<tbb::global_control> threadLimit;
  if (options.threads && *options.threads > 0)
    threadLimit.emplace(tbb::global_control::max_allowed_parallelism,
                        static_cast<size_t>(*options.threads));
  PrivateFolder folder;
  auto meshes = std::make_shared<MeshFileCache>();
  ImageMapCache textures;
  for (Message m;;) {
    receiveBroadcast(m);  // kFrame or kStop
    if (m.tag == kStop) return cli::kOk;
    if (m.tag != kFrame) continue;
    // The frame is parsed while rank 0 parses it, each file name waited for as it is
    // needed; whether it is rendered, rank 0 says after its own parse.
    auto replay = std::make_shared<FileReplay>();
    replay->root = folder.path();
    StreamedFiles files(folder.path(), replay);
    replay->more = [&files] { return files.next(); };
    cli::LoadedScene loaded;
    std::vector<std::string> messages;
    std::optional<std::string> failure;
    int frame = 1;
    try {
      const FileBundle bundle = unpack(m.bytes);
      frame = bundle.frame;
      materialise(bundle, folder.path());
      cli::SceneRequest request = cli::renderSceneRequest(options);
      request.scene = (folder.path() / bundle.scene.relative_path()).string();
      request.frame = frame;
      request.meshCache = meshes;
      request.replay = replay;
      request.quiet = true;
      request.heldMessages = &messages;
      loaded = cli::loadScene(request, common);
    } catch (const cli::ReportedFailure&) {
      failure = messages.empty() ? std::string("it could not parse the scene") : joined(messages);
    } catch (const std::exception& e) {
      failure = e.what();
    }
    while (files.next()) {
    }
    switch (files.state()) {
      case StreamedFiles::State::Stopped:
        return cli::kOk;
      case StreamedFiles::State::Abandoned:
        continue;
      case StreamedFiles::State::Loading:
      case StreamedFiles::State::Loaded:
        break;
    }
    if (failure) {
      send(0, kFailed, text(*failure));
      continue;
    }
    if (!renderFrame(loaded, frame, textures)) return cli::kRuntimeFailure;
  }
}

}  // namespace lucent::mpi
