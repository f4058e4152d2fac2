// The files an animation's frames read are loaded once: meshes through a MeshFileCache
// shared by the parses (ParseOptions::meshCache), image textures through an ImageMapCache
// shared by the renderers. The frames below differ (the sphere moves with clock) yet read
// each file once; a changed file is read again.
#include "../temp_dir.h"

#include "../support/paths.h"
#include "lang/parser.h"
#include "meshes/mesh_file_cache.h"
#include "render/image_map_cache.h"
#include "render/renderer.h"
#include "scenegraph/world.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <thread>

using namespace lucent;

namespace {

const std::string kMesh = std::string(lucentSourceDir()) + "/tests/data/meshes/cube.obj";
const std::string kImage = std::string(lucentSourceDir()) + "/examples/textures/uvgrid.png";

// Three frames: a textured sphere moving with clock and a mesh from a file.
std::string animatedScene(const std::string& mesh, const std::string& image) {
  return R"xml(<scene version="1">
  <animation frames="3"/>
  <render width="16" height="12"/>
  <camera position="0 1 6" look-at="0 0 0"/>
  <light position="5 5 5"/>
  <sphere radius="0.5" transform="translate(${2*clock - 1} 0 0)">
    <material><image src=")xml" +
         image + R"xml("/></material>
  </sphere>
  <mesh src=")xml" +
         mesh + R"xml(" transform="translate(0 -1.5 0)"/>
</scene>)xml";
}

// The scene may read only its own folder: the files are copied there.
std::string sceneWithFiles(const test::TempDir& dir) {
  namespace fs = std::filesystem;
  fs::copy_file(kMesh, dir.path / "cube.obj");
  fs::copy_file(kImage, dir.path / "grid.png");
  return animatedScene("cube.obj", "grid.png");
}

std::unique_ptr<Scene> parseFrame(const std::string& xml, const std::string& path, int frame,
                                  const std::shared_ptr<MeshFileCache>& meshes) {
  ParseOptions options;
  options.frame = frame;
  options.meshCache = meshes;
  ParseResult parsed = parseSceneString(xml, path, options);
  for (const Diagnostic& d : parsed.diagnostics.all()) UNSCOPED_INFO(d.str());
  REQUIRE(parsed.scene);
  return std::move(parsed.scene);
}

}  // namespace

TEST_CASE("animation: a mesh and an image texture are read once for three frames",
          "[render][animation]") {
  test::TempDir dir("frame-caches");
  const std::string xml = sceneWithFiles(dir);
  const std::string path = dir.file("scene.xml");
  auto meshes = std::make_shared<MeshFileCache>();
  ImageMapCache images;
  std::vector<Image> frames;
  for (int f = 1; f <= 3; ++f) {
    std::unique_ptr<Scene> scene = parseFrame(xml, path, f, meshes);
    CHECK(scene->frame == f);
    World world(*scene);
    Renderer renderer(world, scene->cameras[0], &images);
    frames.push_back(renderer.render().image);
  }
  CHECK(meshes->reads() == 1);
  CHECK(images.loads() == 1);
  // The frames really differ: the sphere moved.
  CHECK(frames[0].pixels != frames[1].pixels);
  CHECK(frames[1].pixels != frames[2].pixels);
}

TEST_CASE("animation: without a shared cache each parse reads its meshes", "[render][animation]") {
  test::TempDir dir("frame-caches");
  const std::string xml = sceneWithFiles(dir);
  auto first = std::make_shared<MeshFileCache>(), second = std::make_shared<MeshFileCache>();
  parseFrame(xml, dir.file("scene.xml"), 1, first);
  parseFrame(xml, dir.file("scene.xml"), 2, second);
  CHECK(first->reads() == 1);
  CHECK(second->reads() == 1);
}

TEST_CASE("animation: a mesh or an image changed between frames is read again",
          "[render][animation]") {
  namespace fs = std::filesystem;
  test::TempDir dir("frame-caches");
  const std::string xml = sceneWithFiles(dir);
  const fs::path mesh = dir.path / "cube.obj", image = dir.path / "grid.png";
  auto meshes = std::make_shared<MeshFileCache>();
  ImageMapCache images;
  auto frame = [&](int f) {
    std::unique_ptr<Scene> scene = parseFrame(xml, dir.file("scene.xml"), f, meshes);
    World world(*scene);
    Renderer renderer(world, scene->cameras[0], &images);
  };
  frame(1);
  frame(2);
  CHECK(meshes->reads() == 1);
  CHECK(images.loads() == 1);
  // A new modification time (set, not waited for) stands for an edit.
  const auto later = fs::last_write_time(mesh) + std::chrono::seconds(10);
  fs::last_write_time(mesh, later);
  fs::last_write_time(image, later);
  frame(3);
  CHECK(meshes->reads() == 2);
  CHECK(images.loads() == 2);
}
