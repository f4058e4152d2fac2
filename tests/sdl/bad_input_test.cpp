// Bad POV-Ray input: each refused with its message at its place, and the macro calls and
// includes that led there as notes.
#include <catch2/catch.hpp>

#include "sdl_test_support.h"

#include "sdl/evaluate.h"

using namespace lucent::sdl;
using sdltest::errorOf;

TEST_CASE("sdl bad input: unterminated strings, comments and directives", "[sdl][errors]") {
  CHECK(errorOf("#declare S = \"abc") == "test.pov:1:14: error: this string has no closing quote");
  CHECK(errorOf("#declare A = 1;\n/* never closed") ==
        "test.pov:2:1: error: this '/*' comment has no closing '*/'");
  CHECK(errorOf("#if (1)\n  #debug \"x\"\n") ==
        "test.pov:1:1: error: this #if has no #end before the end of the file");
  CHECK(errorOf("#macro M(A)\n  A\n") ==
        "test.pov:1:1: error: this #macro has no #end before the end of the file");
  CHECK(errorOf("#declare I = 0;\n#while (I < 3) #declare I = I + 1;\n") ==
        "test.pov:2:1: error: this #while has no #end before the end of the file");
}

TEST_CASE("sdl bad input: macro calls with too few or too many arguments", "[sdl][errors]") {
  CHECK(errorOf("#macro M(A, B) A + B #end\n#declare X = M(1);") ==
        "test.pov:2:17: error: macro 'M' expects 2 parameters but only 1 was given");
  CHECK(errorOf("#macro M(A) A #end\n#declare X = M(1, 2);") ==
        "test.pov:2:19: error: macro 'M' takes 1 parameter: expected ')', found float constant");
  CHECK(errorOf("#macro M(A) A #end\n#declare X = M;") ==
        "test.pov:2:15: error: expected '(' after macro 'M', found ';'");
}

TEST_CASE("sdl bad input: undeclared identifiers", "[sdl][errors]") {
  CHECK(errorOf("#declare X = Y + 1;") == "test.pov:1:14: error: undeclared identifier 'Y'");
  CHECK(errorOf("#declare X = 1 + Y;") ==
        "test.pov:1:18: error: expected a numeric expression, found undeclared identifier 'Y'");
  CHECK(errorOf("#declare x = 1;") ==
        "test.pov:1:10: error: 'x' is a reserved word; it cannot be declared");
}

TEST_CASE("sdl bad input: errors inside macros and includes name the way there", "[sdl][errors]") {
  CHECK(errorOf("#macro M()\n  #declare A = B;\n#end\nM()") ==
        "test.pov:2:16: error: undeclared identifier 'B'\n"
        "test.pov:4:1: note: in macro 'M' called here");
  CHECK(errorOf("#macro M()\n  #include \"bad_include.inc\"\n#end\nM()") ==
        "bad_include.inc:2:14: error: undeclared identifier 'Missing'\n"
        "test.pov:2:3: note: in the file included here\n"
        "test.pov:4:1: note: in macro 'M' called here");
}

TEST_CASE("sdl bad input: directives out of place", "[sdl][errors]") {
  CHECK(errorOf("#end") ==
        "test.pov:1:1: error: #end without an open #if, #while, #for, #switch or #macro");
  CHECK(errorOf("#else") ==
        "test.pov:1:1: error: #else without a matching #if, #ifdef, #ifndef or #switch");
  CHECK(errorOf("#break") ==
        "test.pov:1:1: error: #break outside of a #while, #for, #switch or macro");
  CHECK(errorOf("#switch (1) foo #end") ==
        "test.pov:1:13: error: #switch not followed by #case or #range (found undeclared "
        "identifier 'foo')");
  CHECK(errorOf("#error concat(\"bo\", \"om\")") ==
        "test.pov:1:1: error: parse halted by #error directive: boom");
  CHECK(errorOf("#version 3.8;") ==
        "test.pov:1:10: error: this scene requires POV-Ray version 3.8 or later (Lucent reads "
        "POV-Ray 3.7)");
}

TEST_CASE("sdl bad input: values of the wrong kind", "[sdl][errors]") {
  CHECK(errorOf("#declare X = sqrt(-1);") ==
        "test.pov:1:14: error: sqrt of negative number -1.000000");
  CHECK(errorOf("#declare X = 1; #if (<1,2,3>) #end") ==
        "test.pov:1:29: error: float expected but vector or color expression found");
  CHECK(errorOf("#declare X = 1\n#declare Y = 2;") ==
        "test.pov:2:1: error: expected ';' after the value: every #declare or #local of a float, "
        "vector or colour ends with ';' since POV-Ray 3.5 (found '#')");
  CHECK(errorOf("#declare R = rand(3);") ==
        "test.pov:1:14: error: illegal random number generator: 3 is not a stream made by seed()");
  CHECK(errorOf("#declare C = srgb 0.5;") ==
        "test.pov:1:14: error: cannot parse sRGB colors before assumed_gamma has been set");
}

TEST_CASE("sdl bad input: arrays", "[sdl][errors]") {
  CHECK(errorOf("#declare A = array[2];\n#declare B = A[2];") ==
        "test.pov:2:15: error: array subscript 2 out of range (dimension 1 has 2 elements)");
  CHECK(errorOf("#declare A = array[2];\n#declare B = A[1];") ==
        "test.pov:2:14: error: 'A': attempt to access an uninitialized array element");
  CHECK(errorOf("#declare A = array[2] {1, <1, 2, 3>};") ==
        "test.pov:1:27: error: attempted to redefine float identifier as vector identifier (the "
        "elements of a POV-Ray 3.7 array have one type)");
  CHECK(errorOf("#declare A = array[2] {1};") ==
        "test.pov:1:25: error: insufficient number of initializers: expected 2, found '}'");
}

TEST_CASE("sdl bad input: evaluateText refuses the first scene item where it is", "[sdl][errors]") {
  try {
    evaluateText("scene.pov", "#declare R = 2;\n  sphere { 0, R }", ".", Options{});
    FAIL("no error");
  } catch (const SdlError& e) {
    CHECK(std::string(e.what()) ==
          "scene.pov:2:3: error: 'sphere' is not read yet (Lucent's POV-Ray reader evaluates the "
          "language, not yet the scene items)");
  }
}

TEST_CASE("sdl bad input: vstr() wider than POV-Ray's buffer is refused before it is written",
          "[sdl][errors]") {
  CHECK(errorOf("#declare S = vstr(3, <1, 2, 3>, \",\", 0, 100000000);") ==
        "test.pov:1:14: error: vstr(): a component's text would be longer than POV-Ray's 767 "
        "characters (width 0, precision 100000000)");
  CHECK(errorOf("#declare S = vstr(2, <1e300, 2>, \",\", 0, 700);") ==
        "test.pov:1:14: error: vstr(): a component's text is longer than POV-Ray's 767 "
        "characters");
}
