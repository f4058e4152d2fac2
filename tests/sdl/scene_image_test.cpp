// POV-Ray scenes read by the scene reader and rendered by Lucent, held to POV-Ray's own
// image of the same file with the gallery's bounds (tests/data/sdl/scenes).
#include "pov_meaning_support.h"
#include "sdl_test_support.h"

#include "sdl/scene_reader.h"

using namespace lucent;
using namespace lucent::test;

namespace {

std::string fileText(const std::filesystem::path& path) {
  std::ifstream in(path);
  REQUIRE(in);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void requireSameImageAsPovray(const std::string& name, int width, int height) {
  const std::filesystem::path path = sdltest::dataFolder() / "scenes" / name;
  sdl::CollectedOutput out;
  sdl::Options options;
  options.imageWidth = width;
  options.imageHeight = height;
  options.output = &out;
  sdl::SceneLoad load = sdl::loadScene(path, options);
  for (const Diagnostic& d : load.diagnostics.all()) UNSCOPED_INFO(d.str());
  for (const std::string& w : out.warnings) UNSCOPED_INFO(w);
  REQUIRE(load.scene);
  requireSameImage(*load.scene, fileText(path));
}

}  // namespace

TEST_CASE("scene reader image: a sphere on a plane as POV-Ray users write it",
          "[sdl][scene][image][povray]") {
  requireSameImageAsPovray("sphere_on_plane.pov", 160, 120);
}

TEST_CASE("scene reader image: CSG, declared objects, #default and a loop",
          "[sdl][scene][image][povray]") {
  requireSameImageAsPovray("csg_and_objects.pov", 160, 120);
}

TEST_CASE("scene reader image: a macro's objects in a loop, a spotlight and a sky_sphere",
          "[sdl][scene][image][povray]") {
  requireSameImageAsPovray("macro_ring.pov", 160, 120);
}

TEST_CASE("scene reader image: textures placed among transforms, block patterns and maps",
          "[sdl][scene][image][povray][texture]") {
  requireSameImageAsPovray("textures_placed.pov", 160, 120);
}

TEST_CASE("scene reader image: noise patterns with turbulence and colour maps, normals",
          "[sdl][scene][image][povray][texture]") {
  requireSameImageAsPovray("noise_patterns.pov", 160, 120);
}
