// POV-Ray's lexical rules (POV-Ray 3.7's tokenizer, read for the facts): block comments
// nest; a number is digits with at most one '.', then optionally e/E, a sign and digits,
// and a '.' not followed by a digit is the period of `V.x`; a string literal ends at the
// first unescaped quote and may not hold a line break after a backslash.
//
// The lexer scans the text in place: a token's text is a view into it, and characters are
// classed by a table (the C locale's classes, which POV-Ray's tokenizer uses).
#include "source.h"

#include "keywords.h"

#include <array>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>

namespace lucent::sdl {

namespace {

// POV-Ray 3.7 keeps a string literal in a buffer of 256 characters and refuses a longer one.
constexpr size_t kMaxLiteralLength = 255;

enum CharClass : unsigned char { kSpace = 1, kDigit = 2, kWordStart = 4, kWordChar = 8 };

constexpr std::array<unsigned char, 256> makeClasses() {
  std::array<unsigned char, 256> c{};
  for (int ch : {' ', '\t', '\n', '\v', '\f', '\r', '\0', '\032'}) c[ch] = kSpace;
  for (int ch = '0'; ch <= '9'; ++ch) c[ch] = kDigit | kWordChar;
  for (int ch = 'a'; ch <= 'z'; ++ch) c[ch] = kWordStart | kWordChar;
  for (int ch = 'A'; ch <= 'Z'; ++ch) c[ch] = kWordStart | kWordChar;
  c['_'] = kWordStart | kWordChar;
  return c;
}

constexpr std::array<unsigned char, 256> kClasses = makeClasses();

bool is(int c, CharClass k) { return c >= 0 && (kClasses[static_cast<unsigned char>(c)] & k); }

std::string hex2(int c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%02x", c & 0xff);
  return buf;
}

// POV-Ray's text stream (its ITextStream) reads CR LF, LF CR and a lone CR each as one
// line end: a file saved with old Mac line ends has its `//` comments end at each CR.
std::string withPovLineEnds(std::string text) {
  if (text.find('\r') == std::string::npos) return text;
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c != '\n' && c != '\r') {
      out += c;
      continue;
    }
    out += '\n';
    if (i + 1 < text.size() && text[i + 1] == (c == '\n' ? '\r' : '\n')) ++i;
  }
  return out;
}

}  // namespace

SourceFile::SourceFile(std::string name, std::filesystem::path folder, std::string text)
    : name_(std::move(name)), folder_(std::move(folder)), text_(withPovLineEnds(std::move(text))) {}

const RawToken& SourceFile::readUpTo(size_t index) {
  while (index >= count_ && !ended_) readNext();
  if (index >= count_) return at(count_ - 1);  // the End token
  return at(index);
}

RawToken& SourceFile::push() {
  static_assert(std::is_trivially_destructible_v<RawToken>, "chunks never destroy tokens");
  if ((count_ & (kChunk - 1)) == 0)
    chunks_.emplace_back(static_cast<RawToken*>(::operator new(sizeof(RawToken) * kChunk)));
  RawToken* t = new (chunks_.back().get() + (count_ & (kChunk - 1))) RawToken;
  ++count_;
  return *t;
}

void SourceFile::newLines(size_t from, size_t to) {
  for (const char* p = text_.data() + from;
       (p = static_cast<const char*>(std::memchr(p, '\n', text_.data() + to - p))) != nullptr;) {
    ++line_;
    lineStart_ = static_cast<size_t>(++p - text_.data());
  }
}

// After the opening "/*" at line:col. Comments nest, as in POV-Ray; an unclosed one is
// reported where the outermost began.
void SourceFile::blockComment(int line, int col) {
  const size_t size = text_.size();
  size_t p = pos_;
  for (long depth = 1; depth > 0;) {
    while (p < size && text_[p] != '*' && text_[p] != '/') ++p;
    if (p >= size) throw LexError{line, col, "this '/*' comment has no closing '*/'"};
    const char c = text_[p++];
    if (c == '*' && p < size && text_[p] == '/') {
      ++p;
      --depth;
    } else if (c == '/' && p < size && text_[p] == '*') {
      ++p;
      ++depth;
    }
  }
  newLines(pos_, p);
  pos_ = p;
}

void SourceFile::skipSpaceAndComments() {
  const size_t size = text_.size();
  while (pos_ < size) {
    const char c = text_[pos_];
    if (is(c, kSpace)) {
      if (c == '\n') {
        ++line_;
        lineStart_ = pos_ + 1;
      }
      ++pos_;
    } else if (c == '/' && pos_ + 1 < size && text_[pos_ + 1] == '/') {
      const void* end = std::memchr(text_.data() + pos_, '\n', size - pos_);
      pos_ = end ? static_cast<size_t>(static_cast<const char*>(end) - text_.data()) : size;
    } else if (c == '/' && pos_ + 1 < size && text_[pos_ + 1] == '*') {
      const int l = line_, k = col();
      pos_ += 2;
      blockComment(l, k);
    } else {
      return;
    }
  }
}

