// Renders an image as separate tiles (renderer.h's renderRect), several at once over the
// thread pool and each over threads too: what a checkpointed, resumed or region render is
// made of. A tile is reported when it is whole, so whatever stops the render, every tile
// reported holds its final pixels.
#pragma once

#include "renderer.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace lucent {

// The tile size a render uses unless told (--tile-size): 32 pixels, from the simulation of
// many ranks in docs/distributed.md; 128 with adaptive supersampling of centres, which
// renders a margin around each tile (its cost by tile size is measured there too).
int defaultTileSize(const RenderSettings& settings);

struct TileRenderResult {
  RayStats stats;
  double seconds = 0.0;
  bool cancelled = false;
};

// Called once per finished tile, with its index in `tiles` and its pixels (and the seconds
// it took), one call at a time, from the thread that rendered it.
using TileFinished = std::function<void(size_t index, const RenderResult& tile)>;

// The tiles still to render: every i with !skip[i] (skip may be empty: all), in order, and
// their work (Renderer::work) in all.
struct TilesToDo {
  std::vector<size_t> indices;
  uint64_t work = 0;
};
TilesToDo tilesToDo(const Renderer& renderer, const std::vector<PixelRect>& tiles,
                    const std::vector<char>& skip);

// The control each tile renders with: `control`'s, its threads left to the caller's arena,
// and a progress (the caller's, else `local`) whose total is `work`.
RenderControl tileControl(const RenderControl& control, uint64_t work, RenderProgress& local);

// Renders tiles[i] for every i with !skip[i] (skip may be empty: all). Sets the progress's
// workTotal to the tiles' work. `oneAtATime`: tiles one after another (each still over
// every thread), so that a tile's time is its own cost (--tile-costs).
TileRenderResult renderTiles(const Renderer& renderer, const std::vector<PixelRect>& tiles,
                             const std::vector<char>& skip, const RenderControl& control,
                             bool oneAtATime, const TileFinished& finished);

}  // namespace lucent
