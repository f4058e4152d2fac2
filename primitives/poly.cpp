#include "poly.h"

#include "polynomial.h"
#include "quadric.h"
#include "span.h"

#include <algorithm>
#include <stdexcept>

namespace lucent {

Poly::Poly(int order, const std::vector<double>& coefficients) : order_(order) {
  if (order < 2 || order > kMaxOrder) throw std::invalid_argument("poly: the order must be 2, 3 or 4");
  if (static_cast<int>(coefficients.size()) != termCount(order))
    throw std::invalid_argument("poly: wrong number of coefficients for the order");
  size_t index = 0;
  bool surface = false;
  for (int i = order; i >= 0; --i)
    for (int j = order - i; j >= 0; --j)
      for (int k = order - i - j; k >= 0; --k) {
        const double c = coefficients[index++];
        if (!std::isfinite(c)) throw std::invalid_argument("poly: coefficients must be finite");
        if (c == 0.0) continue;
        if (i + j + k > 0) surface = true;
        terms_.push_back({i, j, k, c});
      }
  if (!surface) throw std::invalid_argument("poly: every coefficient but the constant is 0");
  // x², xy, xz, x, y², yz, y, z², z, 1.
  const auto& q = coefficients;
  if (order == 2)
    bounds_ = Quadric({Vec3(q[0], q[4], q[7]), Vec3(q[1], q[2], q[5]), Vec3(q[3], q[6], q[8]), q[9]}).bounds();
}

namespace {

// x^0 .. x^n at one point.
void powers(double x, int n, double* out) {
  out[0] = 1.0;
  for (int i = 1; i <= n; ++i) out[i] = out[i - 1] * x;
}

}  // namespace

double Poly::value(const Vec3& p) const {
  double px[kMaxOrder + 1], py[kMaxOrder + 1], pz[kMaxOrder + 1];
  powers(p.x, order_, px);
  powers(p.y, order_, py);
  powers(p.z, order_, pz);
  double v = 0.0;
  for (const Term& t : terms_) v += t.c * px[t.i] * py[t.j] * pz[t.k];
  return v;
}

Vec3 Poly::gradient(const Vec3& p) const {
  double px[kMaxOrder + 1], py[kMaxOrder + 1], pz[kMaxOrder + 1];
  powers(p.x, order_, px);
  powers(p.y, order_, py);
  powers(p.z, order_, pz);
  Vec3 g(0.0);
  for (const Term& t : terms_) {
    if (t.i > 0) g.x += t.c * t.i * px[t.i - 1] * py[t.j] * pz[t.k];
    if (t.j > 0) g.y += t.c * t.j * px[t.i] * py[t.j - 1] * pz[t.k];
    if (t.k > 0) g.z += t.c * t.k * px[t.i] * py[t.j] * pz[t.k - 1];
  }
  return g;
}

namespace {

constexpr int kN = Poly::kMaxOrder + 1;

// (a + b·u)^p for p = 0..n as polynomials in u (binomial rows), and the same with |a|, |b|
// for the magnitudes.
void linearPowers(double a, double b, int n, double out[kN][kN]) {
  for (int p = 0; p <= n; ++p)
    for (int m = 0; m <= n; ++m) out[p][m] = 0.0;
  out[0][0] = 1.0;
  for (int p = 1; p <= n; ++p)
    for (int m = 0; m <= p; ++m)
      out[p][m] = out[p - 1][m] * a + (m > 0 ? out[p - 1][m - 1] * b : 0.0);
}

// r = f·g, of degrees df and dg.
void multiply(const double* f, int df, const double* g, int dg, double* r) {
  for (int m = 0; m <= df + dg; ++m) r[m] = 0.0;
  for (int a = 0; a <= df; ++a)
    for (int b = 0; b <= dg; ++b) r[a + b] += f[a] * g[b];
}

}  // namespace

int Poly::lineCrossings(const Ray& ray, double t[kMaxOrder], bool entering[kMaxOrder],
                        bool& startsInside) const {
  // The line from its point closest to the object's origin: s = s0 + u.
  const double dd = glm::dot(ray.d, ray.d);
  const double s0 = dd > 0.0 ? -glm::dot(ray.o, ray.d) / dd : 0.0;
  const Vec3 o = ray.o + s0 * ray.d;
  double X[kN][kN], Y[kN][kN], Z[kN][kN], XA[kN][kN], YA[kN][kN], ZA[kN][kN];
  linearPowers(o.x, ray.d.x, order_, X);
  linearPowers(o.y, ray.d.y, order_, Y);
  linearPowers(o.z, ray.d.z, order_, Z);
  linearPowers(std::abs(o.x), std::abs(ray.d.x), order_, XA);
  linearPowers(std::abs(o.y), std::abs(ray.d.y), order_, YA);
  linearPowers(std::abs(o.z), std::abs(ray.d.z), order_, ZA);
  double c[kN] = {}, cAbs[kN] = {};
  for (const Term& term : terms_) {
    double xy[kN], xyz[kN], xyA[kN], xyzA[kN];
    multiply(X[term.i], term.i, Y[term.j], term.j, xy);
    multiply(xy, term.i + term.j, Z[term.k], term.k, xyz);
    multiply(XA[term.i], term.i, YA[term.j], term.j, xyA);
    multiply(xyA, term.i + term.j, ZA[term.k], term.k, xyzA);
    const int degree = term.i + term.j + term.k;
    for (int m = 0; m <= degree; ++m) {
      c[m] += term.c * xyz[m];
      cAbs[m] += std::abs(term.c) * xyzA[m];
    }
  }
  // A leading coefficient within its own rounding error is 0: the line runs along an
  // asymptotic direction and that root has gone to infinity.
  int degree = order_;
  while (degree > 0 && std::abs(c[degree]) <= gamma(2 * order_ + 6) * cAbs[degree]) --degree;
  if (degree == 0) {
    startsInside = c[0] < 0.0;  // P is constant along the line
    return 0;
  }
  // Cauchy's bound holds every real root in (-r, r); beyond 1e60 a root is too far to
  // matter and the powers would overflow.
  double bound = 0.0;
  for (int i = 0; i < degree; ++i) bound = std::max(bound, std::abs(c[i] / c[degree]));
  const double r = std::min(2.0 * (1.0 + bound), 1e60);
  PolynomialRoot roots[kMaxOrder];
  const int found = polynomialRoots(c, cAbs, degree, -r, r, roots);

  // The sign of P before the first root and in each gap after one decides which roots
  // cross (a tangent ray's double root has the same sign on both sides).
  bool insideBefore = evalPolynomial(c, degree, -r) < 0.0;
  startsInside = insideBefore;
  int n = 0;
  for (int k = 0; k < found; ++k) {
    const double next = k + 1 < found ? roots[k + 1].x : r;
    const bool insideAfter = evalPolynomial(c, degree, 0.5 * (roots[k].x + next)) < 0.0;
    if (insideAfter == insideBefore) continue;
    // One Newton step on P itself, unless the slope is too flat to trust.
    const double u = roots[k].x;
    const Vec3 p = o + u * ray.d;
    const double slope = glm::dot(gradient(p), ray.d);
    const double step = slope != 0.0 ? value(p) / slope : 0.0;
    t[n] = s0 + (std::abs(step) <= 1e-6 * (1.0 + std::abs(u)) ? u - step : u);
    entering[n] = insideAfter;
    ++n;
    insideBefore = insideAfter;
  }
  // The polish moves a root by far less than the gap to the next; keep the order anyway.
  for (int k = 1; k < n; ++k)
    if (t[k] < t[k - 1]) {
      std::swap(t[k], t[k - 1]);
      std::swap(entering[k], entering[k - 1]);
    }
  return n;
}

bool Poly::intersect(const Ray& ray, Hit& hit) const {
  double t[kMaxOrder];
  bool entering[kMaxOrder], startsInside;
  const int n = lineCrossings(ray, t, entering, startsInside);
  SurfaceRoot roots[kMaxOrder];
  for (int i = 0; i < n; ++i) roots[i] = {t[i]};
  return intersectRoots(roots, n, ray, this, hit);
}

void Poly::crossings(const Ray& ray, CrossingList& out) const {
  double t[kMaxOrder];
  bool entering[kMaxOrder], inside;
  const int n = lineCrossings(ray, t, entering, inside);
  crossingsOfLine(t, entering, n, inside, ray, this, out);
}

SurfaceInfo Poly::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo s;
  s.p = ray.at(hit.t);
  Vec3 n = gradient(s.p);
  const double len = glm::length(n);
  n = len > 0.0 ? n / len : Vec3(1.0, 0.0, 0.0);
  // The rounding of t·d and of the origin, as the quadric's, plus the band around the
  // surface where P's computed sign is unsure: any line through a point near p evaluates P
  // from coordinates of at most √2·|p| (its point closest to the origin and the step from
  // there), so within gamma(2n + 6)·Σ|c|·(√2|p|)^degree of P, as polynomialRoots bounds it;
  // divided by |∇P| that is a distance. Capped where ∇P vanishes (a singular point).
  s.pError = gamma(8) * (glm::abs(ray.o) + glm::abs(hit.t * ray.d)) + gamma(4) * glm::abs(s.p);
  const double reach = std::sqrt(2.0) * glm::length(s.p);
  double magnitude = 0.0;
  for (const Term& t : terms_) magnitude += std::abs(t.c) * std::pow(reach, t.i + t.j + t.k);
  const double cap = 1e-6 * (1.0 + glm::length(s.p));
  const double band = gamma(2 * order_ + 6) * magnitude;
  s.pError += Vec3(len > 0.0 ? std::min(band / len, cap) : cap);
  s.ng = n;
  s.ns = n;
  return s;
}

}  // namespace lucent
