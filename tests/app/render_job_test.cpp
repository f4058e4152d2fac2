// The render job: its tiles, placed into its image, give the bits of a whole render in
// every sampling mode; observers hear of each tile once, in the order attached, and of the
// end; tiles taken from a checkpoint are not rendered again; the frame's checkpoint keeps
// what was finished and reads back to the same pixels.
#include "../render/scene_builder.h"
#include "../temp_dir.h"

#include "app/checkpoint.h"
#include "app/frame_checkpoint.h"
#include "app/render_job.h"
#include "render/renderer.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <string>
#include <vector>

using namespace lucent;
using namespace lucent::test;

namespace {

// Writes down what it is told, under its name, into a log the observers share.
struct Recorder : RenderObserver {
  Recorder(std::string name, std::vector<std::string>& log, bool oneAtATime = false)
      : name(std::move(name)), log(log), oneAtATime(oneAtATime) {}
  bool wantsTilesOneAtATime() const override { return oneAtATime; }
  void tileFinished(const RenderJob& job, size_t index, const RenderResult& tile) override {
    // The tile is in the job's image when its observers hear of it.
    CHECK(sameBits(job.tilePixels(index), tile.image));
    log.push_back(name + " " + std::to_string(index));
  }
  void jobEnded(const RenderJob&, const TileRenderResult& result) override {
    log.push_back(name + (result.cancelled ? " cancelled" : " ended"));
  }
  std::string name;
  std::vector<std::string>& log;
  bool oneAtATime;
};

}  // namespace

TEST_CASE("a render job's tiles make the bits of the whole image in every sampling mode",
          "[app][job]") {
  Scene scene;
  buildBusyScene(scene);  // 40 x 30
  struct Mode {
    const char* name;
    int samples;
    double adaptive;
    AdaptiveMode mode;
  };
  for (const Mode& m : {Mode{"fixed", 4, 0.0, AdaptiveMode::Centres},
                        Mode{"adaptive centres", 16, 0.05, AdaptiveMode::Centres},
                        Mode{"corners", 1, 0.1, AdaptiveMode::Corners}}) {
    INFO(m.name);
    scene.render.samples = m.samples;
    scene.render.adaptive = m.adaptive;
    scene.render.adaptiveMode = m.mode;
    World world(scene);
    Renderer renderer(world, scene.cameras[0]);
    const Image whole = renderer.render().image;
    RenderJob job(scene.render, wholeImage(40, 30), 13);  // 4 x 3 tiles, odd edges
    REQUIRE(job.tiles().size() == 12);
    const TileRenderResult result = job.render(renderer, {});
    CHECK_FALSE(result.cancelled);
    CHECK(sameBits(job.image(), whole));
  }
}

TEST_CASE("a render job tells its observers of each tile once, in the order attached",
          "[app][job]") {
  Scene scene;
  buildBusyScene(scene);
  World world(scene);
  Renderer renderer(world, scene.cameras[0]);
  RenderJob job(scene.render, {5, 3, 37, 29}, 16);  // a region: 2 x 2 tiles
  std::vector<std::string> log;
  Recorder first("a", log), second("b", log, true);
  job.observe(first);
  job.observe(second);
  // A runner that checks what the job asks of it and renders the tiles in reverse order.
  bool askedOneAtATime = false;
  const TileRunner runner = [&](const Renderer& r, const std::vector<PixelRect>& tiles,
                                const std::vector<char>& skip, const RenderControl& control,
                                bool oneAtATime, const TileFinished& finished) {
    askedOneAtATime = oneAtATime;
    CHECK(skip == std::vector<char>(4, 0));
    for (size_t i = tiles.size(); i-- > 0;) finished(i, r.renderRect(tiles[i], control));
    return TileRenderResult{};
  };
  job.render(renderer, {}, runner);
  CHECK(askedOneAtATime);  // one observer wants it
  CHECK(log == std::vector<std::string>{"a 3", "b 3", "a 2", "b 2", "a 1", "b 1", "a 0", "b 0",
                                        "a ended", "b ended"});
  CHECK(sameBits(job.image(), renderer.renderRect({5, 3, 37, 29}).image));
}

