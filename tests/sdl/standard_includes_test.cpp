// POV-Ray's standard include files evaluate without error (their function and item
// declarations are skipped by the test's item reader, as the scene reader will read them).
#include <catch2/catch.hpp>

#include "sdl_test_support.h"

TEST_CASE("sdl: the standard includes evaluate", "[sdl][include]") {
  for (const char* inc : {"colors.inc", "math.inc", "strings.inc", "rand.inc", "transforms.inc",
                          "arrays.inc", "consts.inc"}) {
    INFO(inc);
    std::string e = sdltest::errorOf(std::string("#version 3.7;\n#include \"") + inc + "\"\n");
    CHECK(e == "");
  }
}

TEST_CASE("sdl: colors.inc declares POV-Ray's colours", "[sdl][include]") {
  CHECK(sdltest::debugOf("#include \"colors.inc\"\n#debug vstr(3, Orange, \",\", 0, 2)") ==
        "1.00,0.50,0.00");
}
