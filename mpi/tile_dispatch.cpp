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

TileRenderResult TileDispatch::operator()(const Renderer& renderer, const cli::LoadedScene& loaded,
                                          int frame, const std::vector<PixelRect>& tiles,
                                          const std::vector<char>& skip,
                                          const RenderControl& control, bool /*oneAtATime: each rank
                                          renders one tile at a time anyway*/
                                          ,
                                          const TileFinished& finished) {
  const auto start = std::chrono::steady_clock::now();
  const TilesToDo toDo = tilesToDo(renderer, tiles, skip);
  const std::vector<size_t>& todo = toDo.indices;
  RenderProgress localProgress;
  const RenderControl inner = tileControl(control, toDo.work, localProgress);
  auto cancelled = [&] {
    return control.cancel && control.cancel->load(std::memory_order_relaxed);
  };

  // Row order, as renderTiles: the next tile for whoever asks first.
  std::atomic<size_t> next{0};
  auto take = [&]() -> std::optional<size_t> {
    if (cancelled()) return std::nullopt;
    const size_t k = next.fetch_add(1);
    if (k >= todo.size()) return std::nullopt;
    return todo[k];
  };
  TileRenderResult result;
  std::mutex reporting;  // `finished` is called one at a time
  auto report = [&](size_t i, const RenderResult& tile) {
    std::lock_guard<std::mutex> lock(reporting);
    result.stats += tile.stats;
    if (!tile.cancelled) finished(i, tile);
  };

  // The workers have parsed the frame too, from the files streamed while rank 0 parsed
  // it (loading, granted): kLoaded completes them, with every name the parse was granted.
  const int workers = ranks() - 1;
  if (workers > 0) {
    if (loadingFrame_ != frame) loading(frame, scene_);
    std::vector<char> bundle = pack(makeBundle(
        frame, scene_, loaded.grants,
        [&] {
          std::vector<std::filesystem::path> files = loaded.sources;
          files.insert(files.end(), loaded.dataFiles.begin(), loaded.dataFiles.end());
          return files;
        }(),
        sent_));
    loadingFrame_.reset();
    sendAll(kLoaded, bundle);
    for (int w = 1; w <= workers; ++w) busy_.insert(w);
  }

  // Rank 0 renders tiles too, on a thread of its own.
  std::thread local([&] {
    auto loop = [&] {
      while (std::optional<size_t> i = take()) report(*i, renderer.renderRect(tiles[*i], inner));
    };
    if (control.threads > 0) {
      tbb::task_arena arena(control.threads);
      arena.execute(loop);
    } else {
      loop();
    }
  });

  // Each worker asks (kReady, or with a result) and gets a tile, so that it holds two: the
  // one it renders and the next, already there when it finishes (a round trip through
  // this polling thread costs a cheap tile's worth of time). Once there are none and its
  // last is back, it gets kNoMore.
  constexpr int kHeld = 2;
  std::map<int, int> held;  // tiles sent to a worker and not yet back
  std::optional<std::string> failure;
  try {
    Message m;
    while (!busy_.empty() && !cancelled()) {
      if (!receive(-1, m, control.cancel)) break;
      if (m.tag == kFailed) {
        busy_.erase(m.source);
        Reader r(m.bytes);
        throw cli::IoFailure(
            fmt::format("rank {} could not load frame {}: {}", m.source, frame, r.getString()));
      }
      if (m.tag == kResult) {
        TileResult t = unpackResult(m.bytes);
        if (t.frame != frame || t.index >= tiles.size())
          throw cli::IoFailure(
              fmt::format("rank {} sent a tile that was not asked of it", m.source));
        inner.progress->workDone += renderer.work(tiles[t.index]);
        inner.progress->rays += t.result.stats.rays();
        report(t.index, t.result);
        --held[m.source];
      } else if (m.tag != kReady) {
        throw cli::IoFailure(
            fmt::format("rank {} sent an unexpected message ({})", m.source, m.tag));
      }
      while (held[m.source] < kHeld) {
        const std::optional<size_t> i = take();
        if (!i) break;
        send(m.source, kTile, pack(TileOrder{frame, *i, tiles[*i]}));
        ++held[m.source];
      }
      if (held[m.source] == 0) {
        send(m.source, kNoMore, {});
        busy_.erase(m.source);
      }
    }
  } catch (const std::exception& e) {
    failure = e.what();
  }
  if (failure) next = todo.size();  // the local thread stops after its tile
  local.join();
  if (failure) throw cli::IoFailure(*failure);
  result.cancelled = cancelled();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void TileDispatch::stopWorkers() {
  loadingFrame_.reset();
  sendAll(kStop, {});
}

}  // namespace lucent::mpi
