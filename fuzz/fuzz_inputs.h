// What each fuzz target does with one input, shared by the libFuzzer entry points
// (fuzz/*_fuzz.cpp, built with -DLUCENT_FUZZ=ON) and the regression test that replays every
// kept crash input through the normal build (tests/fuzz/fuzz_regression_test.cpp).
//
// A finding is anything that is not an orderly refusal: a sanitizer report, a signal, an
// abort, an uncaught exception, or (libFuzzer's -timeout / -rss_limit_mb) a hang or runaway
// memory. Orderly refusals are the located diagnostics of the parser and the exceptions the
// command line turns into exit status 2 or 3 (MeshError, LocatedError).
#pragma once

#include "lang/parser.h"
#include "meshes/mesh_files.h"
#include "render/camera_frame.h"
#include "render/renderer.h"
#include "render/texture.h"
#include "scenegraph/transform_syntax.h"
#include "scenegraph/world.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace lucent::fuzz {

// The scene is parsed as if it were a file in examples/, so its includes and meshes can
// reach real files (examples/parts, examples/meshes) and nothing outside that folder.
inline void sceneParser(const uint8_t* data, size_t size, const std::string& virtualPath) {
  std::string xml(reinterpret_cast<const char*>(data), size);
  ParseResult parsed = parseSceneString(xml, virtualPath);
  // The parser turns an escaped exception into an "internal error" diagnostic rather than
  // crash; for the fuzzer that is still a bug to find. Only a message that starts so: a
  // scene's own text can contain the words (tests/fuzz/crashes/scene_parser/).
  for (const Diagnostic& d : parsed.diagnostics.all())
    if (d.message.rfind("internal error while reading the scene", 0) == 0) __builtin_trap();
  if (!parsed.scene) return;
  Scene& scene = *parsed.scene;
  // A valid scene is also built and one pixel traced, as `lucent render` would; the fuzzer
  // hunts crashes, not settings that are merely slow (a million samples, a thousand
  // reflections between mirrors), so those are kept small.
  scene.render.samples = std::min(scene.render.samples, 2);
  scene.render.maxDepth = std::min(scene.render.maxDepth, 8);
  for (Light& light : scene.lights) {
    light.samplesU = std::min(light.samplesU, 4);
    light.samplesV = std::min(light.samplesV, 4);
  }
  try {
    World world(scene);
    for (const Camera& camera : scene.cameras) {
      Renderer renderer(world, camera);
      RayStats stats;
      renderer.renderPixel(scene.render.width / 2, scene.render.height / 2, stats);
    }
  } catch (const LocatedError&) {  // a camera, a texture, transforms beyond range
  } catch (const MeshError&) {
  }
}

inline void transformSyntax(const uint8_t* data, size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  TransformSyntaxResult r = parseTransformSyntax(text);
  if (!r.ok && r.errorOffset > text.size()) __builtin_trap();  // an offset outside the text
}

inline void meshReader(const uint8_t* data, size_t size, MeshFormat format) {
  try {
    loadMeshBytes(std::string(reinterpret_cast<const char*>(data), size), format);
  } catch (const MeshError&) {
  }
}

}  // namespace lucent::fuzz
