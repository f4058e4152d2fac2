// Renders an image as separate tiles (renderer.h's renderRect), several at once over the
// thread pool and each over threads too: what a checkpointed, resumed or region render is
// made of. A tile is reported when it is whole, so whatever stops the render, every tile
// reported holds its final pixels.
#pragma once

#include "renderer.h"

#include <functional>
#include <vector>

namespace lucent {

// The tile size a render uses unless told (--tile-size): docs/distributed.md has the
// simulation it comes from. 32 pixels keep 256 ranks of a 4K frame busy (over 0.89 of the
// ideal in the simulation); adaptive supersampling of centres renders a margin around each
// tile, which costs 20 % more rays at 32 pixels, so its tiles are 128 (5 %).
int defaultTileSize(const RenderSettings& settings);

struct TileRenderResult {
  RayStats stats;
  double seconds = 0.0;
  bool cancelled = false;
};

// Called once per finished tile, with its index in `tiles` and its pixels (and the seconds
// it took), one call at a time, from the thread that rendered it.
using TileFinished = std::function<void(size_t index, const RenderResult& tile)>;

// Renders tiles[i] for every i with !skip[i] (skip may be empty: all). Sets the progress's
// workTotal to the tiles' work. `oneAtATime`: tiles one after another (each still over
// every thread), so that a tile's time is its own cost (--tile-costs).
TileRenderResult renderTiles(const Renderer& renderer, const std::vector<PixelRect>& tiles,
                             const std::vector<char>& skip, const RenderControl& control,
                             bool oneAtATime, const TileFinished& finished);

}  // namespace lucent
