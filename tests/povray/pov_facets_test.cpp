// export-pov's facets: the keyword in a normal with its size, coords and metric always
// written, so that POV-Ray's defaults cannot drift.
#include "povray/pov_patterns.h"

#include <catch2/catch.hpp>

using namespace lucent;

TEST_CASE("export-pov writes facets with its size, coords and metric", "[povray][patterns]") {
  NormalSpec n;
  n.pattern.type = PatternType::facets;
  n.pattern.facets = {0.25, 0.4, 1.0};
  PovWriter out;
  writeNormal(n, out);
  const std::string text = out.text();
  INFO(text);
  CHECK(text.find("facets 0.5") != std::string::npos);
  CHECK(text.find("size 0.25 coords 0.4 metric 1") != std::string::npos);
}
