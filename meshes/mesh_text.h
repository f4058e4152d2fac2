// Small text-scanning helpers for the mesh file checks: lines with numbers, whitespace
// tokens, and numbers spelled the way CGAL's readers accept them (no "nan", no "inf").
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace lucent::meshtext {

inline bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

// Lines of a text file, numbered from 1; the '\n' is not part of the line.
class Lines {
 public:
  explicit Lines(std::string_view text) : text_(text) {}
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++number_;
    return true;
  }
  std::size_t number() const { return number_; }  // of the line last returned
  std::size_t offset() const { return pos_ < text_.size() ? pos_ : text_.size(); }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t number_ = 0;
};

// Splits at whitespace into `out` (cleared first).
inline void tokens(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && isSpace(line[i])) ++i;
    std::size_t start = i;
    while (i < line.size() && !isSpace(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
}

// A decimal number made only of digits, '.', 'e', 'E', '+', '-' (what CGAL's double reader
// collects before sscanf), consumed entirely. Rejects nan/inf spellings and trailing junk.
inline bool parseReal(std::string_view tok, double& value) {
  if (tok.empty() || tok.size() > 64) return false;
  for (char c : tok) {
    bool ok = (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-';
    if (!ok) return false;
  }
  if (tok.front() == '+') tok.remove_prefix(1);
  if (tok.empty()) return false;
  auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), value);
  if (end != tok.data() + tok.size()) return false;
  if (ec == std::errc::result_out_of_range) {
    // Overflow (1e999) is not finite; underflow (1e-400) is a tiny number, as strtod and
    // CGAL's reader make it.
    const std::string text(tok);
    value = std::strtod(text.c_str(), nullptr);
    return std::isfinite(value);
  }
  return ec == std::errc();
}

// A decimal integer with an optional sign, consumed entirely, within [lo, hi].
inline bool parseInt(std::string_view tok, long long lo, long long hi, long long& value) {
  if (!tok.empty() && tok.front() == '+') tok.remove_prefix(1);
  if (tok.empty() || tok.size() > 19) return false;
  auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), value);
  return ec == std::errc() && end == tok.data() + tok.size() && value >= lo && value <= hi;
}

}  // namespace lucent::meshtext
