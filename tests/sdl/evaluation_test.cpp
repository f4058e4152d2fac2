// The language core's evaluation, part by part: values and promotions, directives,
// macros and scoping, arrays, limits (sdl/token_stream.h).
#include <catch2/catch.hpp>

#include "sdl_test_support.h"

#include "sdl/random.h"

using namespace lucent::sdl;
using sdltest::debugOf;
using sdltest::errorOf;

TEST_CASE("sdl: a float where a vector is wanted fills every component", "[sdl][values]") {
  CHECK(debugOf("#declare V = 2 + <1, 2, 3>; #debug vstr(3, V, \",\", 0, 0)") == "3,4,5");
  CHECK(debugOf("#declare V = <1, 2> + <1, 1, 1>; #debug vstr(3, V, \",\", 0, 0)") == "2,3,1");
  CHECK(debugOf("#declare C = color 0.5; #debug vstr(5, C, \",\", 0, 1)") == "0.5,0.5,0.5,0.5,0.5");
  CHECK(debugOf("#declare C = rgbt <1, 0, 0, 0.5>; #debug vstr(5, C, \",\", 0, 1)") ==
        "1.0,0.0,0.0,0.0,0.5");
}

TEST_CASE("sdl: the types of declared values", "[sdl][values]") {
  CollectedOutput out;
  Options o;
  o.output = &out;
  TokenStream in(o);
  in.openText("t.pov",
              "#declare F = 1; #declare U = <1, 2>; #declare V = <1, 2, 3>;\n"
              "#declare W = <1, 2, 3, 4>; #declare C = rgb 1; #declare S = \"s\";\n"
              "#declare A = array[2][3];",
              ".");
  CHECK(in.next().kind == TokenKind::End);
  CHECK(in.lookup("F")->type == ValueType::Float);
  CHECK(in.lookup("U")->type == ValueType::Uv);
  CHECK(in.lookup("V")->type == ValueType::Vector);
  CHECK(in.lookup("W")->type == ValueType::Vector4);
  CHECK(in.lookup("C")->type == ValueType::Colour);
  CHECK(*in.lookup("S")->str == "s");
  REQUIRE(in.lookup("A")->type == ValueType::Array);
  CHECK(in.lookup("A")->array->sizes == std::vector<int>{2, 3});
  CHECK(in.lookup("A")->array->elements.size() == 6);
  CHECK(in.lookup("Nothing") == nullptr);
}

TEST_CASE("sdl: POV-Ray's generator gives POV-Ray's numbers", "[sdl][random]") {
  // The first numbers of seed(0) and seed(12345), as POV-Ray 3.7 prints them
  // (tests/data/sdl/random.out).
  std::uint32_t s = 0;
  CHECK(povRand(s) == Approx(0.0000028743).margin(1e-10));
  std::uint32_t t = 12345;
  CHECK(povRand(t) == Approx(0.4665636845).margin(1e-10));
  CHECK(debugOf("#declare R = seed(12345); #debug str(rand(R), 0, 10)") == "0.4665636845");
}

TEST_CASE("sdl: directives inside skipped parts are counted, not done", "[sdl][directives]") {
  CHECK(debugOf("#if (0) #while (1) #declare X = ; #end #debug \"no\" #else #debug \"yes\" #end") ==
        "yes");
  CHECK(debugOf("#ifdef (Q) #debug \"a\" #elseif (1) #debug \"b\" #else #debug \"c\" #end") == "b");
  CHECK(debugOf("#macro M() #if (1) #end #end #debug \"defined\"") == "defined");
}

TEST_CASE("sdl: #declare assigns the innermost visible identifier, #local one of the current table",
          "[sdl][scope]") {
  CHECK(debugOf("#declare A = 1;\n"
                "#macro M() #local A = 2; #declare A = 3; #debug str(A, 0, 0) #end\n"
                "M() #debug str(A, 0, 0)") == "31");
  CHECK(debugOf("#macro M() #local B = 2; #end M() #debug str(defined(B), 0, 0)") == "0");
}

