// Lucent's language core against POV-Ray itself: each script of tests/data/sdl prints
// values with #debug; NAME.out is what POV-Ray 3.7 printed (its debug stream, whose lines
// it cuts at 160 and then 80 characters: sdl/console_text.h) (tests/data/sdl/record.sh
// records them again), and Lucent must print the same, byte for byte.
#include <catch2/catch.hpp>

#include "sdl_test_support.h"

#include "sdl/console_text.h"

#include <fstream>
#include <sstream>

using namespace lucent::sdl;

namespace {

std::string readFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The #debug output of tests/data/sdl/NAME.pov, its items skipped.
std::string lucentOutput(const std::string& name) {
  CollectedOutput out;
  Options o;
  o.output = &out;
  sdltest::SkippingItemReader items;
  TokenStream in(o, &items);
  in.openFile(sdltest::dataFolder() / (name + ".pov"));
  for (;;) {
    const Token& t = in.next();
    if (t.kind == TokenKind::End) break;
    REQUIRE(t.kind == TokenKind::Keyword);
    items.read(t, in);
  }
  return povPrinted(out.debugText);  // in lines as POV-Ray prints them
}

void compareWithPovRay(const std::string& name) {
  const std::string expected = readFile(sdltest::dataFolder() / (name + ".out"));
  REQUIRE(!expected.empty());
  std::string actual;
  try {
    actual = lucentOutput(name);
  } catch (const SdlError& e) {
    FAIL(e.what());
  }
  CHECK(actual == expected);
}

}  // namespace

TEST_CASE("sdl vs POV-Ray: expressions, promotions and colours", "[sdl][povray]") {
  compareWithPovRay("expressions");
}

TEST_CASE("sdl vs POV-Ray: the built-in functions", "[sdl][povray]") {
  compareWithPovRay("builtins");
}

TEST_CASE("sdl vs POV-Ray: strings and str() formats", "[sdl][povray]") {
  compareWithPovRay("strings");
}

TEST_CASE("sdl vs POV-Ray: rand() and seed() sequences", "[sdl][povray]") {
  compareWithPovRay("random");
}

TEST_CASE("sdl vs POV-Ray: conditions, loops, #switch and #break", "[sdl][povray]") {
  compareWithPovRay("loops");
}

TEST_CASE("sdl vs POV-Ray: macros, references, recursion and scoping", "[sdl][povray]") {
  compareWithPovRay("macros");
}

TEST_CASE("sdl vs POV-Ray: arrays", "[sdl][povray]") { compareWithPovRay("arrays"); }

TEST_CASE("sdl vs POV-Ray: include files and their #local identifiers", "[sdl][povray]") {
  compareWithPovRay("scoping");
}

TEST_CASE("sdl vs POV-Ray: the standard includes and their macros", "[sdl][povray]") {
  compareWithPovRay("includes");
}

TEST_CASE("sdl vs POV-Ray: corner cases of conversions, references and colours", "[sdl][povray]") {
  compareWithPovRay("edges");
}

TEST_CASE("sdl vs POV-Ray: #debug text in lines cut as POV-Ray cuts them", "[sdl][povray]") {
  compareWithPovRay("wrap");
}

TEST_CASE("sdl vs POV-Ray: user-defined functions and functions.inc's closed forms",
          "[sdl][povray][function]") {
  compareWithPovRay("functions");
}

TEST_CASE("sdl vs POV-Ray: splines of every kind, calls, copies and spline functions",
          "[sdl][povray][spline]") {
  compareWithPovRay("splines");
}
