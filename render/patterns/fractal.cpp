#include "fractal.h"

#include <array>
#include <cmath>

namespace lucent {

namespace {

constexpr int kMaxPower = 33;  // POV-Ray's FRACTAL_MAX_EXPONENT

// The binomial coefficients C(n, k) times the sign of the real or imaginary part of i^k
// (negative where k & 2), so that (a + bi)^n = Σ_even c_k a^(n−k) b^k + i Σ_odd c_k ....
// C(33, 16) fits an int, as in POV-Ray; kept as doubles (exact).
struct Binomials {
  std::array<std::array<double, kMaxPower + 1>, kMaxPower + 1> row{};
  Binomials() {
    row[0][0] = 1.0;
    for (int n = 1; n <= kMaxPower; ++n) {
      row[n][0] = row[n][n] = 1.0;
      for (int k = 1; k < n; ++k) row[n][k] = row[n - 1][k - 1] + row[n - 1][k];
    }
    for (int n = 1; n <= kMaxPower; ++n)
      for (int k = 1; k <= n; ++k)
        if ((k & 2) != 0) row[n][k] = -row[n][k];
  }
};

const Binomials& binomials() {
  static const Binomials b;
  return b;
}

double exteriorValue(const FractalParams& f, int iters, double a, double b) {
  const double k = f.exterior.factor;
  switch (f.exterior.type) {
    case 0:
      return k;
    case 1:
      return static_cast<double>(iters) / static_cast<double>(f.iterations);
    case 2:
      return a * k;
    case 3:
      return b * k;
    case 4:
      return a * a * k;
    case 5:
      return b * b * k;
    case 6:
      return std::sqrt(a * a + b * b) * k;
    case 7:  // 0 .. (n−1)/n; the parsers keep the factor >= 1
      return static_cast<double>(static_cast<unsigned>(iters) % static_cast<unsigned>(k)) / k;
    case 8:  // 0 .. 1; the parsers keep the factor > 0
      return static_cast<double>(static_cast<unsigned>(iters) % static_cast<unsigned>(1.0 + k)) / k;
  }
  return 0.0;
}

double interiorValue(const FractalParams& f, double a, double b, double minDist2) {
  const double k = f.interior.factor;
  switch (f.interior.type) {
    case 0:
      return k;
    case 1:
      return std::sqrt(minDist2) * k;
    case 2:
      return a * k;
    case 3:
      return b * k;
    case 4:
      return a * a * k;
    case 5:
      return b * b * k;
    case 6:
      return a * a + b * b * k;  // POV-Ray's precedence: only b² is scaled
  }
  return 0.0;
}

// z ← z^power + c, starting from z = p; mandel has c = p, julia the constant.
double powerSet(const FractalParams& f, double a, double b, double cr, double ci) {
  const int n = f.power;
  double a2 = a * a, b2 = b * b;
  double minDist2 = a2 + b2;
  const auto& coeff = binomials().row[n];
  for (int i = 0; i < f.iterations; ++i) {
    if (n == 2) {
      b = 2.0 * a * b + ci;
      a = a2 - b2 + cr;
    } else if (n == 3) {
      b = 3.0 * a2 * b - b2 * b + ci;
      a = a2 * a - 3.0 * a * b2 + cr;
    } else if (n == 4) {
      b = 4.0 * (a2 * a * b - a * b2 * b) + ci;
      a = a2 * a2 - 6.0 * a2 * b2 + b2 * b2 + cr;
    } else {
      double re = std::pow(a, n);
      for (int k = 2; k <= n; k += 2) re += coeff[k] * std::pow(a, n - k) * std::pow(b, k);
      double im = 0.0;
      for (int k = 1; k <= n; k += 2) im += coeff[k] * std::pow(a, n - k) * std::pow(b, k);
      a = re + cr;
      b = im + ci;
    }
    a2 = a * a;
    b2 = b * b;
    const double dist2 = a2 + b2;
    if (dist2 < minDist2) minDist2 = dist2;
    if (dist2 > 4.0) return exteriorValue(f, i, a, b);
  }
  return interiorValue(f, a, b, minDist2);
}

// The magnet maps: z ← ((z² + c − 1) / (2z + c − 2))² (type 1) or its cubic form (type 2);
// the Mandelbrot form starts from z = 0 with c = p.
double magnet(const FractalParams& f, const Vec3& p) {
  double a, b, cr, ci, minDist2;
  if (f.juliaForm) {
    a = p.x;
    b = p.y;
    cr = f.cReal;
    ci = f.cImaginary;
    minDist2 = a * a + b * b;
  } else {
    a = b = 0.0;
    cr = p.x;
    ci = p.y;
    minDist2 = 10000.0;
  }
  double a2 = a * a, b2 = b * b;
  const double c1r = cr - 1, c2r = cr - 2;
  const double c1c2r = c1r * c2r - ci * ci;
  const double c1c2i = (c1r + c2r) * ci;
  for (int i = 0; i < f.iterations; ++i) {
    double t1r, t1i, t2r, t2i;
    if (f.magnetType == 1) {
      t1r = a2 - b2 + cr - 1;
      t1i = 2 * a * b + ci;
      t2r = 2 * a + cr - 2;
      t2i = 2 * b + ci;
    } else {
      t1r = a2 * a - 3 * a * b2 + 3 * (a * c1r - b * ci) + c1c2r;
      t1i = 3 * a2 * b - b2 * b + 3 * (a * ci + b * c1r) + c1c2i;
      t2r = 3 * (a2 - b2) + 3 * (a * c2r - b * ci) + c1c2r + 1;
      t2i = 6 * a * b + 3 * (a * ci + b * c2r) + c1c2i;
    }
    const double t = t2r * t2r + t2i * t2i;
    a = (t1r * t2r + t1i * t2i) / t;
    b = (t1i * t2r - t1r * t2i) / t;
    // Squared: (a + bi)² = a² − b² + 2abi.
    b2 = b * b;
    b = 2 * a * b;
    a = a * a - b2;
    a2 = a * a;
    b2 = b * b;
    const double dist2 = a2 + b2;
    if (dist2 < minDist2) minDist2 = dist2;
    const double am1 = a - 1;
    if (dist2 > 10000.0 || am1 * am1 + b2 < 1 / 10000.0) return exteriorValue(f, i, a, b);
  }
  return interiorValue(f, a, b, minDist2);
}

}  // namespace

double fractalValue(PatternType type, const FractalParams& f, const Vec3& p) {
  switch (type) {
    case PatternType::mandel:
      return powerSet(f, p.x, p.y, p.x, p.y);
    case PatternType::julia:
      return powerSet(f, p.x, p.y, f.cReal, f.cImaginary);
    case PatternType::magnet:
      return magnet(f, p);
    default:
      return 0.0;
  }
}

}  // namespace lucent
