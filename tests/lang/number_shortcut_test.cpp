// Parameters::evaluateNumbers, the shortcut numeric attributes take past the text round
// trip, must give exactly what substitution followed by the value syntax gives, and must
// decline (so that the textual way reports the error) whenever that way would not give
// plain numbers.
#include "lang/parameters.h"
#include "lang/values.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

using namespace lucent;

namespace {

struct Fixture {
  Diagnostics diags;
  Parameters params{{{"d", "0.25"}}, diags};
  SourceFile file{"t.xml", ".",
                  "<scene version=\"1\"><param name=\"r\" value=\"1.5\"/>"
                  "<param name=\"v\" value=\"1 2 3\"/></scene>"};
  Fixture() {
    REQUIRE_FALSE(file.parse());
    for (pugi::xml_node p = file.root().child("param"); p; p = p.next_sibling("param"))
      params.declare(p.attribute("name").value(), p.attribute("value").value(), file, p);
  }
};

}  // namespace

TEST_CASE("the numeric shortcut agrees with substitution and the value syntax",
          "[lang][expressions]") {
  Fixture f;
  const char* threes[] = {"${r} 0 ${2*r}", "1, ${r}, 3", "  ${r*1e-3}\t${-r} ${d} ",
                          "${0.1+0.2} 1e3 -0", "${pi} ${e} ${sqrt(2)}"};
  for (const char* raw : threes) {
    INFO(raw);
    double fast[3];
    REQUIRE(f.params.evaluateNumbers(raw, nullptr, fast, 3));
    SubstitutionError error;
    auto text = f.params.substitute(raw, nullptr, error);
    REQUIRE(text);
    Parsed<Vec3> slow = parseVector(*text);
    REQUIRE(slow);
    for (int k = 0; k < 3; ++k) {
      CHECK(std::memcmp(&fast[k], &(*slow)[k], sizeof(double)) == 0);  // the same bits
    }
  }
}

TEST_CASE("the numeric shortcut declines what the textual way must judge", "[lang][expressions]") {
  Fixture f;
  // Wrong counts, separators the value syntax refuses, glued tokens, $name without braces,
  // a parameter that is not one number, values out of the accepted range, errors.
  const char* declined[] = {"${r} 0",      "${r} 0 0 0",   "1,,${r},3",  ",1 ${r} 3",
                            "1 ${r} 3,",   "1${r} 0",      "$r 0 0",     "${v}",
                            "${1e31} 0 0", "${1e-31} 0 0", "${1/0} 0 0", "${rr} 0 0",
                            "+1 ${r} 0",   "${r}x 0 0",    "${r",        "inf ${r} 0"};
  for (const char* raw : declined) {
    INFO(raw);
    double out[3];
    CHECK_FALSE(f.params.evaluateNumbers(raw, nullptr, out, 3));
  }
  double one;
  CHECK(f.params.evaluateNumbers(" ${r} ", nullptr, &one, 1));
  CHECK(one == 1.5);
  CHECK_FALSE(f.params.evaluateNumbers("${r} ${r}", nullptr, &one, 1));
  // "${v}" as three numbers: not one number per token, so the textual way substitutes it.
  double three[3];
  CHECK_FALSE(f.params.evaluateNumbers("${v}", nullptr, three, 3));
}
