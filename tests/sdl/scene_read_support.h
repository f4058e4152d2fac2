// POV-Ray scene text read by the scene reader in tests: the load, its #debug output and
// warnings, and the errors of a scene that must be refused.
#pragma once

#include "sdl_test_support.h"

#include "sdl/scene_reader.h"

#include <catch2/catch.hpp>

#include <memory>
#include <string>
#include <vector>

namespace sdltest {

struct Read {
  lucent::sdl::SceneLoad load;
  lucent::sdl::CollectedOutput out;
};

// `text` read as the scene test.pov in tests/data/sdl, for a 160x120 image.
inline std::unique_ptr<Read> readScene(const std::string& text) {
  auto r = std::make_unique<Read>();
  lucent::sdl::Options options;
  options.imageWidth = 160;
  options.imageHeight = 120;
  options.output = &r->out;
  r->load = lucent::sdl::loadSceneText("test.pov", text, dataFolder(), options);
  for (const lucent::Diagnostic& d : r->load.diagnostics.all()) UNSCOPED_INFO(d.str());
  return r;
}

// The errors of a scene that is refused (checked), each as printed.
inline std::vector<std::string> errorsOf(const std::string& text) {
  auto r = readScene(text);
  CHECK(!r->load.scene);
  std::vector<std::string> errors;
  for (const lucent::Diagnostic& d : r->load.diagnostics.all()) errors.push_back(d.str());
  return errors;
}

// Vectors and matrices equal to within 1e-12 in each component.
inline void checkVec(const lucent::Vec3& got, const lucent::Vec3& want) {
  for (int c = 0; c < 3; ++c) CHECK(got[c] == Approx(want[c]).margin(1e-12));
}
inline void checkMat(const lucent::Mat4& got, const lucent::Mat4& want) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) CHECK(got[i][j] == Approx(want[i][j]).margin(1e-12));
}

// The material of the scene's i-th top-level node (which must have one).
inline const lucent::Material& materialOf(const lucent::Scene& scene, size_t i) {
  REQUIRE(scene.root->children.size() > i);
  const lucent::Node& n = *scene.root->children[i];
  REQUIRE(n.material);
  return scene.materials.at(*n.material);
}

}  // namespace sdltest
