// What a checkpoint must match to be resumed (app/checkpoint.h): the run's options that
// decide which pixels are rendered and how, and each frame's scene, settings and files.
#pragma once

#include "commands.h"
#include "load_scene.h"

#include "app/checkpoint.h"
#include "render/pixel_rect.h"

#include <optional>

namespace lucent::cli {

// The run: the scene named, -D values, the overrides given, the region, --tile-size and
// frames. (Threads, progress and output format do not change a pixel and are left out.)
Identity runIdentity(const RenderOptions& options, const CommonOptions& common,
                     const std::optional<PixelRect>& region);

// One frame: its number, the digest of the scene's XML, the settings after overrides, the
// camera, the tile size used and a digest of every file the scene read (read again from disk for
// it). Throws IoFailure when a file can no longer be read.
Identity frameIdentity(const LoadedScene& loaded, int frame, int tileSize);

}  // namespace lucent::cli
