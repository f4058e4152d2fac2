// The pure logic of `lucent preview` (cli/preview/): the token, the coarse passes' order,
// the debounce of a save's events, the files watched, and the board that keeps what the
// page is shown bounded however slow a browser is.
#include "coarse_passes.h"
#include "debounce.h"
#include "json_text.h"
#include "preview_board.h"
#include "preview_controls.h"
#include "preview_token.h"
#include "scene_parameters.h"
#include "watch_list.h"

#include "../../temp_dir.h"
#include "lang/parser.h"

#include <catch2/catch.hpp>

#include <set>

using namespace lucent::preview;
using namespace std::chrono_literals;

TEST_CASE("preview: a token is 32 hex digits and differs each time", "[preview]") {
  std::set<std::string> seen;
  for (int i = 0; i < 50; ++i) {
    const std::string token = makeToken();
    CHECK(token.size() == 32);
    CHECK(token.find_first_not_of("0123456789abcdef") == std::string::npos);
    seen.insert(token);
  }
  CHECK(seen.size() == 50);
}

TEST_CASE("preview: only the exact token is accepted", "[preview]") {
  const std::string token = "0123456789abcdef0123456789abcdef";
  CHECK(tokenAccepted(token, token));
  CHECK_FALSE(tokenAccepted("", token));
  CHECK_FALSE(tokenAccepted(token.substr(0, 31), token));
  CHECK_FALSE(tokenAccepted(token + "0", token));
  CHECK_FALSE(tokenAccepted("1123456789abcdef0123456789abcdef", token));
  CHECK_FALSE(tokenAccepted("0123456789abcdef0123456789abcdeF", token));
  // No token at all accepts nothing, not even an empty one.
  CHECK_FALSE(tokenAccepted("", ""));
}

TEST_CASE("preview: the coarse passes trace every pixel of the grid once", "[preview]") {
  const int width = 37, height = 21;  // not multiples of 8: partial blocks at the edges
  const std::vector<int> steps = coarseSteps(width, height);
  REQUIRE(steps == std::vector<int>{8, 4, 2});
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      int traced = 0;
      for (int step : steps) traced += tracedInPass(x, y, step, steps.front()) ? 1 : 0;
      // Each pixel on the finest grid (even x and y) once, the others never.
      CHECK(traced == (x % 2 == 0 && y % 2 == 0 ? 1 : 0));
    }
  // The first pass is every 8th pixel of every 8th row; the second adds the 4th ones only.
  CHECK(tracedInPass(0, 0, 8, 8));
  CHECK(tracedInPass(16, 8, 8, 8));
  CHECK_FALSE(tracedInPass(8, 8, 4, 8));
  CHECK(tracedInPass(4, 8, 4, 8));
  CHECK(tracedInPass(4, 4, 4, 8));
  CHECK(gridSize(37, 8) == 5);
  CHECK(gridSize(32, 8) == 4);
  // A tiny image has only the passes finer than itself.
  CHECK(coarseSteps(4, 3) == std::vector<int>{2});
  CHECK(coarseSteps(1, 1).empty());
}

TEST_CASE("preview: a burst of events gives one render after the quiet interval", "[preview]") {
  Debouncer d(50ms);
  const auto t0 = Debouncer::Clock::time_point{} + 1s;
  CHECK_FALSE(d.pending());
  CHECK_FALSE(d.due(t0));
  // An editor's save: write a temporary file, rename it, touch a backup, 10 ms apart.
  d.event(t0);
  d.event(t0 + 10ms);
  d.event(t0 + 20ms);
  CHECK(d.pending());
  CHECK_FALSE(d.due(t0 + 60ms));  // 40 ms after the last event
  CHECK(d.due(t0 + 70ms));        // 50 ms after it
  CHECK_FALSE(d.due(t0 + 80ms));  // once only
  CHECK_FALSE(d.pending());
  // Two saves 200 ms apart are two renders.
  d.event(t0 + 100ms);
  CHECK(d.due(t0 + 150ms));
  d.event(t0 + 300ms);
  CHECK_FALSE(d.due(t0 + 349ms));
  CHECK(d.due(t0 + 350ms));
}

TEST_CASE("preview: the watch list holds the folders of the scene and of every file it read",
          "[preview]") {
  lucent::test::TempDir dir("preview-watch");
  dir.write("parts/ball.xml", R"(<scene version="1"><sphere radius="1"/></scene>)");
  const auto scene = dir.write("main.xml", R"(<scene version="1">
  <camera position="0 0 5" look-at="0 0 0"/>
  <light position="3 3 3"/>
  <include src="parts/ball.xml"/>
</scene>)");
  const lucent::ParseResult parsed = lucent::parseSceneFile(scene.string());
  REQUIRE(parsed.scene);
  WatchList list;
  list.add(parsed.sources);
  list.add(parsed.dataFiles);
  const std::string root = std::filesystem::canonical(dir.path).string();
  CHECK(list.watches(root, "main.xml"));
  CHECK(list.watches(root + "/parts", "ball.xml"));
  CHECK_FALSE(list.watches(root, "ball.xml"));
  CHECK_FALSE(list.watches(root, "other.xml"));
  CHECK(list.folders().size() == 2);
  CHECK(list.files() == 2);

  // A failed load keeps the files of the last good one: merged, nothing lost, nothing twice.
  WatchList always;
  always.add(scene);
  always.add(dir.path / "parts" / ".." / "main.xml");  // the same file, spelled otherwise
  CHECK(always.files() == 1);
  list.merge(always);
  CHECK(list.files() == (dir.path.string() == root ? 2u : 3u));
}

