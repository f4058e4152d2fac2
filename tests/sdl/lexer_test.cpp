// The raw tokens of POV-Ray's lexical rules (sdl/source.h).
#include <catch2/catch.hpp>

#include "sdl/keywords.h"
#include "sdl/source.h"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

using namespace lucent::sdl;

namespace {

// The tokens of `text`, with the file they view kept alive beside them.
struct Lexed {
  std::unique_ptr<SourceFile> file;
  std::vector<RawToken> tokens;
  size_t size() const { return tokens.size(); }
  const RawToken& operator[](size_t i) const { return tokens.at(i); }
};

Lexed lex(const std::string& text) {
  Lexed out{std::make_unique<SourceFile>("t.pov", ".", text), {}};
  for (size_t i = 0;; ++i) {
    const RawToken& t = out.file->at(i);
    if (t.kind == RawKind::End) break;
    out.tokens.push_back(t);
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

TEST_CASE("sdl lexer: CR, CR LF and LF CR end lines as LF does, as POV-Ray's text stream reads",
          "[sdl][lexer]") {
  // A file of old Mac line ends: each `//` comment ends at its CR.
  auto mac = lex("// title\ra // note\r\rb\r  c");
  REQUIRE(mac.size() == 3);
  CHECK(mac[0].text == "a");
  CHECK(mac[0].line == 2);
  CHECK(mac[1].text == "b");
  CHECK(mac[1].line == 4);
  CHECK(mac[2].line == 5);
  CHECK(mac[2].col == 3);
  // CR LF and LF CR are one line end each; LF CR LF is two.
  auto mixed = lex("a\r\nb\n\rc\n\r\nd");
  REQUIRE(mixed.size() == 4);
  CHECK(mixed[1].line == 2);
  CHECK(mixed[2].line == 3);
  CHECK(mixed[3].line == 5);
}

TEST_CASE("sdl lexer: numbers beyond a double's range read as strtod reads them", "[sdl][lexer]") {
  auto t = lex("1e999 1e-400 .25e1");
  REQUIRE(t.size() == 3);
  CHECK(std::isinf(t[0].number));
  CHECK(t[1].number == 0.0);
  CHECK(t[2].number == 2.5);
  CHECK(t[2].text == ".25e1");
}

TEST_CASE("sdl lexer: lines and columns after comments and strings that span lines",
          "[sdl][lexer]") {
  auto t = lex("a /* one\ntwo\n */ b \"x\ny\" c\n\t// note\n  d");
  REQUIRE(t.size() == 5);
  CHECK((t[1].line == 3 && t[1].col == 5));
  CHECK((t[2].line == 3 && t[2].col == 7));
  CHECK(t[2].text == "x\ny");
  CHECK((t[3].text == "c" && t[3].line == 4 && t[3].col == 4));
  CHECK((t[4].text == "d" && t[4].line == 6 && t[4].col == 3));
}

TEST_CASE("sdl lexer: tokens keep their place as the file is read further", "[sdl][lexer]") {
  std::string text;
  for (int i = 0; i < 5000; ++i) text += "w" + std::to_string(i) + " ";
  SourceFile f("t.pov", ".", text);
  const RawToken& first = f.at(0);
  const RawToken& last = f.at(4999);
  CHECK(first.text == "w0");  // still valid after 5000 tokens were read
  CHECK(last.text == "w4999");
  CHECK(last.col == static_cast<int>(text.size()) - 5);
  CHECK(f.at(5000).kind == RawKind::End);
  CHECK(f.at(7000).kind == RawKind::End);
}
