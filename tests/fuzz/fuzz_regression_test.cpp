// The kept inputs of every fuzz target, replayed through the very function the libFuzzer
// target calls (fuzz/fuzz_inputs.h), in the normal build: under LUCENT_SANITIZE a regression
// is a sanitizer report, in any build a crash, an escaped exception or a broken promise.
// tests/fuzz/crashes/TARGET/ holds the inputs that once broke something (any outcome but a
// finding will do); tests/fuzz/corpus/TARGET/ holds inputs that cover the target, each named
// after the outcome it must have (accept-* or refuse-*). The READMEs there tell how inputs
// get there.
#include "../support/paths.h"
// The harness finds examples/ through LUCENT_SOURCE_DIR, which the fuzz targets' build
// defines; here it is the tests' source folder.
#define LUCENT_SOURCE_DIR lucentSourceDir()
#include "fuzz/fuzz_inputs.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> filesIn(const fs::path& dir) {
  std::vector<fs::path> files;
  if (!fs::is_directory(dir)) return files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().filename() != "README.md") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string bytesOf(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// Replays every kept input of `target`; returns how many there were.
template <class Replay>
size_t replayAll(const std::string& target, Replay replay) {
  const fs::path root = fs::path(lucentSourceDir()) / "tests" / "fuzz";
  size_t count = 0;
  for (const char* kind : {"crashes", "corpus"}) {
    for (const fs::path& p : filesIn(root / kind / target)) {
      const std::string name = p.filename().string();
      INFO("tests/fuzz/" << kind << "/" << target << "/" << name);
      const std::string bytes = bytesOf(p);
      lucent::fuzz::Outcome outcome;
      REQUIRE_NOTHROW(outcome =
                          replay(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()));
      CHECK(outcome.finding == "");
      if (std::string(kind) == "corpus") {
        REQUIRE((startsWith(name, "accept-") || startsWith(name, "refuse-")));
        CHECK(outcome.accepted == startsWith(name, "accept-"));
      }
      ++count;
    }
  }
  return count;
}

}  // namespace

TEST_CASE("fuzz regressions: scene parser inputs are refused or built cleanly", "[fuzz]") {
  const size_t n = replayAll("scene_parser", [](const uint8_t* d, size_t n) {
    return lucent::fuzz::sceneParser(d, n,
                                     std::string(lucentSourceDir()) + "/examples/fuzz-input.xml");
  });
  CHECK(n > 0);
}

TEST_CASE("fuzz regressions: POV-Ray scenes are imported and built cleanly, or refused located",
          "[fuzz][sdl]") {
  const size_t n = replayAll("pov_importer", [](const uint8_t* d, size_t n) {
    return lucent::fuzz::povImporter(d, n,
                                     std::string(lucentSourceDir()) + "/tests/data/sdl/samples");
  });
  CHECK(n >= 9);
}

TEST_CASE("fuzz regressions: transform syntax inputs keep their outcome", "[fuzz]") {
  const size_t n = replayAll("transform_syntax", [](const uint8_t* d, size_t n) {
    return lucent::fuzz::transformSyntax(d, n);
  });
  CHECK(n >= 20);
}

TEST_CASE("fuzz regressions: expression inputs are evaluated or refused at a place inside them",
          "[fuzz]") {
  const size_t n = replayAll(
      "expression", [](const uint8_t* d, size_t n) { return lucent::fuzz::expression(d, n); });
  CHECK(n > 0);
}

TEST_CASE("fuzz regressions: expansion programs give scenes that are refused or built cleanly",
          "[fuzz]") {
  const size_t n = replayAll(
      "expansion", [](const uint8_t* d, size_t n) { return lucent::fuzz::expansion(d, n); });
  CHECK(n > 0);
}

TEST_CASE("fuzz regressions: mesh reader inputs", "[fuzz]") {
  using lucent::MeshFormat;
  for (auto [target, format] :
       {std::pair{"mesh_obj", MeshFormat::Obj}, std::pair{"mesh_ply", MeshFormat::Ply},
        std::pair{"mesh_off", MeshFormat::Off}, std::pair{"mesh_stl", MeshFormat::Stl}}) {
    INFO(target);
    const size_t n = replayAll(target, [format = format](const uint8_t* d, size_t n) {
      return lucent::fuzz::meshReader(d, n, format);
    });
    CHECK(n > 0);
  }
}

TEST_CASE("fuzz regressions: font files for text are refused or laid out cleanly", "[fuzz]") {
  const size_t n = replayAll(
      "text_font", [](const uint8_t* d, size_t n) { return lucent::fuzz::fontReader(d, n); });
  CHECK(n > 0);
}

TEST_CASE(
    "fuzz regressions: height-field images are refused or read into a field that keeps the "
    "contract",
    "[fuzz]") {
  // The corpus holds readable images (accept-*) as well as damaged ones (refuse-*).
  const size_t n = replayAll(
      "height_map", [](const uint8_t* d, size_t n) { return lucent::fuzz::heightMapReader(d, n); });
  CHECK(n >= 4);
}

TEST_CASE(
    "fuzz harness: a located exception from building the world is a refusal, others are findings",
    "[fuzz]") {
  using lucent::fuzz::refusedInOrder;
  CHECK(refusedInOrder(std::runtime_error("scene.xml:3:5: error: singular transform")));
  CHECK(
      refusedInOrder(std::runtime_error("/a/b c.xml:12:1: error: the nested transforms overflow")));
  CHECK(refusedInOrder(lucent::LocatedError(lucent::SourceLoc{"scene.xml", 3, 5},
                                            "a camera that cannot frame the image")));
  CHECK(refusedInOrder(lucent::MeshError("mesh.obj: not a mesh")));
  CHECK_FALSE(refusedInOrder(std::runtime_error("vector::_M_range_check")));
  CHECK_FALSE(refusedInOrder(std::runtime_error(":3:5: error: no file")));
  CHECK_FALSE(refusedInOrder(std::runtime_error("scene.xml:x:5: error: no line")));
  CHECK_FALSE(refusedInOrder(std::logic_error("scene.xml:3:5: camera type 9 has no projection")));
}
