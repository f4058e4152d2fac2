#include "pov_gamma.h"

#include <fmt/core.h>

#include <cctype>
#include <cstdlib>

namespace lucent {

namespace {

bool identStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// A cursor over POV-Ray source that steps over whitespace, comments and strings.
struct Scanner {
  const std::string& s;
  size_t i = 0;
  int line = 1;

  bool done() const { return i >= s.size(); }
  void advance() {
    if (s[i] == '\n') ++line;
    ++i;
  }
  // Skips whitespace and comments (POV-Ray's block comments nest).
  void skipSpace() {
    while (!done()) {
      if (std::isspace(static_cast<unsigned char>(s[i]))) {
        advance();
      } else if (s.compare(i, 2, "//") == 0) {
        while (!done() && s[i] != '\n') advance();
      } else if (s.compare(i, 2, "/*") == 0) {
        int depth = 0;
        do {
          if (s.compare(i, 2, "/*") == 0) ++depth, advance(), advance();
          else if (s.compare(i, 2, "*/") == 0) --depth, advance(), advance();
          else advance();
        } while (!done() && depth > 0);
      } else {
        return;
      }
    }
  }
  void skipString() {
    advance();  // the opening quote
    while (!done() && s[i] != '"') {
      if (s[i] == '\\' && i + 1 < s.size()) advance();
      advance();
    }
    if (!done()) advance();
  }
  std::string identifier() {
    size_t start = i;
    while (!done() && identChar(s[i])) advance();
    return s.substr(start, i - start);
  }
  // A number literal: digits, a point, an exponent. Empty if there is none here.
  std::string number() {
    size_t start = i;
    while (!done() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.')) advance();
    if (i > start && !done() && (s[i] == 'e' || s[i] == 'E')) {
      size_t mark = i;
      advance();
      if (!done() && (s[i] == '+' || s[i] == '-')) advance();
      if (done() || !std::isdigit(static_cast<unsigned char>(s[i]))) i = mark;
      while (!done() && std::isdigit(static_cast<unsigned char>(s[i]))) advance();
    }
    return s.substr(start, i - start);
  }
};

// What follows `assumed_gamma`: a number or srgb, and then no operator that would make it
// an expression.
PovAssumedGamma readValue(Scanner& sc, int line) {
  PovAssumedGamma g;
  g.line = line;
  sc.skipSpace();
  std::string written;
  if (!sc.done() && identStart(sc.s[sc.i])) {
    written = sc.identifier();
    if (written == "srgb") g.kind = PovAssumedGamma::Kind::Srgb;
  } else if (!sc.done()) {
    written = sc.number();
    char* end = nullptr;
    double v = written.empty() ? 0.0 : std::strtod(written.c_str(), &end);
    if (!written.empty() && end && *end == '\0' && v > 0.0) {
      g.kind = PovAssumedGamma::Kind::Number;
      g.value = v;
    }
  }
  sc.skipSpace();
  const bool operatorFollows =
      !sc.done() && std::string_view("+-*/^?<>=&|.(").find(sc.s[sc.i]) != std::string_view::npos;
  if (g.kind == PovAssumedGamma::Kind::Absent || operatorFollows) {
    if (written.empty() && !sc.done()) written = sc.s.substr(sc.i, 1);
    g.kind = PovAssumedGamma::Kind::Unreadable;
    g.problem = fmt::format("line {}: assumed_gamma {}{} is not a plain number or srgb", line,
                            written, operatorFollows ? " ..." : "");
  }
  return g;
}

}  // namespace

std::string PovAssumedGamma::fileGamma() const {
  if (kind == Kind::Srgb) return "sRGB";
  if (kind == Kind::Number) {
    std::string v = fmt::format("{}", value);  // shortest exact form; "1.0" rather than "1"
    return v.find_first_of(".e") == std::string::npos ? v + ".0" : v;
  }
  return "1.0";
}

PovAssumedGamma findAssumedGamma(const std::string& text) {
  PovAssumedGamma found;
  Scanner sc{text};
  while (true) {
    sc.skipSpace();
    if (sc.done()) return found;
    const char c = text[sc.i];
    if (c == '"') {
      sc.skipString();
    } else if (identStart(c)) {
      const int line = sc.line;
      if (sc.identifier() != "assumed_gamma") continue;
      PovAssumedGamma g = readValue(sc, line);
      if (g.kind == PovAssumedGamma::Kind::Unreadable) return g;
      if (found.kind != PovAssumedGamma::Kind::Absent &&
          (g.kind != found.kind || g.value != found.value)) {
        PovAssumedGamma several;
        several.kind = PovAssumedGamma::Kind::Unreadable;
        several.line = found.line;
        several.problem = fmt::format(
            "lines {} and {} give different assumed_gamma values "
            "({} and {})",
            found.line, g.line, found.fileGamma(), g.fileGamma());
        return several;
      }
      if (found.kind == PovAssumedGamma::Kind::Absent) found = g;
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      sc.number();  // so that "1e5" does not read as an identifier e5
    } else {
      sc.advance();
    }
  }
}

}  // namespace lucent