void SourceFile::readNext() {
  skipSpaceAndComments();
  RawToken& t = push();
  t.line = line_;
  t.col = col();
  const size_t size = text_.size();
  if (pos_ >= size) {
    t.kind = RawKind::End;
    ended_ = true;
    return;
  }
  const char c = text_[pos_];
  if (is(c, kDigit) || (c == '.' && pos_ + 1 < size && is(text_[pos_ + 1], kDigit))) {
    readNumber(t);
  } else if (is(c, kWordStart)) {
    readWord(t);
  } else if (c == '"') {
    ++pos_;
    readString(t);
  } else {
    readPunct(t);
  }
}

void SourceFile::readNumber(RawToken& t) {
  // Phases as POV-Ray reads a number: integer part, fraction, exponent sign, exponent.
  const size_t size = text_.size(), start = pos_;
  int phase = 1;
  if (text_[pos_] == '.') {
    phase = 2;
    ++pos_;
  }
  for (; pos_ < size; ++pos_) {
    const char c = text_[pos_];
    if (phase > 1 && c == '.') throw LexError{line_, col(), "unexpected second '.' in a number"};
    if (phase <= 2 && is(c, kDigit)) continue;
    if (phase == 1 && c == '.') {
      phase = 2;
    } else if (phase <= 2 && (c == 'e' || c == 'E')) {
      phase = 3;
    } else if (phase == 3 && (is(c, kDigit) || c == '+' || c == '-')) {
      phase = 4;
    } else if (!(phase == 4 && is(c, kDigit))) {
      break;
    }
  }
  t.kind = RawKind::Number;
  t.text = std::string_view(text_).substr(start, pos_ - start);
  const char* first = t.text.data();
  const std::from_chars_result r = std::from_chars(first, first + t.text.size(), t.number);
  // Beyond a double's range from_chars gives no value; strtod gives POV-Ray's (inf, 0).
  if (r.ec != std::errc()) t.number = std::strtod(std::string(t.text).c_str(), nullptr);
}

void SourceFile::readWord(RawToken& t) {
  const size_t size = text_.size(), start = pos_;
  while (pos_ < size && is(text_[pos_], kWordChar)) ++pos_;
  t.kind = RawKind::Word;
  t.text = std::string_view(text_).substr(start, pos_ - start);
  t.keyword = keywordIndex(t.text);
}

void SourceFile::readString(RawToken& t) {
  t.kind = RawKind::String;
  const size_t size = text_.size(), start = pos_;
  bool escapedQuote = false;
  for (;;) {
    if (pos_ >= size) throw LexError{t.line, t.col, "this string has no closing quote"};
    const char c = text_[pos_++];
    if (c == '"') break;
    if (c == '\n') {
      ++line_;
      lineStart_ = pos_;
    } else if (c == '\\') {
      if (pos_ >= size) throw LexError{t.line, t.col, "this string has no closing quote"};
      const char d = text_[pos_++];
      if (d == '\n' || d == '\r')
        throw LexError{t.line, t.col, "this string is not closed before the end of its line"};
      escapedQuote = escapedQuote || d == '"';
    }
  }
  t.text = std::string_view(text_).substr(start, pos_ - 1 - start);
  if (escapedQuote) {  // `\"` is read as `"`: the text is a copy without those backslashes
    std::string s;
    for (size_t i = 0; i < t.text.size(); ++i) {
      if (t.text[i] == '\\' && t.text[i + 1] == '"') ++i;
      else if (t.text[i] == '\\') s += t.text[i++];
      s += t.text[i];
    }
    unescaped_.push_back(std::move(s));
    t.text = unescaped_.back();
  }
  if (t.text.size() > kMaxLiteralLength)
    throw LexError{t.line, t.col,
                   "string literal of " + std::to_string(t.text.size()) +
                       " characters: POV-Ray 3.7 reads at most 255"};
}

void SourceFile::readPunct(RawToken& t) {
  t.kind = RawKind::Punct;
  const size_t start = pos_;
  const char c = text_[pos_++];
  switch (c) {
    case '!':
    case '<':
    case '>':
      if (pos_ < text_.size() && text_[pos_] == '=') ++pos_;
      break;
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
      break;
    default:
      throw LexError{t.line, t.col, "illegal character in input file, value is " + hex2(c)};
  }
  t.text = std::string_view(text_).substr(start, pos_ - start);
}

}  // namespace lucent::sdl
