// Every input the fuzzers ever found a problem with (tests/fuzz/crashes/TARGET/), replayed
// through the very function the libFuzzer target calls (fuzz/fuzz_inputs.h), in the normal
// build: under LUCENT_SANITIZE a regression is a sanitizer report, in any build a crash or
// an escaped exception. The README in that folder tells how inputs get there.
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

std::vector<fs::path> inputsOf(const std::string& target) {
  std::vector<fs::path> files;
  const fs::path dir = fs::path(LUCENT_SOURCE_DIR) / "tests" / "fuzz" / "crashes" / target;
  if (!fs::is_directory(dir)) return files;  // no input kept for this target yet
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().filename() != "README.md") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string bytesOf(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

template <class Replay>
void replayAll(const std::string& target, Replay replay) {
  for (const fs::path& p : inputsOf(target)) {
    INFO("tests/fuzz/crashes/" << target << "/" << p.filename().string());
    const std::string bytes = bytesOf(p);
    const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
    CHECK_NOTHROW(replay(data, bytes.size()));
  }
}

}  // namespace

TEST_CASE("fuzz regressions: scene parser inputs are refused or built cleanly", "[fuzz]") {
  replayAll("scene_parser", [](const uint8_t* d, size_t n) {
    lucent::fuzz::sceneParser(d, n, LUCENT_SOURCE_DIR "/examples/fuzz-input.xml");
  });
}

TEST_CASE("fuzz regressions: transform syntax inputs", "[fuzz]") {
  replayAll("transform_syntax", [](const uint8_t* d, size_t n) { lucent::fuzz::transformSyntax(d, n); });
}

TEST_CASE("fuzz regressions: mesh reader inputs", "[fuzz]") {
  using lucent::MeshFormat;
  for (auto [target, format] : {std::pair{"mesh_obj", MeshFormat::Obj}, std::pair{"mesh_ply", MeshFormat::Ply},
                                std::pair{"mesh_off", MeshFormat::Off}, std::pair{"mesh_stl", MeshFormat::Stl}}) {
    replayAll(target, [format = format](const uint8_t* d, size_t n) { lucent::fuzz::meshReader(d, n, format); });
  }
}
