// Every file in tests/lang/invalid/ is a scene with known errors. Its first line states
// the expected error as an XML comment,
//   <!-- expect: LINE:COL: message fragment -->        (in the file itself)
//   <!-- expect: inc/x.xml:LINE:COL: message fragment --> (in a file it includes)
// further lines may add more "expect:" comments and "<!-- expect-errors: N -->" (the exact
// number of errors). Each expectation must match one error's file, line, column and
// contain the fragment; the scene must be refused. Files under invalid/inc/ are helpers.
#include "lang/parser.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace lucent;

namespace {

struct Expectation {
  std::string file;  // relative to the invalid/ folder
  int line = 0, col = 0;
  std::string fragment;
};

struct ExpectedErrors {
  std::vector<Expectation> errors;
  int count = -1;  // exact number of errors, if stated
};

ExpectedErrors readExpectations(const fs::path& path) {
  ExpectedErrors out;
  std::ifstream in(path);
  std::string line;
  const std::regex expect(R"(^<!-- expect: (?:(\S+\.xml):)?(\d+):(\d+): (.*) -->\s*$)");
  const std::regex count(R"(^<!-- expect-errors: (\d+) -->\s*$)");
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, expect)) {
      out.errors.push_back({m[1].matched ? m[1].str() : path.filename().string(), std::stoi(m[2]),
                            std::stoi(m[3]), m[4]});
    } else if (std::regex_match(line, m, count)) {
      out.count = std::stoi(m[1]);
    } else {
      break;  // expectations are the first lines only
    }
  }
  return out;
}

// Messages name files by the path given to the parser; the expectations are written
// relative to the invalid/ folder, so drop that prefix before comparing.
std::string relative(std::string text, const std::string& prefix) {
  for (size_t at; (at = text.find(prefix)) != std::string::npos;) text.erase(at, prefix.size());
  return text;
}

}  // namespace

TEST_CASE("lang: every invalid scene is refused with its expected located errors", "[lang][invalid]") {
  fs::path dir = fs::path(LUCENT_SOURCE_DIR) / "tests" / "lang" / "invalid";
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".xml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 45);

  const std::string prefix = dir.string() + "/";
  for (const fs::path& file : files) {
    SECTION(file.filename().string()) {
      ExpectedErrors expected = readExpectations(file);
      REQUIRE_FALSE(expected.errors.empty());  // the first line must say what is expected

      ParseResult r = parseSceneFile(file.string());
      std::string all;
      for (const Diagnostic& d : r.diagnostics.all()) all += relative(d.str(), prefix) + "\n";
      INFO("diagnostics:\n" << all);
      CHECK(r.scene == nullptr);
      CHECK_FALSE(r.ioFailure);
      CHECK(r.diagnostics.hasErrors());
      if (expected.count >= 0) CHECK(r.diagnostics.errorCount() == static_cast<size_t>(expected.count));

      for (const Expectation& e : expected.errors) {
        INFO("expected: " << e.file << ":" << e.line << ":" << e.col << ": ..." << e.fragment);
        bool found = false;
        for (const Diagnostic& d : r.diagnostics.all()) {
          if (d.severity != Severity::Error) continue;
          if (relative(d.loc.file, prefix) != e.file || d.loc.line != e.line || d.loc.col != e.col) continue;
          if (relative(d.message, prefix).find(e.fragment) != std::string::npos) found = true;
        }
        CHECK(found);
      }
    }
  }
}
