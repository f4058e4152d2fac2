// A tile's messages: which tile (rank 0 -> worker) and its result (worker -> rank 0): the
// float pixels as rendered, the seconds and the ray counts, so that rank 0's image,
// checkpoint, --stats and --tile-costs are those of a single-process render.
#pragma once

#include "render/pixel_rect.h"
#include "render/renderer.h"

#include <cstdint>
#include <vector>

namespace lucent::mpi {

struct TileOrder {
  int frame = 1;
  uint64_t index = 0;
  PixelRect rect;
};
std::vector<char> pack(const TileOrder& order);
TileOrder unpackOrder(const std::vector<char>& bytes);

struct TileResult {
  int frame = 1;
  uint64_t index = 0;
  RenderResult result;
};
std::vector<char> pack(const TileResult& tile);
TileResult unpackResult(const std::vector<char>& bytes);

}  // namespace lucent::mpi