TEST_CASE("preview: the board sends the current state and coalesces what a slow reader missed",
          "[preview]") {
  PreviewBoard board;
  uint64_t fast = 0, slow = 0;
  std::string out;
  board.publishImage("{\"pass\":8}");
  board.publishStatus("{\"n\":1}");
  REQUIRE(board.collect(fast, 0ms, out));
  CHECK(out == "event: image\ndata: {\"pass\":8}\n\nevent: status\ndata: {\"n\":1}\n\n");
  // Nothing new: an empty read after the wait.
  REQUIRE(board.collect(fast, 1ms, out));
  CHECK(out.empty());

  // Many updates while the slow reader reads nothing: it later gets only the latest of each.
  for (int i = 0; i < 1000; ++i) {
    board.publishTile("0,0", "{\"t\":" + std::to_string(i) + "}");
    board.publishStatus("{\"n\":" + std::to_string(i) + "}");
  }
  board.publishTile("32,0", "{\"t\":\"b\"}");
  REQUIRE(board.collect(slow, 0ms, out));
  CHECK(out ==
        "event: image\ndata: {\"pass\":8}\n\n"
        "event: tile\ndata: {\"t\":999}\n\n"
        "event: status\ndata: {\"n\":999}\n\n"
        "event: tile\ndata: {\"t\":\"b\"}\n\n");
  const size_t held = board.bytesHeld();
  CHECK(held < 100);

  // A new picture replaces the tiles under it.
  board.publishImage("{\"pass\":1}");
  REQUIRE(board.collect(fast, 0ms, out));
  CHECK(out.find("event: tile") == std::string::npos);
  CHECK(out.find("{\"pass\":1}") != std::string::npos);
  CHECK(board.bytesHeld() < held);

  board.close();
  CHECK_FALSE(board.collect(fast, 1000ms, out));
}

TEST_CASE("preview: JSON strings and base64 as the page decodes them", "[preview]") {
  CHECK(jsonString("a\"b\\c\nd\te") == "\"a\\\"b\\\\c\\nd\\u0009e\"");
  CHECK(jsonString("x.xml:4:22: error: <sphere>") == "\"x.xml:4:22: error: <sphere>\"");
  // RFC 4648's test vectors.
  CHECK(base64("") == "");
  CHECK(base64("f") == "Zg==");
  CHECK(base64("fo") == "Zm8=");
  CHECK(base64("foo") == "Zm9v");
  CHECK(base64("foob") == "Zm9vYg==");
  CHECK(base64("fooba") == "Zm9vYmE=");
  CHECK(base64("foobar") == "Zm9vYmFy");
  CHECK(base64(std::string("\xff\x00\x80", 3)) == "/wCA");
}

TEST_CASE("preview: the sliders are the scene's numeric top-level parameters", "[preview]") {
  lucent::test::TempDir dir("preview-params");
  const auto scene = dir.write("s.xml", R"(<scene version="1">
  <param name="turn" value="30"/>
  <param name="tint" value="0.9 0.3 0.1"/>
  <param name="size" value="-1.5e0"/>
  <param name="expr" value="${turn * 2}"/>
  <group><param name="inner" value="1"/></group>
</scene>)");
  const std::vector<SceneParameter> found = numericParameters(scene.string());
  REQUIRE(found.size() == 2);
  CHECK(found[0].name == "turn");
  CHECK(found[0].declared == 30.0);
  CHECK(found[1].name == "size");
  CHECK(found[1].declared == -1.5);
  CHECK(numericParameters(dir.file("missing.xml")).empty());
  dir.write("broken.xml", "<scene><param name=");
  CHECK(numericParameters(dir.file("broken.xml")).empty());
}

TEST_CASE("preview: a slider sets only a parameter offered, or a frame of the animation",
          "[preview]") {
  PreviewControls controls;
  CHECK(controls.set("turn", "10") != "");  // nothing offered yet
  controls.offer({{"turn", 30.0}}, 24);
  CHECK(controls.set("turn", "45.5") == "");
  CHECK(controls.set("turn", "forty") == "'forty' is not a number");
  CHECK(controls.set("turn", "1e999") != "");
  CHECK(controls.set("tint", "1") == "'tint' is not a numeric parameter of the scene");
  CHECK(controls.set("frame", "24") == "");
  CHECK(controls.set("frame", "25") == "frame 25: the scene has frames 1 to 24");
  CHECK(controls.set("frame", "2.5") != "");
  CHECK(controls.values() == std::map<std::string, std::string>{{"frame", "24"}, {"turn", "45.5"}});
  CHECK(controls.set("samples", "4") == "");
  CHECK(controls.set("samples", "0") == "samples 0: 1 to 64");
  CHECK(controls.set("samples", "1.5") != "");
  CHECK(controls.values().at("samples") == "4");
  controls.offer({{"turn", 30.0}}, 0);
  CHECK(controls.set("frame", "1") == "the scene is not an animation (or -D picks its moment)");
}

TEST_CASE("preview: a region is four pixel bounds, or none for the whole image", "[preview]") {
  PreviewControls controls;
  CHECK_FALSE(controls.region());
  CHECK(controls.setRegion("0,0,120,160") == "");
  REQUIRE(controls.region());
  CHECK(*controls.region() == lucent::PixelRect{0, 0, 120, 160});
  for (const char* bad : {"5,5,2,9", "0,0,0,4", "-1,0,4,4", "1,2,3", "1,2,3,4,5", "1;2;3;4", "a"})
    CHECK(controls.setRegion(bad) != "");
  CHECK(*controls.region() == lucent::PixelRect{0, 0, 120, 160});  // a bad one changes nothing
  CHECK(controls.setRegion("") == "");
  CHECK_FALSE(controls.region());
}
