#include "transform_syntax.h"

#include "primitives/transform.h"
#include "primitives/value_limits.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace lucent {

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool isNameChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
         c == '_';
}

// Exact sine and cosine at multiples of 90 degrees, so rotate-y(90) maps +x to exactly -z.
void sinCosDegrees(double degrees, double& s, double& c) {
  double a = std::fmod(degrees, 360.0);
  if (a < 0.0) a += 360.0;
  if (a == 0.0) {
    s = 0.0;
    c = 1.0;
    return;
  }
  if (a == 90.0) {
    s = 1.0;
    c = 0.0;
    return;
  }
  if (a == 180.0) {
    s = 0.0;
    c = -1.0;
    return;
  }
  if (a == 270.0) {
    s = -1.0;
    c = 0.0;
    return;
  }
  s = std::sin(radians(degrees));
  c = std::cos(radians(degrees));
}

struct Scanner {
  std::string_view text;
  size_t pos = 0;
  TransformSyntaxResult result;

  bool fail(size_t at, std::string message) {
    result.ok = false;
    result.error = std::move(message);
    result.errorOffset = at;
    return false;
  }
  void skipSpace() {
    while (pos < text.size() && isSpace(text[pos])) ++pos;
  }

  // Reads the arguments up to ')' into `args`; pos ends after ')'.
  bool arguments(const std::string& op, size_t opStart, std::vector<double>& args) {
    bool needNumber = false;  // after a comma another number must follow
    while (true) {
      skipSpace();
      if (pos >= text.size()) return fail(opStart, "'" + op + "(' is missing its ')'");
      char ch = text[pos];
      if (ch == ')') {
        if (needNumber) return fail(pos, "'" + op + "': a number is missing after ','");
        ++pos;
        return true;
      }
      if (ch == ',') {
        if (needNumber || args.empty())
          return fail(pos, "'" + op + "': a number is missing before ','");
        needNumber = true;
        ++pos;
        continue;
      }
      size_t start = pos;
      while (pos < text.size() && !isSpace(text[pos]) && text[pos] != ',' && text[pos] != ')' &&
             text[pos] != '(')
        ++pos;
      std::string_view token = text.substr(start, pos - start);
      if (token.empty())
        return fail(start, "'" + op + "': unexpected '" + std::string(1, ch) + "'");
      // from_chars does not take a leading '+'; a decimal number may have one.
      std::string_view digits = token;
      if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-') digits.remove_prefix(1);
      double value = 0.0;
      auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
      if (ec != std::errc() || end != digits.data() + digits.size())
        return fail(start, "'" + op + "': expected a number, got '" + std::string(token) + "'");
      if (!std::isfinite(value))
        return fail(start,
                    "'" + op + "': expected a finite number, got '" + std::string(token) + "'");
      if (std::abs(value) > kMaxMagnitude)
        return fail(start, "'" + op + "': the number '" + std::string(token) +
                               "' is too large (the limit is 1e30 in magnitude)");
      if (value != 0.0 && std::abs(value) < kMinMagnitude)
        return fail(start,
                    "'" + op + "': the number '" + std::string(token) +
                        "' is too small (a nonzero number must be at least 1e-30 in magnitude)");
      args.push_back(value);
      needNumber = false;
    }
  }

