#include "tile_dispatch.h"

#include "file_bundle.h"
#include "messages.h"
#include "tile_message.h"

#include "exit_status.h"

#include "lang/file_access.h"

#include <fmt/core.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

namespace lucent::mpi {

void TileDispatch::sendAll(int tag, const std::vector<char>& bytes) {
  if (ranks() > 1) broadcast(static_cast<Tag>(tag), bytes);
}

void TileDispatch::loading(int frame, const std::filesystem::path& scene) {
  if (ranks() == 1) return;
  if (loadingFrame_) sendAll(kNoMore, {});  // the frame loaded before is not rendered
  scene_ = canonicalPath(scene);
  loadingFrame_ = frame;
  FileBundle b;
  try {
    b = makeBundle(frame, scene_, {}, {scene_}, sent_);
  } catch (const cli::IoFailure&) {
    b = makeBundle(frame, scene_, {}, {}, sent_);  // rank 0's own parse says what is wrong
  }
  sendAll(kFrame, pack(b));
}

void TileDispatch::granted(const FileGrant& grant) {
  if (!loadingFrame_ || std::this_thread::get_id() != mainThread_) return;
  FileBundle b;
  try {
    b = makeBundle(*loadingFrame_, scene_, {grant}, {grant.canonical}, sent_);
  } catch (const cli::IoFailure&) {
    b = makeBundle(*loadingFrame_, scene_, {grant}, {}, sent_);
  }
  sendAll(kFile, pack(b));
}

// One frame's tiles as they are handed out: the next in row order for whoever asks first,
// each result reported as renderTiles would (one at a time, its counts summed).
class FrameTiles {
 public:
  FrameTiles(const Renderer& renderer, const std::vector<PixelRect>& tiles,
             const std::vector<char>& skip, const RenderControl& control,
             const TileFinished& finished)
      : renderer_(renderer),
        tiles_(tiles),
        toDo_(tilesToDo(renderer, tiles, skip)),
        control_(control),
        inner_(tileControl(control, toDo_.work, localProgress_)),
        finished_(finished) {}

  bool cancelled() const {
    return control_.cancel && control_.cancel->load(std::memory_order_relaxed);
  }
  // The index of the next tile to render, none when all are handed out or the render is
  // cancelled.
  std::optional<size_t> take() {
    if (cancelled()) return std::nullopt;
    const size_t k = next_.fetch_add(1);
    if (k >= toDo_.indices.size()) return std::nullopt;
    return toDo_.indices[k];
  }
  // No tile is handed out after this.
  void stop() { next_ = toDo_.indices.size(); }
  // Rank 0's own share: tiles rendered here until none is left.
  void renderHere() {
    auto loop = [&] {
      while (std::optional<size_t> i = take()) report(*i, renderer_.renderRect(tiles_[*i], inner_));
    };
    if (control_.threads > 0) {
      tbb::task_arena arena(control_.threads);
      arena.execute(loop);
    } else {
      loop();
    }
  }
  // A worker's tile: counted into the progress here, as a local tile counts itself.
  void reportFromWorker(size_t i, const RenderResult& tile) {
    inner_.progress->workDone += renderer_.work(tiles_[i]);
    inner_.progress->rays += tile.stats.rays();
    report(i, tile);
  }
  TileRenderResult& result() { return result_; }

 private:
  void report(size_t i, const RenderResult& tile) {
    std::lock_guard<std::mutex> lock(reporting_);  // `finished` is called one at a time
    result_.stats += tile.stats;
    if (!tile.cancelled) finished_(i, tile);
  }

  const Renderer& renderer_;
  const std::vector<PixelRect>& tiles_;
  const TilesToDo toDo_;
  const RenderControl& control_;
  RenderProgress localProgress_;
  const RenderControl inner_;
  const TileFinished& finished_;
  std::atomic<size_t> next_{0};
  std::mutex reporting_;
  TileRenderResult result_;
};

void TileDispatch::sendLoaded(const cli::LoadedScene& loaded, int frame) {
  if (loadingFrame_ != frame) loading(frame, scene_);
  std::vector<std::filesystem::path> files = loaded.sources;
  files.insert(files.end(), loaded.dataFiles.begin(), loaded.dataFiles.end());
  std::vector<char> bundle = pack(makeBundle(frame, scene_, loaded.grants, files, sent_));
  loadingFrame_.reset();
  sendAll(kLoaded, bundle);
  for (int w = 1; w < ranks(); ++w) busy_.insert(w);
}

// Each worker asks (kReady, or with a result) and gets a tile, so that it holds two: the
// one it renders and the next, already there when it finishes (a round trip through this
// polling thread costs a cheap tile's worth of time). Once there are none and its last is
// back, it gets kNoMore.
void TileDispatch::serveWorkers(FrameTiles& tiles, const std::vector<PixelRect>& rects, int frame,
                                const std::atomic<bool>* cancel) {
  constexpr int kHeld = 2;
  std::map<int, int> held;  // tiles sent to a worker and not yet back
  Message m;
  while (!busy_.empty() && !tiles.cancelled()) {
    if (!receive(-1, m, cancel)) break;
    if (m.tag == kFailed) {
      busy_.erase(m.source);
      Reader r(m.bytes);
      throw cli::IoFailure(
          fmt::format("rank {} could not load frame {}: {}", m.source, frame, r.getString()));
    }
    if (m.tag == kResult) {
      TileResult t = unpackResult(m.bytes);
      if (t.frame != frame || t.index >= rects.size())
        throw cli::IoFailure(fmt::format("rank {} sent a tile that was not asked of it", m.source));
      tiles.reportFromWorker(t.index, t.result);
      --held[m.source];
    } else if (m.tag != kReady) {
      throw cli::IoFailure(fmt::format("rank {} sent an unexpected message ({})", m.source, m.tag));
    }
    while (held[m.source] < kHeld) {
      const std::optional<size_t> i = tiles.take();
      if (!i) break;
      send(m.source, kTile, pack(TileOrder{frame, *i, rects[*i]}));
      ++held[m.source];
    }
    if (held[m.source] == 0) {
      send(m.source, kNoMore, {});
      busy_.erase(m.source);
    }
  }
}

TileRenderResult TileDispatch::operator()(const Renderer& renderer, const cli::LoadedScene& loaded,
                                          int frame, const std::vector<PixelRect>& rects,
                                          const std::vector<char>& skip,
                                          const RenderControl& control, bool /*oneAtATime: each rank
                                          renders one tile at a time anyway*/
                                          ,
                                          const TileFinished& finished) {
  const auto start = std::chrono::steady_clock::now();
  FrameTiles tiles(renderer, rects, skip, control, finished);
  // The workers have parsed the frame too, from the files streamed while rank 0 parsed
  // it (loading, granted): kLoaded completes them, with every name the parse was granted.
  if (ranks() > 1) sendLoaded(loaded, frame);
  // Rank 0 renders tiles too, on a thread of its own.
  std::thread local([&] { tiles.renderHere(); });
  std::optional<std::string> failure;
  try {
    serveWorkers(tiles, rects, frame, control.cancel);
  } catch (const std::exception& e) {
    failure = e.what();
  }
  if (failure) tiles.stop();  // the local thread stops after its tile
  local.join();
  if (failure) throw cli::IoFailure(*failure);
  TileRenderResult& result = tiles.result();
  result.cancelled = tiles.cancelled();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void TileDispatch::stopWorkers() {
  loadingFrame_.reset();
  sendAll(kStop, {});
}

}  // namespace lucent::mpi
