// POV-Ray's lexical rules (POV-Ray 3.7's tokenizer, read for the facts): block comments
// nest; a number is digits with at most one '.', then optionally e/E, a sign and digits,
// and a '.' not followed by a digit is the period of `V.x`; a string literal ends at the
// first unescaped quote and may not hold a line break after a backslash.
#include "source.h"

#include "keywords.h"

#include <cctype>
#include <cstdio>
#include <cstdlib>

namespace lucent::sdl {

namespace {

// POV-Ray 3.7 keeps a string literal in a buffer of 256 characters and refuses a longer one.
constexpr size_t kMaxLiteralLength = 255;

bool isWordStart(int c) { return std::isalpha(c) || c == '_'; }
bool isWordChar(int c) { return std::isalnum(c) || c == '_'; }

std::string hex2(int c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%02x", c & 0xff);
  return buf;
}

}  // namespace

SourceFile::SourceFile(std::string name, std::filesystem::path folder, std::string text)
    : name_(std::move(name)), folder_(std::move(folder)), text_(std::move(text)) {}

const RawToken& SourceFile::at(size_t index) {
  while (index >= tokens_.size() && !ended_) readNext();
  if (index >= tokens_.size()) return tokens_.back();  // the End token
  return tokens_[index];
}

int SourceFile::get() {
  if (pos_ >= text_.size()) return EOF;
  int c = static_cast<unsigned char>(text_[pos_++]);
  if (c == '\n') {
    ++line_;
    col_ = 1;
  } else {
    ++col_;
  }
  return c;
}

int SourceFile::peek(size_t ahead) const {
  size_t p = pos_ + ahead;
  return p < text_.size() ? static_cast<unsigned char>(text_[p]) : EOF;
}

// After the opening "/*" at line:col. Comments nest, as in POV-Ray; an unclosed one is
// reported where the outermost began.
void SourceFile::blockComment(int line, int col) {
  for (long depth = 1; depth > 0;) {
    int c = get();
    if (c == EOF) throw LexError{line, col, "this '/*' comment has no closing '*/'"};
    if (c == '*' && peek() == '/') {
      get();
      --depth;
    } else if (c == '/' && peek() == '*') {
      get();
      ++depth;
    }
  }
}

void SourceFile::skipSpaceAndComments() {
  for (;;) {
    int c = peek();
    if (c == EOF) return;
    if (std::isspace(c) || c == '\0' || c == '\032') {
      get();
    } else if (c == '/' && peek(1) == '/') {
      while (peek() != EOF && peek() != '\n') get();
    } else if (c == '/' && peek(1) == '*') {
      int l = line_, k = col_;
      get();
      get();
      blockComment(l, k);
    } else {
      return;
    }
  }
}

void SourceFile::readNext() {
  skipSpaceAndComments();
  RawToken t;
  t.line = line_;
  t.col = col_;
  int c = peek();
  if (c == EOF) {
    ended_ = true;
  } else if (std::isdigit(c) || (c == '.' && std::isdigit(peek(1)))) {
    readNumber(t);
  } else if (isWordStart(c)) {
    readWord(t);
  } else if (c == '"') {
    get();
    readString(t);
  } else {
    readPunct(t, get());
  }
  tokens_.push_back(std::move(t));
}

void SourceFile::readNumber(RawToken& t) {
  // Phases as POV-Ray reads a number: integer part, fraction, exponent sign, exponent.
  std::string s;
  int phase = std::isdigit(peek()) ? 1 : 2;
  if (phase == 2) {
    s = "0";
    s += static_cast<char>(get());  // the '.'
  }
  for (;;) {
    int c = peek();
    if (phase > 1 && c == '.') throw LexError{line_, col_, "unexpected second '.' in a number"};
    bool take = false;
    if (phase <= 2 && std::isdigit(c)) {
      take = true;
    } else if (phase == 1 && c == '.') {
      take = true;
      phase = 2;
    } else if (phase <= 2 && (c == 'e' || c == 'E')) {
      take = true;
      phase = 3;
    } else if (phase == 3 && (std::isdigit(c) || c == '+' || c == '-')) {
      take = true;
      phase = 4;
    } else if (phase == 4 && std::isdigit(c)) {
      take = true;
    }
    if (!take) break;
    s += static_cast<char>(get());
  }
  t.kind = RawKind::Number;
  t.text = s;
  t.number = std::strtod(s.c_str(), nullptr);
}

void SourceFile::readWord(RawToken& t) {
  while (isWordChar(peek())) t.text += static_cast<char>(get());
  t.kind = RawKind::Word;
  t.keyword = keywordIndex(t.text);
}

void SourceFile::readString(RawToken& t) {
  t.kind = RawKind::String;
  for (;;) {
    int c = get();
    if (c == EOF) throw LexError{t.line, t.col, "this string has no closing quote"};
    if (c == '"') break;
    if (c == '\\') {
      int d = get();
      if (d == '\n' || d == '\r')
        throw LexError{t.line, t.col, "this string is not closed before the end of its line"};
      if (d == EOF) throw LexError{t.line, t.col, "this string has no closing quote"};
      if (d != '"') t.text += '\\';
      c = d;
    }
    t.text += static_cast<char>(c);
  }
  if (t.text.size() > kMaxLiteralLength)
    throw LexError{t.line, t.col,
                   "string literal of " + std::to_string(t.text.size()) +
                       " characters: POV-Ray 3.7 reads at most 255"};
}

void SourceFile::readPunct(RawToken& t, int c) {
  t.kind = RawKind::Punct;
  t.text = std::string(1, static_cast<char>(c));
  switch (c) {
    case '!':
    case '<':
    case '>':
      if (peek() == '=') t.text += static_cast<char>(get());
      return;
    case '{':
    case '}':
    case '@':
    case '&':
    case '`':
    case '\\':
    case '|':
    case ':':
    case ',':
    case '-':
    case '$':
    case '=':
    case '#':
    case '^':
    case '(':
    case '[':
    case '%':
    case '+':
    case '?':
    case ')':
    case ']':
    case ';':
    case '\'':
    case '/':
    case '*':
    case '~':
    case '.':
      return;
    default:
      throw LexError{t.line, t.col, "illegal character in input file, value is " + hex2(c)};
  }
}

}  // namespace lucent::sdl
