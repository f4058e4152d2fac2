// The parser, in-process, on the one bad-scene corpus (tests/bad/cases.txt, the format is
// described there): every `2 | check scenes/X.xml | ...` case is refused, by the parser or
// by checkRenderable after it, and each expected field appears among the lines `lucent
// check` would print (every diagnostic, then "N errors; the scene is invalid" or the
// located error of checkRenderable). tests/scripts/bad_inputs.sh runs the same cases
// through the binary, with time limits; this test runs them in the test build's sanitizers.
#include "../support/paths.h"
#include "lang/parser.h"
#include "render/scene_check.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace lucent;

namespace {

struct SceneCase {
  std::string scene;                  // as written in cases.txt, relative to tests/bad
  std::vector<std::string> expected;  // substrings of the output
};

std::vector<std::string> splitFields(const std::string& text) {
  std::vector<std::string> fields;
  for (size_t start = 0;;) {
    size_t bar = text.find(" | ", start);
    fields.push_back(
        text.substr(start, bar == std::string::npos ? std::string::npos : bar - start));
    if (bar == std::string::npos) break;
    start = bar + 3;
  }
  return fields;
}

// The cases that check one corpus scene with no other argument and expect status 2.
std::vector<SceneCase> checkCases(const fs::path& casesFile) {
  std::vector<SceneCase> out;
  std::ifstream in(casesFile);
  const std::regex line(R"(^2 \| check (scenes/\S+\.xml) \| (.*)$)");
  for (std::string text; std::getline(in, text);) {
    std::smatch m;
    if (!std::regex_match(text, m, line)) continue;
    out.push_back({m[1], splitFields(m[2])});
  }
  return out;
}

}  // namespace

TEST_CASE("lang: every invalid scene of the corpus is refused with its expected located errors",
          "[lang][invalid]") {
  const fs::path bad = fs::path(lucentSourceDir()) / "tests" / "bad";
  const std::vector<SceneCase> cases = checkCases(bad / "cases.txt");
  REQUIRE(cases.size() >= 180);

  // Messages name files by the path given to the parser: shown relative to tests/bad, as
  // the cases are written.
  const std::string prefix = bad.string() + "/";
  auto relative = [&](std::string text) {
    for (size_t at; (at = text.find(prefix)) != std::string::npos;) text.erase(at, prefix.size());
    return text;
  };
  for (const SceneCase& c : cases) {
    SECTION(c.scene) {
      ParseResult r = parseSceneFile((bad / c.scene).string());
      std::string out;
      for (const Diagnostic& d : r.diagnostics.all()) out += relative(d.str()) + "\n";
      if (r.scene) {
        // Parsed: then it is refused by what check and render run after parsing.
        try {
          checkRenderable(*r.scene, *r.scene->findCamera(""));
          out += "(accepted)\n";
        } catch (const LocatedError& e) {
          out += relative(e.what()) + "\n";
        }
      } else {
        const size_t n = r.diagnostics.errorCount();
        out += c.scene + ": " + std::to_string(n) + " error" + (n == 1 ? "" : "s") +
               "; the scene is invalid\n";
      }
      INFO("output:\n" << out);
      CHECK_FALSE(r.ioFailure);
      CHECK(out.find("(accepted)") == std::string::npos);
      for (const std::string& e : c.expected) {
        INFO("expected: " << e);
        CHECK(out.find(e) != std::string::npos);
      }
    }
  }
}
