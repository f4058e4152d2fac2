#include "poly.h"

#include "implicit_surface.h"
#include "polynomial.h"
#include "quadric.h"
#include "span.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucent {

Poly::Poly(int order, const std::vector<double>& coefficients) : order_(order) {
  if (order < 2 || order > kMaxOrder)
    throw std::invalid_argument("poly: the order must be from 2 to 35");
  if (static_cast<int>(coefficients.size()) != termCount(order))
    throw std::invalid_argument("poly: wrong number of coefficients for the order");
  const size_t side = static_cast<size_t>(order) + 1;
  dense_.assign(side * side * side, 0.0);
  size_t index = 0;
  bool surface = false;
  for (int i = order; i >= 0; --i)
    for (int j = order - i; j >= 0; --j)
      for (int k = order - i - j; k >= 0; --k) {
        const double c = coefficients[index++];
        if (!std::isfinite(c)) throw std::invalid_argument("poly: coefficients must be finite");
        dense_[(static_cast<size_t>(i) * side + static_cast<size_t>(j)) * side +
               static_cast<size_t>(k)] = c;
        if (c == 0.0) continue;
        if (i + j + k > 0) surface = true;
        terms_.push_back({i, j, k, c});
      }
  if (!surface) throw std::invalid_argument("poly: every coefficient but the constant is 0");
  // x², xy, xz, x, y², yz, y, z², z, 1.
  const auto& q = coefficients;
  if (order == 2)
    bounds_ =
        Quadric({Vec3(q[0], q[4], q[7]), Vec3(q[1], q[2], q[5]), Vec3(q[3], q[6], q[8]), q[9]})
            .bounds();
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

// A polynomial in u of degree <= D, and the magnitudes of what each of its coefficients
// sums (the inputs' absolute values through the same operations), for the root finder's
// error bound.
template <int D>
struct LinePolynomial {
  double c[D + 1] = {}, a[D + 1] = {};
};

// r = r·(o + d·u) + add: one Horner step in polynomial arithmetic, r of degree < n <= D.
template <int D>
void hornerStep(LinePolynomial<D>& r, int n, double o, double d, double ao, double ad,
                const LinePolynomial<D>& add) {
  for (int m = n; m >= 1; --m) {
    r.c[m] = r.c[m] * o + r.c[m - 1] * d + add.c[m];
    r.a[m] = r.a[m] * ao + r.a[m - 1] * ad + add.a[m];
  }
  r.c[0] = r.c[0] * o + add.c[0];
  r.a[0] = r.a[0] * ao + add.a[0];
}

// P = Σ_i x^i Σ_j y^j Σ_k c_ijk z^k, each sum by Horner's rule in its variable, the
// variables being the linear polynomials o + d·u. N > 0: the order, known when compiling
// so that the loops of the common orders 2 to 4 unroll; N = 0: any order, given as n.
template <int N>
void expandAlongLine(const double* dense, int n, const Vec3& o, const Vec3& d, double* c,
                     double* cAbs) {
  constexpr int D = N > 0 ? N : Poly::kMaxOrder;
  if constexpr (N > 0) n = N;
  const int side = n + 1;
  const Vec3 ao = glm::abs(o), ad = glm::abs(d);
  LinePolynomial<D> px;
  for (int i = n; i >= 0; --i) {
    LinePolynomial<D> py;
    for (int j = n - i; j >= 0; --j) {
      LinePolynomial<D> pz;
      for (int k = n - i - j; k >= 0; --k) {
        LinePolynomial<D> constant;
        constant.c[0] = dense[(i * side + j) * side + k];
        constant.a[0] = std::abs(constant.c[0]);
        hornerStep(pz, n, o.z, d.z, ao.z, ad.z, constant);
      }
      hornerStep(py, n, o.y, d.y, ao.y, ad.y, pz);
    }
    hornerStep(px, n, o.x, d.x, ao.x, ad.x, py);
  }
  for (int m = 0; m <= n; ++m) {
    c[m] = px.c[m];
    cAbs[m] = px.a[m];
  }
}

}  // namespace

void Poly::linePolynomial(const Vec3& o, const Vec3& d, double* c, double* cAbs) const {
  switch (order_) {
    case 2:
      return expandAlongLine<2>(dense_.data(), 2, o, d, c, cAbs);
    case 3:
      return expandAlongLine<3>(dense_.data(), 3, o, d, c, cAbs);
    case 4:
      return expandAlongLine<4>(dense_.data(), 4, o, d, c, cAbs);
    default:
      return expandAlongLine<0>(dense_.data(), order_, o, d, c, cAbs);
  }
}

