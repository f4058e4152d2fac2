// `lucent check` refuses exactly what `lucent render` refuses: on every scene of the
// bad-scene corpus (tests/bad/scenes; its expectations are in tests/bad/cases.txt) both
// exit with the same status and print the same first error. Both run loadScene
// (cli/load_scene.h), so render's checks after parsing, such as a cube map whose width has
// no whole-pixel faces or transforms multiplying beyond range, run in check too.
#include "run_lucent.h"
#include "tests/test_effort.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

namespace fs = std::filesystem;
using namespace lucent::test;

namespace {

// The first error line; the memory available, which changes between two runs, is masked.
std::string firstError(const std::string& err) {
  static const std::regex available(R"([0-9.]+ [kMGT]?B available)");
  std::istringstream in(err);
  for (std::string line; std::getline(in, line);)
    if (line.find(": error: ") != std::string::npos || line.rfind("lucent: error", 0) == 0)
      return std::regex_replace(line, available, "N available");
  return "";
}

std::vector<fs::path> corpusScenes() {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(sourcePath("tests/bad/scenes")))
    if (e.is_regular_file() && e.path().extension() == ".xml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("lang: check and render give the same status and first error on every invalid scene",
          "[lang][check][agreement]") {
  TempFolder tmp("lucent-agreement");
  const std::vector<fs::path> scenes = corpusScenes();
  REQUIRE(scenes.size() >= 230);
  int refused = 0, compared = 0;
  for (size_t i = 0; i < scenes.size(); ++i) {
    // Under the sanitizers every eighth scene: script.bad_inputs runs each of them there.
    if (kSanitizerPass && i % 8 != 0 && scenes[i].filename() != "valid.xml") continue;
    const fs::path& scene = scenes[i];
    ++compared;
    const std::string size = " -w 16 -h 12";
    LucentRun check = runLucent("check '" + scene.string() + "'" + size);
    LucentRun render =
        runLucent("render '" + scene.string() + "' -o '" + tmp.str("out.png") + "'" + size + " -q");
    INFO(scene.string() << "\ncheck:\n" << check.err << "render:\n" << render.err);
    CHECK(check.status == render.status);
    CHECK(firstError(check.err) == firstError(render.err));
    if (scene.filename() == "valid.xml") {
      CHECK(render.status == 0);
    } else {
      CHECK(render.status >= 2);  // the corpus is invalid scenes and unreadable files
      CHECK_FALSE(firstError(render.err).empty());
      ++refused;
    }
  }
  CHECK(refused == compared - 1);
}

TEST_CASE("lang: check refuses what only building the world or the camera finds",
          "[lang][check][agreement]") {
  // Each group's scale(1e30) is fine; eleven multiply beyond double range.
  const std::string nested = sourcePath("tests/bad/scenes/transform_nested_scale_overflow.xml");
  LucentRun r = runLucent("check '" + nested + "'");
  CHECK(r.status == 2);
  CHECK(r.err ==
        nested + ":13:23: error: the transforms down to this node multiply beyond double range\n");

  // A size of the scene's own, which the corpus's -w 16 -h 12 would replace.
  TempFolder tmp("lucent-check-cubemap");
  const std::string cube = tmp.str("cube.xml");
  std::ofstream(cube) << "<scene version=\"1\">\n  <render width=\"90\" height=\"75\"/>\n"
                         "  <camera type=\"cubemap\" layout=\"cross\"/>\n  <sphere/>\n</scene>\n";
  r = runLucent("check '" + cube + "'");
  CHECK(r.status == 2);
  CHECK(r.err ==
        cube +
            ":3:3: error: a cubemap camera with layout=\"cross\" needs a width divisible by 4 "
            "and a height divisible by 3 (got 90x75; for square faces use e.g. 512x384)\n");
  // The size render would use: -w 96 gives whole faces.
  CHECK(runLucent("check '" + cube + "' -w 96").status == 0);

  const std::string texture = sourcePath("tests/bad/scenes/texture_image_truncated.xml");
  r = runLucent("check '" + texture + "'");
  CHECK(r.status == 3);
  // (libpng adds lines of its own on stderr.)
  CHECK_THAT(r.err,
             Catch::Contains(texture + ":3:32: error: cannot read '" +
                             sourcePath("tests/bad/scenes/textures/truncated_header.png") + "': "));
}