  bool operation() {
    size_t opStart = pos;
    while (pos < text.size() && isNameChar(text[pos])) ++pos;
    std::string op(text.substr(opStart, pos - opStart));
    if (op.empty())
      return fail(opStart, "expected an operation such as translate(x y z), got '" +
                               std::string(1, text[pos]) + "'");
    const auto& names = transformOperationNames();
    if (std::find(names.begin(), names.end(), op) == names.end()) {
      result.unknownOperation = op;
      return fail(opStart, "unknown operation '" + op + "'");
    }
    skipSpace();
    if (pos >= text.size() || text[pos] != '(')
      return fail(pos, "'" + op + "' must be followed by '(' and its arguments");
    ++pos;
    std::vector<double> a;
    if (!arguments(op, opStart, a)) return false;

    auto arity = [&](const char* expected) {
      return fail(opStart,
                  "'" + op + "' expects " + expected + ", got " + std::to_string(a.size()));
    };
    Mat4 m(1.0);
    if (op == "translate") {
      if (a.size() != 3) return arity("3 numbers (x y z)");
      m = translationMatrix(Vec3(a[0], a[1], a[2]));
    } else if (op == "scale") {
      if (a.size() == 1) m = scaleMatrix(Vec3(a[0]));
      else if (a.size() == 3) m = scaleMatrix(Vec3(a[0], a[1], a[2]));
      else return arity("1 or 3 numbers");
    } else if (op == "rotate") {
      if (a.size() != 4) return arity("4 numbers (angle, x y z)");
      Vec3 axis(a[1], a[2], a[3]);
      double len = glm::length(axis);
      if (!(len > 0.0) || !std::isfinite(len))
        return fail(opStart, "'rotate': the rotation axis must not be zero");
      m = rotationMatrix(a[0], axis / len);
    } else if (op == "rotate-x" || op == "rotate-y" || op == "rotate-z") {
      if (a.size() != 1) return arity("1 number (the angle in degrees)");
      Vec3 axis(0.0);
      axis[op.back() - 'x'] = 1.0;
      m = rotationMatrix(a[0], axis);
    } else {  // matrix
      if (a.size() != 12 && a.size() != 16)
        return arity("12 numbers (3 rows of 4) or 16 (4 rows of 4)");
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) m[c][r] = a[r * 4 + c];  // row-major text, glm column-major
      if (a.size() == 16 && (a[12] != 0.0 || a[13] != 0.0 || a[14] != 0.0 || a[15] != 1.0))
        return fail(opStart,
                    "'matrix': the last row must be 0 0 0 1 (only affine transforms are allowed)");
    }
    // The first operation written is applied first: each new one multiplies from the left.
    result.matrix = m * result.matrix;
    return true;
  }

  void run() {
    skipSpace();
    while (pos < text.size()) {
      if (!operation()) return;
      skipSpace();
      if (pos < text.size() && text[pos] == ',') {
        ++pos;
        skipSpace();
        if (pos >= text.size()) {
          fail(pos - 1, "expected an operation after ','");
          return;
        }
      }
    }
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (!std::isfinite(result.matrix[c][r])) {
          fail(0,
               "the transform overflows (its operations multiply to numbers beyond double range)");
          return;
        }
    if (!Transform::fromMatrix(result.matrix))
      fail(0,
           "the transform is singular (it flattens space, e.g. a zero scale) and cannot be "
           "inverted");
  }
};

}  // namespace

const std::vector<std::string>& transformOperationNames() {
  static const std::vector<std::string> names{"translate", "scale",    "rotate", "rotate-x",
                                              "rotate-y",  "rotate-z", "matrix"};
  return names;
}

Mat4 translationMatrix(const Vec3& t) {
  Mat4 m(1.0);
  m[3] = Vec4(t, 1.0);
  return m;
}

Mat4 scaleMatrix(const Vec3& s) {
  Mat4 m(1.0);
  m[0][0] = s.x;
  m[1][1] = s.y;
  m[2][2] = s.z;
  return m;
}

Mat4 rotationMatrix(double degrees, const Vec3& k) {
  // Rodrigues: R = c·I + s·[k]x + (1 − c)·k kᵀ, written as R(row, col) into m[col][row].
  double s, c;
  sinCosDegrees(degrees, s, c);
  double t = 1.0 - c;
  double r[3][3] = {
      {c + t * k.x * k.x, t * k.x * k.y - s * k.z, t * k.x * k.z + s * k.y},
      {t * k.y * k.x + s * k.z, c + t * k.y * k.y, t * k.y * k.z - s * k.x},
      {t * k.z * k.x - s * k.y, t * k.z * k.y + s * k.x, c + t * k.z * k.z},
  };
  Mat4 m(1.0);
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) m[col][row] = r[row][col];
  return m;
}

TransformSyntaxResult parseTransformSyntax(std::string_view text) {
  Scanner s{text, 0, {}};
  s.run();
  if (!s.result.ok) s.result.matrix = Mat4(1.0);
  return s.result;
}

}  // namespace lucent