int Poly::lineCrossings(const Ray& ray, double t[kMaxOrder], bool entering[kMaxOrder],
                        bool& startsInside) const {
  // The line from its point closest to the object's origin: s = s0 + u.
  const double dd = glm::dot(ray.d, ray.d);
  const double s0 = dd > 0.0 ? -glm::dot(ray.o, ray.d) / dd : 0.0;
  const Vec3 o = ray.o + s0 * ray.d;
  double c[kN], cAbs[kN];
  linePolynomial(o, ray.d, c, cAbs);
  // A leading coefficient within its own rounding error is 0: the line runs along an
  // asymptotic direction and that root has gone to infinity.
  int degree = order_;
  while (degree > 0 && std::abs(c[degree]) <= gamma(2 * order_ + 6) * cAbs[degree]) --degree;
  if (degree == 0) {
    startsInside = c[0] < 0.0;  // P is constant along the line
    return 0;
  }
  // Every real root lies in (-r, r) by Cauchy's bound, 1 + max |c_i/c_n|, and, above
  // degree 4, by Fujiwara's, 2·max |c_(n−k)/c_n|^(1/k) (the last term halved; 1 is added to
  // keep the interval's ends clear of a root at 0), whichever is smaller. On a line almost
  // square to a high power Cauchy's is 1e11 where Fujiwara's is 1e3, and the needlessly wide
  // interval starves the root finder's Newton steps (at order 34 the roots within a unit of
  // the origin were lost in 2 of 400 lines). Up to degree 4 Cauchy's alone, as measured in
  // docs/accuracy.md (Fujiwara's moved the tangle cube's worst clear t error from 9.3e-15 to
  // 1.6e-14, over its bound). Beyond 1e60, or where r^degree would pass 1e250
  // (10^(250/degree), 1.4e7 at order 35), a root is too far to matter and the powers would
  // overflow.
  double cauchy = 0.0, fujiwara = 0.0;
  for (int i = 0; i < degree; ++i) {
    const double ratio = std::abs(c[i] / c[degree]);
    cauchy = std::max(cauchy, ratio);
    if (degree > 4)
      fujiwara = std::max(fujiwara, std::pow(i == 0 ? 0.5 * ratio : ratio, 1.0 / (degree - i)));
  }
  const double r = std::min({2.0 * (1.0 + cauchy), degree > 4 ? 2.0 * fujiwara + 1.0 : 1e300, 1e60,
                             std::pow(10.0, 250.0 / static_cast<double>(degree))});
  // Only the ray's stretch is searched: a narrower bracket takes the root finder far fewer
  // steps (a clipped quartic's stretch through its box against Cauchy's bound). Each end is
  // widened by twice the most the polish below moves a root, so that every root that could
  // end up in [tmin, tmax] is still found and the sign at the start is the state there.
  const auto widen = [](double u) { return 2e-6 * (1.0 + std::abs(u)); };
  double lo = -r, hi = r;
  if (std::isfinite(ray.tmin)) lo = std::max(lo, ray.tmin - s0 - widen(ray.tmin - s0));
  if (std::isfinite(ray.tmax)) hi = std::min(hi, ray.tmax - s0 + widen(ray.tmax - s0));
  if (!(lo < hi)) {
    // No root can lie in the stretch: P keeps the sign it has at its nearer end.
    startsInside = evalPolynomial(c, degree, std::clamp(ray.tmin - s0, -r, r)) < 0.0;
    return 0;
  }
  PolynomialRoot roots[kMaxOrder];
  const int found = polynomialRoots(c, cAbs, degree, lo, hi, roots);

  // The sign of P before the first root and in each gap after one decides which roots
  // cross (a tangent ray's double root has the same sign on both sides).
  bool insideBefore = evalPolynomial(c, degree, lo) < 0.0;
  startsInside = insideBefore;
  int n = 0;
  for (int k = 0; k < found; ++k) {
    const double next = k + 1 < found ? roots[k + 1].x : hi;
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
  const Vec3 p = ray.at(hit.t);
  const Vec3 g = gradient(p);
  SurfaceInfo s = implicitSurface(ray, hit, p, g);
  // Beyond the rounding of the point, the band around the surface where P's computed sign
  // is unsure: any line through a point near p evaluates P from coordinates of at most
  // √2·|p| (its point closest to the origin and the step from there), so within
  // gamma(2n + 6)·Σ|c|·(√2|p|)^degree of P, as polynomialRoots bounds it; divided by |∇P|
  // that is a distance. Capped where ∇P vanishes (a singular point).
  const double len = glm::length(g);
  const double reach = std::sqrt(2.0) * glm::length(s.p);
  double magnitude = 0.0;
  for (const Term& t : terms_) magnitude += std::abs(t.c) * std::pow(reach, t.i + t.j + t.k);
  const double cap = 1e-6 * (1.0 + glm::length(s.p));
  const double band = gamma(2 * order_ + 6) * magnitude;
  s.pError += Vec3(len > 0.0 ? std::min(band / len, cap) : cap);
  return s;
}

}  // namespace lucent
