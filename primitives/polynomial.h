// Real roots of polynomials on an interval: the torus's quartic, the lathe's sextic, the
// sphere sweep's tenth-degree envelope condition, a poly's line polynomial up to degree 35
// (POV-Ray's MAX_ORDER).
//
// Method: Yuksel, "High-Performance Polynomial Root Finding for Graphics" (HPG 2022). The
// roots of the derivative split the interval into pieces on which the polynomial is
// monotonic; each piece whose ends differ in sign holds exactly one root, found by Newton
// steps kept inside the bracket (bisection when a step leaves it). The derivative's roots
// come from the same procedure one degree down. Unlike Ferrari's closed form, nothing
// cancels catastrophically, a root is never lost between the pieces, and a tangent ray
// shows up as a critical point where the polynomial is zero up to its rounding error.
#pragma once

namespace lucent {

constexpr int kMaxPolynomialDegree = 35;

struct PolynomialRoot {
  double x;
  bool touching;  // a critical point where p is 0 within rounding: a double (tangent) root
};

// p(x) = Σ c[i]·x^i of degree n (1 <= n <= 35, c[n] != 0). cAbs[i] bounds the magnitude of
// the terms that make up c[i] (c[i]'s own rounding error is a few ulps of it), so that
// gamma(2n + 6)·Σ cAbs[i]·|x|^i bounds the error of p's value at x. Writes the roots in
// (lo, hi), ascending, to out (room for n) and returns their count. A touching root is
// reported once, at the critical point. p(lo) and p(hi) should be clearly nonzero.
int polynomialRoots(const double* c, const double* cAbs, int n, double lo, double hi,
                    PolynomialRoot* out);

// Horner evaluation of p and of its derivative.
double evalPolynomial(const double* c, int n, double x);
double evalPolynomialDerivative(const double* c, int n, double x);

}  // namespace lucent
