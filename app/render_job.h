// A render job: one frame's image as the command renders it. The image (or --region's part
// of it) is cut into tiles; a tile runner renders them (this process's threads, renderTiles,
// or the ranks of lucent-mpi); each finished tile is placed into the job's image and told to
// the job's observers, one call at a time: the checkpoint (frame_checkpoint.h) and whatever
// else is attached from outside, such as the hooks of the benchmarks and tests
// (cli/render_hooks.h). The progress is the caller's (RenderControl), the output is written
// from image() once the job is done (image_output.h).
#pragma once

#include "render/image.h"
#include "render/pixel_rect.h"
#include "render/renderer.h"
#include "render/tile_render.h"

#include "scenegraph/render_settings.h"

#include <functional>
#include <utility>
#include <vector>

namespace lucent {

class RenderJob;

// What a job tells those who watch it.
class RenderObserver {
 public:
  virtual ~RenderObserver() = default;
  // Asked before the render: the tiles one after another (each still over every thread),
  // so that a tile's time is its own cost.
  virtual bool wantsTilesOneAtATime() const { return false; }
  // Tile `index` of job.tiles() is finished and placed in job.image(); `tile` holds its
  // pixels, counts and seconds. Called from the thread that rendered it.
  virtual void tileFinished(const RenderJob& job, size_t index, const RenderResult& tile) = 0;
  // The render is over: every tile is finished, or it was cancelled (result.cancelled).
  virtual void jobEnded(const RenderJob& /*job*/, const TileRenderResult& /*result*/) {}
};

// How a job's tiles get rendered, with renderTiles' contract (tile_render.h).
using TileRunner = std::function<TileRenderResult(
    const Renderer& renderer, const std::vector<PixelRect>& tiles, const std::vector<char>& skip,
    const RenderControl& control, bool oneAtATime, const TileFinished& finished)>;

class RenderJob {
 public:
  // The pixels `area` of an image rendered with `settings`, in tiles of tileSize pixels a
  // side (tilesOf). `frame`: its number in an animation; `loadSeconds`: the time its scene
  // took to load (both for reports).
  RenderJob(const RenderSettings& settings, const PixelRect& area, int tileSize, int frame = 1,
            double loadSeconds = 0.0);

  const RenderSettings& settings() const { return settings_; }
  const PixelRect& area() const { return area_; }
  int tileSize() const { return tileSize_; }
  int frame() const { return frame_; }
  double loadSeconds() const { return loadSeconds_; }
  const std::vector<PixelRect>& tiles() const { return tiles_; }
  // The area's pixels: tiles not finished are black.
  const Image& image() const { return image_; }
  // The pixels of tile `index`, copied out of image().
  Image tilePixels(size_t index) const;

  // Takes tiles finished before (a resumed checkpoint's): each one that is a tile of this
  // job is placed and not rendered again. Returns how many were taken.
  size_t takeFinished(const std::vector<std::pair<PixelRect, Image>>& finished);

  // Attaches an observer, told after those attached before it; it must outlive render().
  void observe(RenderObserver& observer) { observers_.push_back(&observer); }

  // Renders the tiles not taken with `runner` (renderTiles when empty), placing each and
  // telling the observers.
  TileRenderResult render(const Renderer& renderer, const RenderControl& control,
                          const TileRunner& runner = {});

 private:
  void place(const PixelRect& tile, const Image& pixels);

  const RenderSettings settings_;
  const PixelRect area_;
  const int tileSize_;
  const int frame_;
  const double loadSeconds_;
  const std::vector<PixelRect> tiles_;
  std::vector<char> taken_;  // per tile: finished before, not to render
  Image image_;
  std::vector<RenderObserver*> observers_;
};

}  // namespace lucent
