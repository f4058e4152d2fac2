// Reading assumed_gamma out of a hand-written POV-Ray scene (povray/pov_gamma.h): numbers,
// srgb, comments and strings stepped over, and what compare must refuse.
#include <catch2/catch.hpp>

#include "povray/pov_gamma.h"

using namespace lucent;
using Kind = PovAssumedGamma::Kind;

TEST_CASE("pov gamma: a number or srgb in global_settings, with its line", "[povray][gamma]") {
  PovAssumedGamma g = findAssumedGamma("#version 3.7;\nglobal_settings { assumed_gamma 2.2 }\n");
  CHECK(g.kind == Kind::Number);
  CHECK(g.value == 2.2);
  CHECK(g.line == 2);
  CHECK(g.nonLinear());
  CHECK(g.fileGamma() == "2.2");

  g = findAssumedGamma("global_settings{assumed_gamma 1.0}");
  CHECK(g.kind == Kind::Number);
  CHECK_FALSE(g.nonLinear());
  CHECK(g.fileGamma() == "1.0");

  g = findAssumedGamma("global_settings { assumed_gamma srgb max_trace_level 5 }");
  CHECK(g.kind == Kind::Srgb);
  CHECK(g.nonLinear());
  CHECK(g.fileGamma() == "sRGB");

  g = findAssumedGamma("global_settings { assumed_gamma 1.8e0 }");
  CHECK(g.kind == Kind::Number);
  CHECK(g.value == 1.8);
}

TEST_CASE("pov gamma: comments and strings do not count", "[povray][gamma]") {
  PovAssumedGamma g = findAssumedGamma(
      "// assumed_gamma 2.2\n"
      "/* an old header: /* nested */ global_settings { assumed_gamma 2.2 } */\n"
      "#declare Name = \"assumed_gamma 2.2\";\n"
      "global_settings { assumed_gamma 1.0 }\n");
  CHECK(g.kind == Kind::Number);
  CHECK(g.value == 1.0);
  CHECK(g.line == 4);

  CHECK(findAssumedGamma("#version 3.7; // assumed_gamma 2.2\nsphere { 0, 1 }").kind ==
        Kind::Absent);
}

TEST_CASE("pov gamma: expressions, names and disagreeing values are unreadable",
          "[povray][gamma]") {
  PovAssumedGamma g = findAssumedGamma("#declare G = 2.2;\nglobal_settings { assumed_gamma G }");
  CHECK(g.kind == Kind::Unreadable);
  CHECK(g.problem == "line 2: assumed_gamma G is not a plain number or srgb");

  g = findAssumedGamma("global_settings { assumed_gamma 1.1 * 2 }");
  CHECK(g.kind == Kind::Unreadable);
  CHECK(g.problem == "line 1: assumed_gamma 1.1 ... is not a plain number or srgb");

  g = findAssumedGamma("global_settings { assumed_gamma -1 }");
  CHECK(g.kind == Kind::Unreadable);

  g = findAssumedGamma(
      "#if (Old)\nglobal_settings { assumed_gamma 2.2 }\n#else\n"
      "global_settings { assumed_gamma 1.0 }\n#end\n");
  CHECK(g.kind == Kind::Unreadable);
  CHECK(g.problem == "lines 2 and 4 give different assumed_gamma values (2.2 and 1.0)");

  // The same value twice is one answer.
  g = findAssumedGamma(
      "global_settings { assumed_gamma 2.2 }\nglobal_settings { assumed_gamma 2.2 }");
  CHECK(g.kind == Kind::Number);
  CHECK(g.value == 2.2);
}
