// POV-Ray's standard include files evaluate without error (their functions are the core's
// values; their item declarations are skipped by the test's item reader).
#include <catch2/catch.hpp>

#include "sdl_test_support.h"

TEST_CASE("sdl: the standard includes evaluate", "[sdl][include]") {
  for (const char* inc : {"colors.inc", "math.inc", "strings.inc", "rand.inc", "transforms.inc",
                          "arrays.inc", "consts.inc", "functions.inc"}) {
    INFO(inc);
    std::string e = sdltest::errorOf(std::string("#version 3.7;\n#include \"") + inc + "\"\n");
    CHECK(e == "");
  }
}

TEST_CASE("sdl: colors.inc declares POV-Ray's colours", "[sdl][include]") {
  CHECK(sdltest::debugOf("#include \"colors.inc\"\n#debug vstr(3, Orange, \",\", 0, 2)") ==
        "1.00,0.50,0.00");
}

TEST_CASE("sdl: math.inc's and functions.inc's functions evaluate", "[sdl][include][function]") {
  // math.inc: `#declare even = function(x) { select(mod(x, 2), 0, 1, 0) }`.
  CHECK(sdltest::debugOf("#include \"math.inc\"\n#debug str(even(4) + 10*odd(3), 0, 1)") == "11.0");
  CHECK(sdltest::debugOf("#include \"functions.inc\"\n#debug str(f_sphere(0, 2, 0, 0.5), 0, 3)") ==
        "1.500");
}
