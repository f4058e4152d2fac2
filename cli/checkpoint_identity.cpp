#include "checkpoint_identity.h"

#include "exit_status.h"

#include "scenegraph/digest.h"

#include <fmt/core.h>

#include <fstream>

namespace lucent::cli {

namespace {

std::string given(const std::optional<int>& v) { return v ? std::to_string(*v) : "the scene's"; }

std::string fileDigest(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw IoFailure(fmt::format("cannot read '{}' for the checkpoint's digest", path.string()));
  Digest d;
  std::string buffer(1 << 16, '\0');
  while (in.read(buffer.data(), static_cast<std::streamsize>(buffer.size())) || in.gcount() > 0)
    d.add(std::string_view(buffer.data(), static_cast<size_t>(in.gcount())));
  return d.hex();
}

}  // namespace

Identity runIdentity(const RenderOptions& options, const CommonOptions& common,
                     const std::optional<PixelRect>& region) {
  Identity id;
  id.emplace_back("program", "lucent 0.1");
  id.emplace_back("scene", options.scene);
  std::string defines;
  for (const auto& [name, value] : common.defines)
    defines += (defines.empty() ? "" : " ") + name + "=" + value;
  id.emplace_back("-D", defines.empty() ? "none" : defines);
  id.emplace_back("--width", given(options.width));
  id.emplace_back("--height", given(options.height));
  id.emplace_back("--samples", given(options.samples));
  id.emplace_back("--max-depth", given(options.maxDepth));
  id.emplace_back("--camera", options.camera.empty() ? "the scene's first" : options.camera);
  id.emplace_back("--region", region ? fmt::format("{},{},{},{}", region->x0, region->y0,
                                                   region->x1, region->y1)
                                     : "the whole image");
  id.emplace_back("--tile-size",
                  options.tileSize ? std::to_string(*options.tileSize) : "the default");
  id.emplace_back("--frames", options.frames.empty() ? "all" : options.frames);
  return id;
}

Identity frameIdentity(const LoadedScene& loaded, int frame, int tileSize) {
  const Scene& scene = *loaded.scene;
  const RenderSettings& r = scene.render;
  Identity id;
  id.emplace_back("frame", std::to_string(frame));
  id.emplace_back("digest of the scene XML", fmt::format("{:016x}", loaded.xmlDigest));
  id.emplace_back("image size", fmt::format("{}x{}", r.width, r.height));
  id.emplace_back("samples", std::to_string(r.samples));
  id.emplace_back("max-depth", std::to_string(r.maxDepth));
  id.emplace_back("tile size", std::to_string(tileSize));
  id.emplace_back("camera",
                  loaded.camera && !loaded.camera->name.empty() ? loaded.camera->name : "unnamed");
  // The scene file and its includes are in the XML digest (a comment changes no pixel).
  for (const std::filesystem::path& f : loaded.dataFiles)
    id.emplace_back("digest of " + f.string(), fileDigest(f));
  return id;
}

}  // namespace lucent::cli