TEST_CASE("sdl: macro parameters: lone identifiers by reference, expressions by value",
          "[sdl][macros]") {
  CHECK(debugOf("#macro Set(P) #declare P = 9; #end\n"
                "#declare A = 1; #declare B = 1; Set(A) Set(B + 0)\n"
                "#debug concat(str(A, 0, 0), str(B, 0, 0))") == "91");
  CHECK(debugOf("#macro Set(P) #declare P = \"x\"; #end\n"
                "#declare S = \"a\"; Set(S) #debug S") == "x");
}

TEST_CASE("sdl: a macro's value is its tokens, read where it is called", "[sdl][macros]") {
  CHECK(debugOf("#macro Two() 1 + 1 #end #debug str(Two() * 3, 0, 0)") == "4");
  CHECK(debugOf("#macro Two() (1 + 1) #end #debug str(Two() * 3, 0, 0)") == "6");
}

TEST_CASE("sdl: the include search: the scene's folder, then the library folders",
          "[sdl][include]") {
  Options o;
  o.includeFolders = {sdltest::dataFolder()};
  CHECK(debugOf("#declare A = 1; #include \"scoping.inc\" #debug str(A, 0, 0)", nullptr, o) ==
        "in 100\n2");
  o.includeFolders = {};
  std::string e = errorOf("#include \"no_such_file.inc\"", o);
  CHECK(e.rfind("test.pov:1:1: error: cannot open include file 'no_such_file.inc' (searched ", 0) ==
        0);
}

TEST_CASE("sdl: #debug and #warning reach the output as POV-Ray prints them", "[sdl][output]") {
  CollectedOutput out;
  debugOf("#debug \"a\\tb\\n\"\n#warning concat(\"w\", str(1, 0, 0))", &out);
  CHECK(out.debugText == "a\tb\n");
  REQUIRE(out.warnings.size() == 1);
  CHECK(out.warnings[0] == "test.pov:2:1: warning: w1");
}

TEST_CASE("sdl: division by zero is a warning and gives a huge value, as in POV-Ray",
          "[sdl][errors]") {
  CollectedOutput out;
  CHECK(debugOf("#declare X = 1 / 0;\n#debug str(X, 0, 0)", &out) == "inf");
  REQUIRE(out.warnings.size() == 1);
  CHECK(out.warnings[0] == "test.pov:1:16: warning: divide by zero");
}

TEST_CASE("sdl: the frame identifiers and declared values come from the options", "[sdl][values]") {
  Options o;
  o.clock = 0.25;
  o.frameNumber = 3;
  o.imageWidth = 640;
  o.declared["Quality"] = 2;
  CHECK(debugOf("#debug concat(str(clock, 0, 2), str(frame_number, 0, 0), str(image_width, 0, "
                "0), str(Quality, 0, 0))",
                nullptr, o) == "0.2536402");
}

TEST_CASE("sdl: an endless #while ends with an error at the loop", "[sdl][limits]") {
  CHECK(errorOf("#declare I = 0;\n#while (1)\n  #declare I = I + 1;\n#end") ==
        "test.pov:2:1: error: this #while loop ran more than 1000000 times (the limit of one "
        "loop; see docs/povray-import.md)");
  Options o;
  o.limits.loopIterations = 10;
  CHECK(errorOf("#for (I, 1, 11) #end", o) ==
        "test.pov:1:1: error: this #for loop ran more than 10 times (the limit of one loop; see "
        "docs/povray-import.md)");
  CHECK(errorOf("#for (I, 1, 10) #end", o) == "");
}

TEST_CASE("sdl: endless recursion and runaway strings are refused", "[sdl][limits]") {
  CHECK(errorOf("#macro R(N) R(N + 1) #end\n#declare X = R(1);")
            .rfind("test.pov:1:13: error: macro calls and include files nested more than 100 deep",
                   0) == 0);
  Options o;
  o.limits.stringLength = 100;
  CHECK(errorOf("#declare S = \"0123456789\";\n#while (1) #declare S = concat(S, S); #end", o)
            .rfind("test.pov:2:35: error: a string of more than 100 characters", 0) == 0);
  o = Options{};
  o.limits.tokens = 1000;
  CHECK(errorOf("#declare I = 0; #while (I < 1000) #declare I = I + 1; #end", o)
            .find("error: the scene reads more than 1000 tokens") != std::string::npos);
}
