// crand exported as POV-Ray's: Lucent's is a share of k_d, POV-Ray's multiplies its pigment,
// so the number written is crand times POV-Ray's diffuse share of k_d.
#include "pov_test_support.h"

using namespace lucent;
using namespace lucent::test;

TEST_CASE("crand is written beside diffuse as a share of the pigment", "[povray][crand]") {
  SECTION("a grey k_d: POV-Ray's diffuse carries it") {
    Exported e = exportScene(R"(<sphere><material diffuse="0.6" crand="0.5"/></sphere>)");
    REQUIRE(e.pov.ok());
    CHECK(e.has("diffuse 0.6\n"));
    CHECK(e.has("crand 0.3\n"));
  }
  SECTION("a coloured k_d: the pigment carries it, diffuse is 1") {
    Exported e = exportScene(R"(<sphere><material diffuse="0.8 0.4 0.2" crand="0.25"/></sphere>)");
    REQUIRE(e.pov.ok());
    CHECK(e.has("crand 0.25\n"));
  }
  SECTION("none without crand") {
    Exported e = exportScene(R"(<sphere><material diffuse="0.6"/></sphere>)");
    REQUIRE(e.pov.ok());
    CHECK(!e.has("crand"));
  }
}
