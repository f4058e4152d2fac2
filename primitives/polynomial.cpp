#include "polynomial.h"

#include "math.h"

#include <algorithm>
#include <cmath>

namespace lucent {

double evalPolynomial(const double* c, int n, double x) {
  double r = c[n];
  for (int i = n - 1; i >= 0; --i) r = r * x + c[i];
  return r;
}

double evalPolynomialDerivative(const double* c, int n, double x) {
  double r = n * c[n];
  for (int i = n - 1; i >= 1; --i) r = r * x + i * c[i];
  return r;
}

namespace {

// Everything below is written for a degree known when compiling (N), so that the Horner
// loops unroll; the arithmetic is the same, operation for operation, as for a degree
// given at run time.

template <int N>
double evalN(const double* c, double x) {
  double r = c[N];
  for (int i = N - 1; i >= 0; --i) r = r * x + c[i];
  return r;
}

template <int N>
double evalDerivativeN(const double* c, double x) {
  double r = N * c[N];
  for (int i = N - 1; i >= 1; --i) r = r * x + i * c[i];
  return r;
}

// p' and the magnitudes behind its coefficients.
template <int N>
void derivative(const double* c, const double* cAbs, double* d, double* dAbs) {
  for (int i = 0; i < N; ++i) {
    d[i] = (i + 1) * c[i + 1];
    dAbs[i] = (i + 1) * cAbs[i + 1];
  }
}

template <int N>
double errorBound(const double* cAbs, double x) {
  double ax = std::abs(x), r = cAbs[N];
  for (int i = N - 1; i >= 0; --i) r = r * ax + cAbs[i];
  return gamma(2 * N + 6) * r;
}

// The one root of p in (a, b), where p(a) and p(b) have opposite signs and p is monotonic:
// Newton steps kept inside the shrinking bracket, bisection when a step would leave it
// (Numerical Recipes' rtsafe). It stops once |p(x)| is within the rounding error of its
// evaluation (then x is as good as the coefficients allow; one more Newton step is taken)
// or the step falls below a few ulps: waiting for the step itself to vanish would make
// Newton chase the rounding noise of p near the root for dozens of iterations. A bracket
// may span the Cauchy bound of a line polynomial with a tiny leading coefficient (1e11 for a
// sextic poly met by a line almost square to its x⁶ axis) with the root near 0: halving it
// down to the ulps of the root takes about 90 steps, so the cap of 400 is never the reason
// to stop (at 100 such a root came back unfinished, a critical point off by far more than
// its piece, and the roots beside it were lost).
template <int N>
double refineBracketed(const double* c, const double* cAbs, double a, double b, double fa) {
  double x = 0.5 * (a + b);
  for (int it = 0; it < 400; ++it) {
    double fx = evalN<N>(c, x);
    if (fx == 0.0) return x;
    if ((fx < 0.0) == (fa < 0.0)) {
      a = x;
      fa = fx;
    } else {
      b = x;
    }
    double df = evalDerivativeN<N>(c, x);
    double next = df != 0.0 ? x - fx / df : 0.5 * (a + b);
    bool newton = a < next && next < b;
    if (!newton) next = 0.5 * (a + b);
    if (newton && std::abs(fx) <= errorBound<N>(cAbs, x)) return next;
    if (std::abs(next - x) <= 4.0 * kMachineEps * std::abs(next) || next == a || next == b)
      return next;
    x = next;
  }
  return x;
}

// The root of a linear p in (lo, hi), if any.
inline int linearRoot(const double* c, double lo, double hi, double& x) {
  x = -c[0] / c[1];
  return lo < x && x < hi ? 1 : 0;
}

// Roots where p changes sign in (lo, hi), ascending (used for the derivatives, whose
// touching roots are inflections of p and need no splitting).
template <int N>
int signChangeRoots(const double* c, const double* cAbs, double lo, double hi, double* out);

template <>
int signChangeRoots<1>(const double* c, const double*, double lo, double hi, double* out) {
  return linearRoot(c, lo, hi, out[0]);
}

// A quadratic's sign changes in closed form (the cancellation-free pair q/c2, c0/q with
// q = -(c1 + sign(c1)·√disc)/2): they only split a cubic into monotonic pieces, whose ends
// are evaluated anyway, so the few ulps they may be off change nothing.
template <>
int signChangeRoots<2>(const double* c, const double*, double lo, double hi, double* out) {
  if (c[2] == 0.0) return c[1] != 0.0 ? linearRoot(c, lo, hi, out[0]) : 0;
  const double disc = c[1] * c[1] - 4.0 * c[2] * c[0];
  if (!(disc > 0.0)) return 0;  // no sign change: no root, or a double one
  const double q = -0.5 * (c[1] + std::copysign(std::sqrt(disc), c[1]));
  double r1 = q / c[2], r2 = q != 0.0 ? c[0] / q : -r1;
  if (r1 > r2) std::swap(r1, r2);
  int count = 0;
  if (lo < r1 && r1 < hi) out[count++] = r1;
  if (lo < r2 && r2 < hi && r2 != r1) out[count++] = r2;
  return count;
}

template <int N>
int signChangeRoots(const double* c, const double* cAbs, double lo, double hi, double* out) {
  double d[N] = {}, dAbs[N] = {};
  derivative<N>(c, cAbs, d, dAbs);
  double pts[N + 2];
  int m = 0;
  pts[m++] = lo;
  m += signChangeRoots<N - 1>(d, dAbs, lo, hi, pts + m);
  pts[m++] = hi;
  int count = 0;
  double fa = evalN<N>(c, pts[0]);
  for (int i = 0; i + 1 < m; ++i) {
    double fb = evalN<N>(c, pts[i + 1]);
    if (fa == 0.0 && i > 0) {
      out[count++] = pts[i];
    } else if ((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0)) {
      out[count++] = refineBracketed<N>(c, cAbs, pts[i], pts[i + 1], fa);
    }
    fa = fb;
  }
  return count;
}

template <int N>
int polynomialRootsN(const double* c, const double* cAbs, double lo, double hi,
                     PolynomialRoot* out) {
  // Split points: the ends and the critical points (roots of p').
  double d[N] = {}, dAbs[N] = {};
  derivative<N>(c, cAbs, d, dAbs);
  double pts[N + 2];
  int m = 0;
  pts[m++] = lo;
  m += signChangeRoots<N - 1>(d, dAbs, lo, hi, pts + m);
  pts[m++] = hi;

  // Sign at each split point; 0 for an interior critical point where p is 0 up to its
  // rounding error (the two roots around it cannot be told apart from a double root).
  double val[N + 2];
  int sgn[N + 2];
  for (int i = 0; i < m; ++i) {
    val[i] = evalN<N>(c, pts[i]);
    bool interior = i > 0 && i + 1 < m;
    sgn[i] = (interior && std::abs(val[i]) <= errorBound<N>(cAbs, pts[i])) ? 0
             : val[i] > 0.0                                                ? 1
             : val[i] < 0.0                                                ? -1
                                                                           : 0;
  }
  int count = 0;
  int lastSign = sgn[0];
  for (int i = 1; i < m; ++i) {
    if (sgn[i] == 0) {
      // A touching point: the sign either comes back (a double root) or changes across it
      // (an odd root with zero slope, e.g. a triple one); decide by the next nonzero sign.
      int j = i + 1;
      while (j < m && sgn[j] == 0) ++j;
      int after = j < m ? sgn[j] : lastSign;
      out[count++] = {pts[i], after == lastSign};
      lastSign = after;
      // Skip the other zero points of the run (degenerate, at most a couple of ulps apart).
      i = j - 1;
      continue;
    }
    if (sgn[i] != lastSign && sgn[i - 1] != 0) {
      out[count++] = {refineBracketed<N>(c, cAbs, pts[i - 1], pts[i], val[i - 1]), false};
    }
    lastSign = sgn[i];
  }
  return count;
}

}  // namespace

namespace {

// The degree-N solver for n = N, or the next one up: the instantiations 2 to
// kMaxPolynomialDegree without writing each case, the low degrees (the torus's, the
// lathe's) tested first.
template <int N>
int rootsOfDegree(const double* c, const double* cAbs, int n, double lo, double hi,
                  PolynomialRoot* out) {
  if (n == N) return polynomialRootsN<N>(c, cAbs, lo, hi, out);
  if constexpr (N < kMaxPolynomialDegree) return rootsOfDegree<N + 1>(c, cAbs, n, lo, hi, out);
  return 0;
}

}  // namespace

int polynomialRoots(const double* c, const double* cAbs, int n, double lo, double hi,
                    PolynomialRoot* out) {
  if (n == 1) {
    double x;
    if (!linearRoot(c, lo, hi, x)) return 0;
    out[0] = {x, false};
    return 1;
  }
  if (n < 1 || n > kMaxPolynomialDegree) return 0;
  return rootsOfDegree<2>(c, cAbs, n, lo, hi, out);
}

}  // namespace lucent