TEST_CASE("a render job does not render again the tiles it took from a checkpoint", "[app][job]") {
  Scene scene;
  buildBusyScene(scene);
  World world(scene);
  Renderer renderer(world, scene.cameras[0]);
  RenderJob job(scene.render, wholeImage(40, 30), 20);  // 2 x 2 tiles, the lower ones 10 high
  // Tile 1 as a checkpoint holds it, and a rectangle that is no tile of this job.
  Image saved(20, 20);
  for (Color& c : saved.pixels) c = Color(0.25f, 0.5f, 0.75f);
  CHECK(job.takeFinished({{{20, 0, 40, 20}, saved}, {{0, 0, 10, 10}, Image(10, 10)}}) == 1);
  std::vector<std::string> log;
  Recorder recorder("r", log);
  job.observe(recorder);
  job.render(renderer, {});
  std::sort(log.begin(), log.end());
  CHECK(log == std::vector<std::string>{"r 0", "r 2", "r 3", "r ended"});
  CHECK(sameBits(job.tilePixels(1), saved));
  CHECK(sameBits(job.tilePixels(3), renderer.renderRect({20, 20, 40, 30}).image));
}

TEST_CASE("a cancelled render job ends cancelled and its checkpoint keeps the finished tiles",
          "[app][job][checkpoint]") {
  Scene scene;
  buildBusyScene(scene);
  World world(scene);
  Renderer renderer(world, scene.cameras[0]);
  TempDir dir("render-job");
  const std::string path = dir.file("out.png.checkpoint");
  CheckpointWriter writer(path, {{"scene", "busy"}});
  int identities = 0;
  const Identity identity = {{"frame", "1"}};
  // A long interval: nothing is saved until the render is cancelled.
  FrameCheckpoint checkpoint(
      writer, 1,
      [&]() -> const Identity& {
        ++identities;
        return identity;
      },
      1e9);
  RenderJob job(scene.render, wholeImage(40, 30), 10);  // 12 tiles
  std::atomic<bool> cancel{false};
  // Cancels after the third tile; a stand-in for Ctrl-C, as the command's test hook.
  struct CancelAfter : RenderObserver {
    std::atomic<bool>& cancel;
    int left;
    CancelAfter(std::atomic<bool>& c, int n) : cancel(c), left(n) {}
    void tileFinished(const RenderJob&, size_t, const RenderResult&) override {
      if (--left == 0) cancel = true;
    }
  } cancelAfter(cancel, 3);
  job.observe(cancelAfter);
  job.observe(checkpoint);
  RenderControl control;
  control.threads = 1;  // tiles one after another: exactly three finish
  control.cancel = &cancel;
  const TileRenderResult result = job.render(renderer, control);
  CHECK(result.cancelled);
  CHECK(identities == 1);
  const CheckpointContents read = readCheckpoint(path);
  REQUIRE(read.frames.count(1) == 1);
  const CheckpointContents::Frame& frame = read.frames.at(1);
  CHECK(frame.identity == identity);
  CHECK_FALSE(frame.written);
  REQUIRE(frame.tiles.size() == 3);
  for (const auto& [rect, pixels] : frame.tiles) {
    size_t index = 0;
    while (index < job.tiles().size() && !(job.tiles()[index] == rect)) ++index;
    REQUIRE(index < job.tiles().size());
    CHECK(sameBits(pixels, renderer.renderRect(rect).image));
  }
  // The image is written: recorded, and the frame no longer keeps tiles to save.
  checkpoint.imageWritten();
  CHECK(readCheckpoint(path).frames.at(1).written);
  CHECK(identities == 1);
}

TEST_CASE("a frame's checkpoint saves each finished tile once the interval has passed",
          "[app][job][checkpoint]") {
  Scene scene;
  buildBusyScene(scene);
  World world(scene);
  Renderer renderer(world, scene.cameras[0]);
  TempDir dir("render-job");
  const std::string path = dir.file("out.png.checkpoint");
  CheckpointWriter writer(path, {{"scene", "busy"}});
  const Identity identity = {{"frame", "2"}};
  FrameCheckpoint checkpoint(
      writer, 2, [&]() -> const Identity& { return identity; }, 0.0);
  RenderJob job(scene.render, wholeImage(40, 30), 16, 2);  // 3 x 2 tiles
  job.observe(checkpoint);
  job.render(renderer, {});
  const CheckpointContents read = readCheckpoint(path);
  REQUIRE(read.frames.count(2) == 1);
  CHECK(read.frames.at(2).tiles.size() == 6);
  for (const auto& [rect, pixels] : read.frames.at(2).tiles)
    CHECK(sameBits(pixels, renderer.renderRect(rect).image));
}
