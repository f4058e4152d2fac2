// The built-in float and vector functions, with POV-Ray 3.7's semantics: int() and div()
// truncate towards zero, mod() is C's fmod, degrees and radians use POV-Ray's constant,
// vrotate rotates about x, then y, then z, with POV-Ray's matrices (so that results match
// to the last bit).
#include "token_stream.h"

#include "random.h"

#include "scenegraph/turbulence.h"

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>

namespace lucent::sdl {

namespace {

constexpr double kEpsilon = 1e-10;
constexpr double kPi = 3.1415926535897932384626;
constexpr double kRadiansPerDegree = 0.01745329251994329576;  // POV-Ray's M_PI_180

// C's (int) conversion as the x86 processors POV-Ray runs on do it: a value out of int's
// range (or NaN) becomes INT_MIN, where C++ leaves it undefined.
int toInt(double x) {
  if (!(x > -2147483649.0 && x < 2147483648.0)) return INT_MIN;
  return static_cast<int>(x);
}

std::string printfFloat(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

using Matrix = std::array<std::array<double, 4>, 4>;

Matrix identity() {
  Matrix m{};
  for (int i = 0; i < 4; ++i) m[i][i] = 1;
  return m;
}

// result = result x b, every term summed in POV-Ray's order.
void timesA(Matrix& r, const Matrix& b) {
  for (int i = 0; i < 4; ++i) {
    const double t0 = r[i][0], t1 = r[i][1], t2 = r[i][2], t3 = r[i][3];
    for (int j = 0; j < 4; ++j) r[i][j] = t0 * b[0][j] + t1 * b[1][j] + t2 * b[2][j] + t3 * b[3][j];
  }
}

std::array<double, 3> transformPoint(const Matrix& m, const std::array<double, 3>& v) {
  std::array<double, 3> r;
  for (int i = 0; i < 3; ++i) r[i] = v[0] * m[0][i] + v[1] * m[1][i] + v[2] * m[2][i] + m[3][i];
  return r;
}

std::array<double, 3> rotate(const std::array<double, 3>& v, const std::array<double, 3>& deg) {
  const double rx = deg[0] * kRadiansPerDegree, ry = deg[1] * kRadiansPerDegree,
               rz = deg[2] * kRadiansPerDegree;
  Matrix m = identity();
  m[1][1] = std::cos(rx);
  m[2][2] = std::cos(rx);
  m[1][2] = std::sin(rx);
  m[2][1] = 0.0 - std::sin(rx);
  Matrix y = identity();
  y[0][0] = std::cos(ry);
  y[2][2] = std::cos(ry);
  y[0][2] = 0.0 - std::sin(ry);
  y[2][0] = std::sin(ry);
  timesA(m, y);
  Matrix z = identity();
  z[0][0] = std::cos(rz);
  z[1][1] = std::cos(rz);
  z[0][1] = std::sin(rz);
  z[1][0] = 0.0 - std::sin(rz);
  timesA(m, z);
  return transformPoint(m, v);
}

std::array<double, 3> normalize(const std::array<double, 3>& v) {
  const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  const double inv = 1.0 / len;
  return {v[0] * inv, v[1] * inv, v[2] * inv};
}

std::array<double, 3> axisRotate(const std::array<double, 3>& p, const std::array<double, 3>& axis,
                                 double angle) {
  const auto a = normalize(axis);
  const double c = std::cos(angle), s = std::sin(angle);
  Matrix m = identity();
  m[0][0] = a[0] * a[0] + c * (1.0 - a[0] * a[0]);
  m[0][1] = a[0] * a[1] * (1.0 - c) + a[2] * s;
  m[0][2] = a[0] * a[2] * (1.0 - c) - a[1] * s;
  m[1][0] = a[0] * a[1] * (1.0 - c) - a[2] * s;
  m[1][1] = a[1] * a[1] + c * (1.0 - a[1] * a[1]);
  m[1][2] = a[1] * a[2] * (1.0 - c) + a[0] * s;
  m[2][0] = a[0] * a[2] * (1.0 - c) + a[1] * s;
  m[2][1] = a[1] * a[2] * (1.0 - c) - a[0] * s;
  m[2][2] = a[2] * a[2] + c * (1.0 - a[2] * a[2]);
  return transformPoint(m, p);
}

}  // namespace

void TokenStream::notEvaluated(const Token& t) const {
  error(t, "'" + std::string(t.text()) +
               "' is not evaluated yet by Lucent's POV-Ray reader (it needs the scene's "
               "objects, functions or noise)");
}

double TokenStream::floatFunction(Kw kw) {
  const Token at = cur_;
  switch (kw) {
    case Kw::k_abs:
      return std::fabs(floatParam());
    case Kw::k_acos:
    case Kw::k_asin: {
      double x = floatParam();
      if (x > 1.0 || x < -1.0) {
        warning(at.loc(), std::string("domain error in ") + std::string(at.text()));
        x = x > 1.0 ? 1.0 : -1.0;
      }
      return kw == Kw::k_acos ? std::acos(x) : std::asin(x);
    }
    case Kw::k_atan:
      return std::atan(floatParam());
    case Kw::k_atan2: {
      double a, b;
      floatParam2(a, b);
      if (std::fabs(a) > kEpsilon || std::fabs(b) > kEpsilon) return std::atan2(a, b);
      error(at, "domain error in atan2: both arguments are 0");
    }
    case Kw::k_cosh:
      return std::cosh(floatParam());
    case Kw::k_sinh:
      return std::sinh(floatParam());
    case Kw::k_tanh:
      return std::tanh(floatParam());
    case Kw::k_acosh:
      return std::acosh(floatParam());
    case Kw::k_asinh:
      return std::asinh(floatParam());
    case Kw::k_atanh:
      return std::atanh(floatParam());
    case Kw::k_ceil:
      return std::ceil(floatParam());
    case Kw::k_cos:
      return std::cos(floatParam());
    case Kw::k_sin:
      return std::sin(floatParam());
    case Kw::k_tan:
      return std::tan(floatParam());
    case Kw::k_exp:
      return std::exp(floatParam());
    case Kw::k_floor:
      return std::floor(floatParam());
    case Kw::k_degrees:
      return floatParam() / kRadiansPerDegree;
    case Kw::k_radians:
      return floatParam() * kRadiansPerDegree;
    case Kw::k_int:
      return toInt(floatParam());
    case Kw::k_div: {
      double a, b;
      floatParam2(a, b);
      return toInt(a / b);
    }
    case Kw::k_mod: {
      double a, b;
      floatParam2(a, b);
      return std::fmod(a, b);
    }
    case Kw::k_pow: {
      double a, b;
      floatParam2(a, b);
      if (a == 0.0 && b == 0.0) error(at, "domain error: pow(0, 0)");
      return std::pow(a, b);
    }
    case Kw::k_ln:
    case Kw::k_log: {
      double x = floatParam();
      if (x <= 0.0)
        error(at, std::string(at.text()) + " of negative number " + printfFloat("%f", x));
      return kw == Kw::k_ln ? std::log(x) : std::log10(x);
    }
    case Kw::k_sqrt: {
      double x = floatParam();
      if (x < 0.0) error(at, "sqrt of negative number " + printfFloat("%f", x));
      return std::sqrt(x);
    }
    case Kw::k_max:
    case Kw::k_min:
      return minMaxFunction(kw);
    case Kw::k_bitwise_and:
    case Kw::k_bitwise_or:
    case Kw::k_bitwise_xor:
      return bitwiseFunction(kw);
    case Kw::k_select:
      return selectFunction();
    case Kw::k_vdot: {
      std::array<double, 3> a, b;
      vectorParam2(a, b);
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }
    case Kw::k_vlength: {
      auto v = vectorParam();
      return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }
    case Kw::k_dimensions:
    case Kw::k_dimension_size:
      return arrayFunction(kw);
    case Kw::k_seed:
    case Kw::k_rand:
      return randomFunction(kw);
    default:
      return floatValue(kw);
  }
}

// The float keywords that are values, and the functions of strings and files.
double TokenStream::floatValue(Kw kw) {
  const Token at = cur_;
  switch (kw) {
    case Kw::k_pi:
      return kPi;
    case Kw::k_true:
    case Kw::k_yes:
    case Kw::k_on:
      return 1.0;
    case Kw::k_false:
    case Kw::k_no:
    case Kw::k_off:
      return 0.0;
    case Kw::k_clock:
      return options_.clock;
    case Kw::k_clock_on:
      return options_.clockOn ? 1.0 : 0.0;
    case Kw::k_version:
      return version_ / 100.0;
    case Kw::k_defined:
      return ifdefParam() ? 1.0 : 0.0;
    case Kw::k_now: {
      using namespace std::chrono;
      const double s = duration<double>(system_clock::now().time_since_epoch()).count();
      return (s - 946684800.0) / 86400.0;  // days since 2000-01-01 UTC
    }
    case Kw::k_val:
    case Kw::k_asc:
    case Kw::k_strlen:
    case Kw::k_file_exists: {
      expect("(");
      std::string s;
      stringExpression(s, false, true);
      expect(")");
      if (kw == Kw::k_val) return std::atof(s.c_str());
      if (kw == Kw::k_asc) return s.empty() ? 0.0 : static_cast<unsigned char>(s[0]);
      if (kw == Kw::k_strlen) return static_cast<double>(s.size());
      std::string display;
      try {
        findInclude(s, at.loc(), display);
        return 1.0;
      } catch (const SdlError&) {
        return 0.0;
      }
    }
    case Kw::k_strcmp: {
      expect("(");
      std::string a, b;
      stringExpression(a, false, true);
      parseComma();
      stringExpression(b, false, true);
      expect(")");
      // POV-Ray returns the difference of the first characters that differ.
      size_t i = 0;
      while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
      const int ca = i < a.size() ? static_cast<unsigned char>(a[i]) : 0;
      const int cb = i < b.size() ? static_cast<unsigned char>(b[i]) : 0;
      return ca - cb;
    }
    case Kw::k_inside:
      return insideFunction();
    default:
      notEvaluated(at);  // sum() and prod() (of functions only)
  }
}

double TokenStream::minMaxFunction(Kw kw) {
  expect("(");
  double v = parseFloat();
  while (allow(",")) {
    double w = parseFloat();
    v = kw == Kw::k_max ? std::max(v, w) : std::min(v, w);
  }
  expect(")");
  return v;
}

double TokenStream::bitwiseFunction(Kw kw) {
  expect("(");
  int v = toInt(parseFloat());
  while (allow(",")) {
    int w = toInt(parseFloat());
    v = kw == Kw::k_bitwise_and ? (v & w) : kw == Kw::k_bitwise_or ? (v | w) : (v ^ w);
  }
  expect(")");
  return v;
}

// select(a, neg, zero_or_pos) or select(a, neg, zero, pos).
double TokenStream::selectFunction() {
  expect("(");
  double v = parseFloat();
  parseComma();
  double less = parseFloat();
  parseComma();
  double equal = parseFloat();
  if (allow(",")) {
    double greater = parseFloat();
    expect(")");
    return v < 0.0 ? less : v == 0.0 ? equal : greater;
  }
  expect(")");
  return v < 0.0 ? less : equal;
}

double TokenStream::arrayFunction(Kw kw) {
  expect("(");
  getToken();
  const Value* v = cur_.kind == TokenKind::Identifier ? cur_.value() : nullptr;
  if (!v || v->type != ValueType::Array)
    error(cur_, "expected an array identifier, found " + cur_.describe());
  std::shared_ptr<ArrayValue> a = v->array;
  double r = static_cast<double>(a->sizes.size());
  if (kw == Kw::k_dimension_size) {
    parseComma();
    const int i = toInt(parseFloat()) - 1;
    r = (i < 0 || i >= static_cast<int>(a->sizes.size())) ? 0.0 : a->sizes[i];
  }
  expect(")");
  return r;
}

// seed(n) makes a new stream and returns its number; rand(stream) its next number.
double TokenStream::randomFunction(Kw kw) {
  const Token at = cur_;
  const int n = toInt(floatParam());
  if (kw == Kw::k_seed) {
    random_.push_back(static_cast<std::uint32_t>(n));
    return static_cast<double>(random_.size() - 1);
  }
  if (n < 0 || n >= static_cast<int>(random_.size()))
    error(at, "illegal random number generator: " + std::to_string(n) +
                  " is not a stream made by seed()");
  return povRand(random_[n]);
}

std::array<double, 3> TokenStream::vectorFunction(Kw kw) {
  const Token at = cur_;
  switch (kw) {
    case Kw::k_x:
      return {1, 0, 0};
    case Kw::k_y:
      return {0, 1, 0};
    case Kw::k_z:
      return {0, 0, 1};
    case Kw::k_vcross: {
      std::array<double, 3> b, c;
      vectorParam2(b, c);
      return {b[1] * c[2] - b[2] * c[1], b[2] * c[0] - b[0] * c[2], b[0] * c[1] - b[1] * c[0]};
    }
    case Kw::k_vnormalize: {
      auto v = vectorParam();
      if (v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0) {
        if (version_ >= 350) warning(at.loc(), "normalizing zero-length vector");
        return {0, 0, 0};
      }
      return normalize(v);
    }
    case Kw::k_vrotate: {
      std::array<double, 3> v, r;
      vectorParam2(v, r);
      return rotate(v, r);
    }
    case Kw::k_vaxis_rotate: {
      expect("(");
      auto p = parseVector();
      parseComma();
      auto axis = parseVector();
      parseComma();
      double angle = parseFloat() * kRadiansPerDegree;
      expect(")");
      return axisRotate(p, axis, angle);
    }
    case Kw::k_trace:
      return traceFunction();
    case Kw::k_min_extent:
    case Kw::k_max_extent:
      return extentFunction(kw);
    case Kw::k_vturbulence:
      return vturbulenceFunction();
    default:
      notEvaluated(at);
  }
}

// vturbulence(Lambda, Omega, Octaves, P): POV-Ray's DTurbulence at P, the octaves truncated
// to a whole number and kept in 1..10 as POV-Ray keeps them (dturbulence does both).
std::array<double, 3> TokenStream::vturbulenceFunction() {
  expect("(");
  PatternPlacement turbulence;
  turbulence.lambda = parseFloat();
  parseComma();
  turbulence.omega = parseFloat();
  parseComma();
  const double octaves = parseFloat();
  turbulence.octaves = octaves >= 10.0 ? 10 : octaves >= 1.0 ? static_cast<int>(octaves) : 1;
  parseComma();
  const std::array<double, 3> p = parseVector();
  parseComma();
  expect(")");
  const Vec3 d = dturbulence(Vec3(p[0], p[1], p[2]), turbulence);
  return {d.x, d.y, d.z};
}

}  // namespace lucent::sdl
