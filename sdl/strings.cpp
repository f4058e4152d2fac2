// Strings: literals with POV-Ray's escapes, and the string functions. str() formats with
// C's printf as POV-Ray does: str(x, L, P) is "%L.Pf" (L < 0: zero-padded to -L; P < 0:
// printf's default of 6 decimals), and %g when the text would not fit in 255 characters.
#include "token_stream.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>

namespace lucent::sdl {

namespace {

int toInt(double x) {
  if (!(x > -2147483649.0 && x < 2147483648.0)) return INT_MIN;
  return static_cast<int>(x);
}

// The printf format POV-Ray builds for str() and vstr().
std::string numberFormat(int length, int precision) {
  std::string f = "%";
  if (length > 0) f += std::to_string(length);
  else if (length < 0) f += "0" + std::to_string(-static_cast<long long>(length));
  if (precision >= 0) f += "." + std::to_string(precision);
  return f + "f";
}

std::string format(const std::string& f, double v) {
  int n = std::snprintf(nullptr, 0, f.c_str(), v);
  if (n < 0) return "<invalid>";
  std::string s(static_cast<size_t>(n) + 1, '\0');
  std::snprintf(s.data(), s.size(), f.c_str(), v);
  s.resize(static_cast<size_t>(n));
  return s;
}

void appendUtf8(std::string& s, unsigned c) {
  if (c < 0x80) {
    s += static_cast<char>(c);
  } else if (c < 0x800) {
    s += static_cast<char>(0xC0 | (c >> 6));
    s += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    s += static_cast<char>(0xE0 | (c >> 12));
    s += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    s += static_cast<char>(0x80 | (c & 0x3F));
  }
}

}  // namespace

void TokenStream::checkLength(size_t n) {
  if (n > options_.limits.stringLength)
    error(cur_, "a string of more than " + std::to_string(options_.limits.stringLength) +
                    " characters (the limit of one string; see docs/povray-import.md)");
}

// A string expression: a literal, a string identifier or a string function. False (and
// nothing read) when none starts here and `require` is false.
bool TokenStream::stringExpression(std::string& out, bool pathname, bool require) {
  Nesting nesting(*this);
  getToken();
  if (cur_.kind == TokenKind::String) {
    out = pathname ? std::string(cur_.text()) : decodeEscapes(std::string(cur_.text()), cur_);
    return true;
  }
  if (cur_.kind == TokenKind::Keyword && isStringFunction(cur_.kw)) {
    out = stringFunction(cur_.kw, pathname);
    checkLength(out.size());
    return true;
  }
  const Value* v = cur_.kind == TokenKind::Identifier ? cur_.value() : nullptr;
  if (v && v->type == ValueType::String) {
    out = *v->str;
    return true;
  }
  if (require) error(cur_, "expected a string expression, found " + cur_.describe());
  unget_ = true;
  return false;
}

std::string TokenStream::parseString() {
  std::string s;
  stringExpression(s, false, true);
  return s;
}

// The escapes POV-Ray reads in a string: \a \b \f \n \r \t \v \' \\ \uXXXX. Characters
// outside ASCII become spaces, as in POV-Ray's default (ASCII) string encoding.
std::string TokenStream::decodeEscapes(const std::string& raw, const Token& at) {
  std::string s;
  bool replaced = false;
  for (size_t i = 0; i < raw.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(raw[i]);
    if (c >= 0x80) {
      s += ' ';
      replaced = true;
      continue;
    }
    if (c != '\\') {
      s += static_cast<char>(c);
      continue;
    }
    if (++i >= raw.size()) {
      s += '\\';
      break;
    }
    switch (raw[i]) {
      case 'a':
        s += '\a';
        break;
      case 'b':
        s += '\b';
        break;
      case 'f':
        s += '\f';
        break;
      case 'n':
        s += '\n';
        break;
      case 'r':
        s += '\r';
        break;
      case 't':
        s += '\t';
        break;
      case 'v':
        s += '\v';
        break;
      case '\'':
        s += '\'';
        break;
      case '\\':
        s += '\\';
        break;
      case 'u': {
        if (i + 4 >= raw.size()) error(at, "unexpected end of escape sequence in text string");
        appendUtf8(s,
                   static_cast<unsigned>(std::strtoul(raw.substr(i + 1, 4).c_str(), nullptr, 16)));
        i += 4;
        break;
      }
      default:
        error(at, std::string("illegal escape sequence '\\") + raw[i] + "' in string");
    }
  }
  if (replaced) warning(at.loc(), "non-ASCII character has been replaced by space character");
  return s;
}

std::string TokenStream::stringFunction(Kw kw, bool pathname) {
  switch (kw) {
    case Kw::k_str:
      return strFunction();
    case Kw::k_vstr:
      return vstrFunction();
    case Kw::k_substr:
      return substrFunction();
    case Kw::k_datetime:
      return datetimeFunction();
    case Kw::k_chr: {
      const Token at = cur_;
      const int d = toInt(floatParam());
      if (d < 0 || d > 65535)
        error(at, "value " + std::to_string(d) + " cannot be used in chr(...)");
      std::string s;
      appendUtf8(s, static_cast<unsigned>(d));
      return s;
    }
    case Kw::k_concat: {
      expect("(");
      std::string s, more;
      stringExpression(s, false, true);
      for (;;) {
        getToken();
        if (cur_.is(")")) break;
        unget_ = true;
        parseComma();
        stringExpression(more, pathname, true);
        s += more;
        checkLength(s.size());
      }
      return s;
    }
    default: {  // strupr, strlwr
      expect("(");
      std::string s;
      stringExpression(s, pathname, true);
      expect(")");
      for (char& c : s)
        c = static_cast<char>(kw == Kw::k_strupr ? std::toupper(static_cast<unsigned char>(c))
                                                 : std::tolower(static_cast<unsigned char>(c)));
      return s;
    }
  }
}

std::string TokenStream::strFunction() {
  expect("(");
  const double v = parseFloat();
  parseComma();
  const int length = toInt(parseFloat());
  parseComma();
  const int precision = toInt(parseFloat());
  expect(")");
  // POV-Ray's buffer holds 254 characters: a longer %f text is written again as %g, and a
  // longer %g text is "<invalid>". A width or a precision above 300 makes %f that long
  // anyway, so it is not written out (a precision of 10^8 would take seconds); %g shows
  // no more than a double's 767 significant digits, so a higher precision changes nothing.
  constexpr int kSure = 300, kDoubleDigits = 800;
  const bool tooLong = std::abs(static_cast<long long>(length)) > kSure || precision > kSure;
  std::string f = numberFormat(length, precision);
  std::string s = tooLong ? std::string(255, ' ') : format(f, v);
  if (s.size() >= 255) {
    if (std::abs(static_cast<long long>(length)) > kSure) return "<invalid>";
    f = numberFormat(length, std::min(precision, kDoubleDigits));
    f.back() = 'g';
    s = format(f, v);
    if (s.size() >= 255) s = "<invalid>";
  }
  return s;
}

// vstr(n, V, separator, L, P): the first n (2 to 5) components of V, each as str() has it.
std::string TokenStream::vstrFunction() {
  const Token at = cur_;
  expect("(");
  int n = toInt(parseFloat());
  parseComma();
  n = n < 2 ? 2 : n > 5 ? 5 : n;
  Express e;
  unknownVector(e);
  parseComma();
  std::string sep;
  stringExpression(sep, false, true);
  parseComma();
  const int length = toInt(parseFloat());
  parseComma();
  const int precision = toInt(parseFloat());
  expect(")");
  // POV-Ray writes each component into a buffer of 768 characters, and overruns it with a
  // longer one: refused instead, before a width or precision of millions is written out.
  constexpr int kBuffer = 767;
  if (std::abs(static_cast<long long>(length)) > kBuffer || precision > kBuffer)
    error(at, "vstr(): a component's text would be longer than POV-Ray's " +
                  std::to_string(kBuffer) + " characters (width " + std::to_string(length) +
                  ", precision " + std::to_string(precision) + ")");
  const std::string f = numberFormat(length, precision);
  std::string s;
  for (int i = 0; i < n; ++i) {
    const std::string c = format(f, e.v[i]);
    if (c.size() > static_cast<size_t>(kBuffer))
      error(at, "vstr(): a component's text is longer than POV-Ray's " + std::to_string(kBuffer) +
                    " characters");
    s += (i == 0 ? "" : sep) + c;
  }
  return s;
}

std::string TokenStream::substrFunction() {
  expect("(");
  std::string s;
  stringExpression(s, false, true);
  parseComma();
  const Token at = cur_;
  const int start = toInt(parseFloat());
  parseComma();
  const int count = toInt(parseFloat());
  expect(")");
  const long long len = static_cast<long long>(s.size());
  if (static_cast<long long>(start) + count - 1 > len || start < 0 || count < 0 ||
      (start == 0 && count > 0))
    error(at, "illegal parameters in substr: start " + std::to_string(start) + ", length " +
                  std::to_string(count) + " of a string of " + std::to_string(len) + " characters");
  return count == 0 ? std::string() : s.substr(static_cast<size_t>(start - 1), count);
}

// datetime(days since 2000-01-01 [, strftime format]), in UTC.
std::string TokenStream::datetimeFunction() {
  expect("(");
  const double days = parseFloat();
  parseComma();
  std::string f = "%Y-%m-%d %H:%M:%SZ";
  getToken();
  if (!cur_.is(")")) {
    unget_ = true;
    stringExpression(f, false, true);
    if (f.empty()) error(cur_, "empty format string");
    if (f.size() > 200) error(cur_, "format string too long");
    expect(")");
  }
  const std::time_t t =
      static_cast<std::time_t>(std::floor((days + (365 * 30 + 7)) * 24 * 60 * 60 + 0.5));
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[201];
  const size_t n = std::strftime(buf, 200, f.c_str(), &tm);
  if (n == 0) error(cur_, "invalid formatting code in format string, or resulting string too long");
  return std::string(buf, n);
}

}  // namespace lucent::sdl
