// The raw tokens of POV-Ray's lexical rules (sdl/source.h).
#include <catch2/catch.hpp>

#include "sdl/keywords.h"
#include "sdl/source.h"

#include <string>
#include <vector>

using namespace lucent::sdl;

namespace {

std::vector<RawToken> lex(const std::string& text) {
  SourceFile f("t.pov", ".", text);
  std::vector<RawToken> out;
  for (size_t i = 0;; ++i) {
    const RawToken& t = f.at(i);
    if (t.kind == RawKind::End) break;
    out.push_back(t);
  }
  return out;
}

std::string lexError(const std::string& text) {
  try {
    lex(text);
  } catch (const LexError& e) {
    return std::to_string(e.line) + ":" + std::to_string(e.col) + ": " + e.message;
  }
  return "";
}

}  // namespace

TEST_CASE("sdl lexer: POV-Ray's forms of numbers", "[sdl][lexer]") {
  auto t = lex("1. .5 1e-3 2.5E+2 7 1e 3.x");
  REQUIRE(t.size() == 8);
  CHECK(t[0].number == 1.0);
  CHECK(t[1].number == 0.5);
  CHECK(t[2].number == 0.001);
  CHECK(t[3].number == 250.0);
  CHECK(t[4].number == 7.0);
  CHECK(t[5].number == 1.0);  // "1e": the exponent never came
  CHECK(t[6].number == 3.0);
  CHECK(t[7].kind == RawKind::Word);
  CHECK(t[7].text == "x");
  CHECK(lexError("1.5.3") == "1:4: unexpected second '.' in a number");
}

TEST_CASE("sdl lexer: a period not followed by a digit is the period of V.x", "[sdl][lexer]") {
  auto t = lex("V.x");
  REQUIRE(t.size() == 3);
  CHECK(t[1].kind == RawKind::Punct);
  CHECK(t[1].text == ".");
}

TEST_CASE("sdl lexer: words, reserved words and operators", "[sdl][lexer]") {
  auto t = lex("sphere My_Id2 <= >= != < ! # ;");
  REQUIRE(t.size() == 9);
  CHECK(t[0].keyword >= 0);
  CHECK(keywordName(t[0].keyword) == "sphere");
  CHECK(t[1].keyword == -1);
  CHECK(t[2].text == "<=");
  CHECK(t[3].text == ">=");
  CHECK(t[4].text == "!=");
  CHECK(t[5].text == "<");
  CHECK(t[6].text == "!");
  CHECK(t[7].text == "#");
  CHECK(keywordKind(keywordIndex("vrotate")) == Kw::k_vrotate);
  CHECK(keywordKind(keywordIndex("sphere")) == Kw::None);
  CHECK(keywordIndex("sqr") >= 0);  // reserved, though not a function of the language
}

TEST_CASE("sdl lexer: strings keep their escapes for later, but an escaped quote ends no string",
          "[sdl][lexer]") {
  auto t = lex(R"("a\"b\n\\" "x")");
  REQUIRE(t.size() == 2);
  CHECK(t[0].text == R"(a"b\n\\)");
  CHECK(t[0].col == 1);
  CHECK(t[1].text == "x");
  CHECK(lexError("#declare S = \"abc") == "1:14: this string has no closing quote");
  CHECK(lexError("\"ab\\\ncd\"") == "1:1: this string is not closed before the end of its line");
  CHECK(lexError("\"" + std::string(256, 'a') + "\"") ==
        "1:1: string literal of 256 characters: POV-Ray 3.7 reads at most 255");
  CHECK(lex("\"" + std::string(255, 'a') + "\"").size() == 1);
}

TEST_CASE("sdl lexer: comments, block comments nest as in POV-Ray", "[sdl][lexer]") {
  auto t = lex("a // line\n/* b /* c */ d */ e");
  REQUIRE(t.size() == 2);
  CHECK(t[0].text == "a");
  CHECK(t[1].text == "e");
  CHECK(t[1].line == 2);
  CHECK(t[1].col == 19);
  CHECK(lexError("x\n  /* open /* inner */ still open") ==
        "2:3: this '/*' comment has no closing '*/'");
  CHECK(lexError("a $ \x01") == "1:5: illegal character in input file, value is 01");
}
