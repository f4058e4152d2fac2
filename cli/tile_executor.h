// How a frame's tiles get rendered: `lucent` renders them on its own threads
// (renderTiles, tile_render.h); `lucent-mpi` hands them out to MPI ranks
// (mpi/tile_dispatch.h). Either way the same tiles, the same `finished` calls, so the
// checkpoint and the image are the same.
#pragma once

#include "commands.h"
#include "load_scene.h"

#include "render/tile_render.h"

#include <functional>
#include <type_traits>
#include <vector>

namespace lucent::cli {

// TileExecutor (declared in commands.h) has renderTiles' contract, with the loaded scene
// (its files, for other processes) and the frame the tiles are of:
//   (renderer, loaded, frame, tiles, skip, control, oneAtATime, finished) -> TileRenderResult
static_assert(std::is_same_v<TileFinished, std::function<void(size_t, const RenderResult&)>>);

}  // namespace lucent::cli
