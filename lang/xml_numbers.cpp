#include "xml_numbers.h"

#include <charconv>
#include <cmath>

namespace lucent {

namespace {

template <class T>
std::string shortest(T v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, end);
}

}  // namespace

std::string xmlNumber(double v) { return shortest(v); }

std::string xmlVector(const Vec3& v) {
  return xmlNumber(v.x) + " " + xmlNumber(v.y) + " " + xmlNumber(v.z);
}

std::string xmlColor(const Color& c) {
  return shortest(c.r) + " " + shortest(c.g) + " " + shortest(c.b);
}

std::string xmlMatrix(const Mat4& m) {
  if (m == Mat4(1.0)) return "";
  std::string text = "matrix(";
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) text += (r + c == 0 ? "" : " ") + xmlNumber(m[c][r]);
  return text + ")";
}

std::string xmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      // A reader turns these into spaces in an attribute unless written as references.
      case '\t':
        out += "&#9;";
        break;
      case '\n':
        out += "&#10;";
        break;
      case '\r':
        out += "&#13;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace lucent
