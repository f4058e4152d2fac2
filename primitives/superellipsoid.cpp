#include "superellipsoid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucent {

namespace {

// The clipping box: N >= max(|x|, |y|, |z|) for every exponent, so N > 1 on its faces by
// far more than the rounding of points far from the origin.
constexpr double kBoxHalf = 1.0 + 1.0 / 64.0;
// N's computed value is within a few ulps of the exact gauge at the computed point (each
// ‖·‖ is 1-Lipschitz in its arguments, each pow errs by an ulp): a range of N farther than
// this from 1, plus the rounding of the points themselves, surely holds no root.
constexpr double kRangeMargin = 1e-14;
// The relative rounding of the derivative's bounds, per unit of the exponents: each bound
// is a product of pows whose exponents (p − 1, q − 1) multiply their base's rounding.
// Halvings of a piece before a stretch is decided by its end signs alone (a tangency
// within rounding).
constexpr int kMaxDepth = 80;

// x^k, without pow for the exponents of round (e or n = 1: k = 2, 1/2) and straight
// (e or n = 2: k = 1) cross-sections, whose results are the same correctly rounded values.
double power(double x, double k) {
  if (k == 2.0) return x * x;
  if (k == 1.0) return x;
  if (k == 0.5) return std::sqrt(x);
  if (k == 0.0) return 1.0;
  return std::pow(x, k);
}

// ‖(a, b)‖ with exponent p, for a, b >= 0, scaled by the larger.
double normOf(double a, double b, double p, double invP) {
  double m = std::max(a, b), s = std::min(a, b);
  if (!(s > 0.0)) return m;
  return m * power(1.0 + power(s / m, p), invP);
}

// a / ‖(a, b)‖, in [0, 1]: increasing in a, decreasing in b.
double ratioOf(double a, double b, double p, double invP) {
  if (!(a > 0.0)) return 0.0;
  if (!(b > 0.0)) return 1.0;
  if (a >= b) return 1.0 / power(1.0 + power(b / a, p), invP);
  double r = a / b;
  return r / power(1.0 + power(r, p), invP);
}

// A range of non-negative values.
struct Range {
  double lo, hi;
};

// {x^k : x in r}, r within [0, 1] (0^k is infinite for k < 0).
Range powRange(Range r, double k) {
  if (k >= 0.0) return {power(r.lo, k), power(r.hi, k)};
  return {power(r.hi, k), power(r.lo, k)};
}

Range product(Range a, Range b) {
  double lo = a.lo * b.lo, hi = a.hi * b.hi;
  if (std::isnan(lo)) lo = 0.0;  // 0·∞: nothing is known beyond the obvious
  if (std::isnan(hi)) hi = kInf;
  return {lo, hi};
}

}  // namespace

Superellipsoid::Superellipsoid(double e, double n) : e_(e), n_(n) {
  auto ok = [](double v) { return v >= kMinExponent && v <= kMaxExponent; };
  if (!ok(e) || !ok(n))
    throw std::invalid_argument("superellipsoid: the exponents e and n must lie in [0.01, 10]");
  p_ = 2.0 / e;
  invP_ = 0.5 * e;
  q_ = 2.0 / n;
  invQ_ = 0.5 * n;
}

AABB Superellipsoid::bounds() const { return {Vec3(-1.0), Vec3(1.0)}; }

double Superellipsoid::gauge(const Vec3& p) const {
  double r = normOf(std::abs(p.x), std::abs(p.y), p_, invP_);
  return normOf(r, std::abs(p.z), q_, invQ_);
}

namespace {

// ‖(a, b)‖_p for a, b >= 0 as normOf computes it, with the partial derivatives (a/N)^(p−1)
// and (b/N)^(p−1) from the same two pows (a zero argument's is 0: see gaugeAndGradient).
double normAndSlopes(double a, double b, double p, double invP, double& da, double& db) {
  const bool aMax = a >= b;
  const double m = aMax ? a : b, s = aMax ? b : a;
  if (!(s > 0.0)) {
    da = aMax ? 1.0 : 0.0;
    db = aMax ? 0.0 : 1.0;
    return m;
  }
  const double ratio = s / m, up = power(ratio, p), sum = 1.0 + up, root = power(sum, invP);
  const double dMax = root / sum, dMin = up / ratio * dMax;
  da = aMax ? dMax : dMin;
  db = aMax ? dMin : dMax;
  return m * root;
}

}  // namespace

std::pair<double, Vec3> Superellipsoid::gaugeAndGradient(const Vec3& p) const {
  // ∂N/∂z = (Z/N)^(q−1), ∂N/∂x = (R/N)^(q−1)·(X/R)^(p−1), R = ‖(X, Y)‖_p: powers of ratios
  // in [0, 1], so only a zero ratio under a negative power (a crease) is infinite.
  const double X = std::abs(p.x), Y = std::abs(p.y), Z = std::abs(p.z);
  double dX, dY, dR, dZ;
  const double R = normAndSlopes(X, Y, p_, invP_, dX, dY);
  const double N = normAndSlopes(R, Z, q_, invQ_, dR, dZ);
  double gX = dR * dX, gY = dR * dY, gZ = dZ;
  // On a coordinate plane the surface is symmetric: its normal (or the mean of the two
  // sides' normals, on a kink or crease) has no component across the plane.
  if (X == 0.0 || std::isnan(gX)) gX = 0.0;
  if (Y == 0.0 || std::isnan(gY)) gY = 0.0;
  if (Z == 0.0 || std::isnan(gZ)) gZ = 0.0;
  return {N, {std::copysign(gX, p.x), std::copysign(gY, p.y), std::copysign(gZ, p.z)}};
}

bool Superellipsoid::inside(const Vec3& p) const { return gauge(p) < 1.0; }

namespace {

// One line's search: the pieces, their stretches and the refinement of each root.
class LineSolver {
 public:
  LineSolver(const Superellipsoid& s, double p, double invP, double q, double invQ, const Ray& ray,
             double margin, Superellipsoid::Roots& out, double firstAfter)
      : s_(s),
        p_(p),
        invP_(invP),
        q_(q),
        invQ_(invQ),
        o_(ray.o),
        d_(ray.d),
        margin_(margin),
        slopeSlack_(8.0 * kMachineEps * (std::abs(p - 1.0) + std::abs(q - 1.0) + 8.0)),
        out_(out),
        firstAfter_(firstAfter) {}

  // N − 1 at o + t·d: negative inside.
  double value(double t) const { return s_.gauge(o_ + t * d_) - 1.0; }

  // The roots on one piece [a, b], on which the signs of x, y, z are fixed: slope holds
  // d|x|/dt, d|y|/dt, d|z|/dt there.
  void piece(double a, double fa, double b, double fb, const Vec3& slope) {
    slope_ = slope;
    isolate(a, fa, b, fb, 0);
  }

  bool done() const { return done_; }

  // For e, n <= 2, N is a norm (an absolute norm of a norm), so f = N − 1 is convex along
  // the whole line, and a tangent (with any subgradient at a kink) lies below it. Newton's
  // steps from an end where f > 0 therefore never pass a root: from the left they climb to
  // the first root (quadratically where it is simple), from the right to the last, and a
  // step that meets a non-negative slope, or lands beyond the window, proves that side
  // holds no root. One root where the ends' signs differ, none where both are negative.
  // False when it cannot decide (no convergence, a slope that is not finite): then the
  // general search runs, nothing having been recorded.
  // fa and ga: f and its slope at a, known to the caller; f at b is computed only if needed.
  bool convexWindow(double a, double fa, double ga, double b) {
    double tl = a, tr = b;
    if (fa >= 0.0) {
      const Side left = newtonFrom(a, fa, ga, b, +1.0, tl);
      if (left == Side::Undecided) return false;
      if (left == Side::None) return true;  // the tangents prove f > 0 over [a, b]
      if (tl > firstAfter_) {
        recordRoot(tl);
        return true;
      }
    }
    const auto [nb, gradB] = s_.gaugeAndGradient(o_ + b * d_);
    const double fb = nb - 1.0;
    if (fb < 0.0) {
      if (fa >= 0.0) recordRoot(tl);  // the one root; none at all when both ends are inside
      return true;
    }
    const Side right = newtonFrom(b, fb, glm::dot(gradB, d_), fa >= 0.0 ? tl : a, -1.0, tr);
    if (right != Side::Root) return false;  // a root must be there: leave it to the search
    if (fa >= 0.0) recordRoot(tl);
    if (!done_) recordRoot(tr);
    return true;
  }

  // f and its slope at t, from one evaluation.
  std::pair<double, double> valueAndSlope(double t) const {
    const auto [n, grad] = s_.gaugeAndGradient(o_ + t * d_);
    return {n - 1.0, glm::dot(grad, d_)};
  }

 private:
  enum class Side { Root, None, Undecided };

  // Newton's steps on f from t (f(t) >= 0, slope given) in the direction `dir` (+1: up),
  // towards `limit`: Root with the root in `root`, None if the tangents prove f > 0 all the
  // way to `limit`, Undecided if neither within the iterations or the slope is not finite.
  Side newtonFrom(double t, double f, double slope, double limit, double dir, double& root) const {
    double g = slope * dir;
    for (int it = 0; it < 100; ++it) {
      if (f <= 0.0) {
        root = t;  // on the surface to the last bit, or just past it by rounding
        return Side::Root;
      }
      if (!std::isfinite(g)) return Side::Undecided;
      if (g >= 0.0) return Side::None;  // f rises from here on that side
      const double next = t - dir * f / g;
      if (dir * (next - limit) >= 0.0) return Side::None;  // the tangent meets 0 beyond the window
      // A step within the last bits of t: the root, as closely as double tells.
      if (std::abs(next - t) <= 2.0 * kMachineEps * std::max(std::abs(t), std::abs(next))) {
        root = next;
        return Side::Root;
      }
      t = next;
      const auto [N, grad] = s_.gaugeAndGradient(o_ + t * d_);
      f = N - 1.0;
      g = glm::dot(grad, d_) * dir;
    }
    return Side::Undecided;
  }

  void recordRoot(double t) {
    if (out_.count < Superellipsoid::kMaxRoots) out_.t[out_.count++] = t;
    if (t > firstAfter_) done_ = true;
  }

  Vec3 absAt(double t) const { return glm::abs(o_ + t * d_); }
  double slopeAt(double t) const { return glm::dot(s_.gradient(o_ + t * d_), d_); }

  void isolate(double a, double fa, double b, double fb, int depth) {
    if (done_) return;
    const bool change = (fa < 0.0) != (fb < 0.0);
    if (resolved(a, fa, b, fb)) {
      if (change) addRoot(a, fa, b, fb);
      return;
    }
    const double m = a + 0.5 * (b - a);
    if (depth >= kMaxDepth || !(a < m && m < b) ||
        b - a <= 4.0 * kMachineEps * std::max(std::abs(a), std::abs(b))) {
      if (change) addRoot(a, fa, b, fb);
      return;
    }
    const double fm = value(m);
    isolate(a, fa, m, fm, depth + 1);
    isolate(m, fm, b, fb, depth + 1);
  }

  // Whether the stretch [a, b] holds exactly as many roots as its end signs tell (one if
  // they differ, none if not): N − 1 surely excludes 0 there, or is monotone, or varies
  // less than its own rounding (a face flat to rounding, a tangency: nothing finer can be
  // told).
  bool resolved(double a, double fa, double b, double fb) const {
    const Vec3 A = absAt(a), B = absAt(b);
    const Vec3 lo = glm::min(A, B), hi = glm::max(A, B);
    const double rLo = normOf(lo.x, lo.y, p_, invP_), rHi = normOf(hi.x, hi.y, p_, invP_);
    // N is increasing in |x|, |y|, |z|, each affine over the stretch: N at the corners.
    double low = normOf(rLo, lo.z, q_, invQ_) - 1.0, high = normOf(rHi, hi.z, q_, invQ_) - 1.0;
    if (low > margin_ || high < -margin_) return true;
    double dLo, dHi;
    slopeBounds(lo, hi, rLo, rHi, dLo, dHi);
    if (dLo >= 0.0 || dHi <= 0.0) return true;
    // The mean-value form, f(t) = f(a) + f'(ξ)(t − a): tight where the corners are loose,
    // as on a ray parallel to a flat face, along which |x|, |y|, |z| change and N does not.
    const double w = b - a;
    low = std::max({low, fa + dLo * w, fb - dHi * w});
    high = std::min({high, fa + dHi * w, fb - dLo * w});
    return low > margin_ || high < -margin_ || high - low <= margin_;
  }

  // Bounds of dN/dt over the box [lo, hi] of (|x|, |y|, |z|), widened by their rounding;
  // 0 is a bound only when the derivative surely has that sign (or is 0).
  void slopeBounds(const Vec3& lo, const Vec3& hi, double rLo, double rHi, double& dLo,
                   double& dHi) const {
    double posLo = 0.0, posHi = 0.0, negLo = 0.0, negHi = 0.0;
    auto add = [&](Range g, double slope) {
      if (slope > 0.0) {
        posLo += g.lo * slope;
        posHi += g.hi * slope;
      } else if (slope < 0.0) {
        negLo += g.lo * -slope;
        negHi += g.hi * -slope;
      }
    };
    if (slope_.x != 0.0 || slope_.y != 0.0) {
      // R/N rises with R and falls with |z|; X/R rises with |x| and falls with |y|.
      const Range gR =
          powRange({ratioOf(rLo, hi.z, q_, invQ_), ratioOf(rHi, lo.z, q_, invQ_)}, q_ - 1.0);
      if (slope_.x != 0.0)
        add(product(gR, powRange({ratioOf(lo.x, hi.y, p_, invP_), ratioOf(hi.x, lo.y, p_, invP_)},
                                 p_ - 1.0)),
            slope_.x);
      if (slope_.y != 0.0)
        add(product(gR, powRange({ratioOf(lo.y, hi.x, p_, invP_), ratioOf(hi.y, lo.x, p_, invP_)},
                                 p_ - 1.0)),
            slope_.y);
    }
    if (slope_.z != 0.0)
      add(powRange({ratioOf(lo.z, rHi, q_, invQ_), ratioOf(hi.z, rLo, q_, invQ_)}, q_ - 1.0),
          slope_.z);
    dLo = negHi == 0.0 ? 0.0 : posLo * (1.0 - slopeSlack_) - negHi * (1.0 + slopeSlack_);
    dHi = posHi == 0.0 ? 0.0 : posHi * (1.0 + slopeSlack_) - negLo * (1.0 - slopeSlack_);
    if (std::isnan(dLo)) dLo = -kInf;
    if (std::isnan(dHi)) dHi = kInf;
  }

  void addRoot(double a, double fa, double b, double fb) {
    double t = refine(a, fa, b, fb);
    if (out_.count < Superellipsoid::kMaxRoots) out_.t[out_.count++] = t;
    if (t > firstAfter_) done_ = true;
  }

  // Newton kept inside the bracket [a, b] whose ends differ in sign, bisecting when a step
  // leaves it or does not halve the previous one (Numerical Recipes' rtsafe). Returns the
  // bracket's end where |N − 1| is smaller once the two are adjacent (or N = 1 exactly).
  double refine(double a, double fa, double b, double fb) const {
    const bool aInside = fa < 0.0;
    double lo = a, hi = b, fLo = fa, fHi = fb;
    double t = a + 0.5 * (b - a);
    double dxOld = b - a, dx = dxOld;
    for (int it = 0; it < 200; ++it) {
      const auto [N, grad] = s_.gaugeAndGradient(o_ + t * d_);
      const double f = N - 1.0;
      if (f == 0.0) return t;
      if ((f < 0.0) == aInside) {
        lo = t;
        fLo = f;
      } else {
        hi = t;
        fHi = f;
      }
      const double df = glm::dot(grad, d_);
      double next = 0.0;
      bool newton = std::isfinite(df) && df != 0.0;
      if (newton) {
        next = t - f / df;
        newton = lo < next && next < hi && std::abs(2.0 * f) <= std::abs(dxOld * df);
      }
      if (!newton) next = lo + 0.5 * (hi - lo);
      dxOld = dx;
      dx = next - t;
      if (!(lo < next && next < hi)) break;  // lo and hi are adjacent doubles
      t = next;
    }
    return std::abs(fLo) <= std::abs(fHi) ? lo : hi;
  }

  const Superellipsoid& s_;
  double p_, invP_, q_, invQ_;
  Vec3 o_, d_;
  double margin_;
  double slopeSlack_;  // relative rounding of the derivative's bounds
  Superellipsoid::Roots& out_;
  double firstAfter_;
  Vec3 slope_{0.0};
  bool done_ = false;
};

}  // namespace

void Superellipsoid::roots(const Ray& ray, double lo, double hi, Roots& out,
                           double firstAfter) const {
  out.count = 0;
  out.startsInside = false;
  // The line's stretch inside the clipping box.
  double tEnter = -kInf, tExit = kInf;
  for (int i = 0; i < 3; ++i) {
    if (ray.d[i] == 0.0) {
      if (!(std::abs(ray.o[i]) <= kBoxHalf)) return;
      continue;
    }
    double t0 = (-kBoxHalf - ray.o[i]) / ray.d[i], t1 = (kBoxHalf - ray.o[i]) / ray.d[i];
    if (t0 > t1) std::swap(t0, t1);
    tEnter = std::max(tEnter, t0);
    tExit = std::min(tExit, t1);
  }
  if (!(tEnter < tExit)) return;
  const double a = std::max(lo, tEnter), b = std::min(hi, tExit);
  // The rounding of the points themselves, for the range test.
  const double scale = maxComponent(glm::abs(ray.o)) +
                       std::max(std::abs(a), std::abs(b)) * maxComponent(glm::abs(ray.d));
  LineSolver solver(*this, p_, invP_, q_, invQ_, ray,
                    kRangeMargin + 8.0 * kMachineEps * (std::isfinite(scale) ? scale : 0.0), out,
                    firstAfter);
  if (!(a <= b)) {
    out.startsInside = tEnter <= lo && lo <= tExit && solver.value(lo) < 0.0;
    return;
  }
  // Cut at the coordinate planes: on each piece |x|, |y|, |z| are affine.
  double ts[5];
  int nt = 0;
  ts[nt++] = a;
  for (int i = 0; i < 3; ++i) {
    if (ray.d[i] == 0.0) continue;
    double t = -ray.o[i] / ray.d[i];
    if (a < t && t < b) ts[nt++] = t;
  }
  ts[nt++] = b;
  // At most three cuts between a and b: sorted in place (GCC 12 warns of an out-of-bounds
  // read in std::sort's unrolled code for this array, a read it can never take).
  for (int i = 2; i < nt - 1; ++i)
    for (int j = i; j > 1 && ts[j] < ts[j - 1]; --j) std::swap(ts[j], ts[j - 1]);
  double f0;
  if (e_ <= 2.0 && n_ <= 2.0) {
    const auto [fa, ga] = solver.valueAndSlope(a);
    out.startsInside = fa < 0.0;
    if (solver.convexWindow(a, fa, ga, b)) return;
    f0 = fa;
  } else {
    f0 = solver.value(a);
    out.startsInside = f0 < 0.0;
  }
  for (int k = 0; k + 1 < nt && !solver.done(); ++k) {
    const double t0 = ts[k], t1 = ts[k + 1];
    const double f1 = solver.value(t1);
    if (t0 < t1) {
      const Vec3 mid = ray.at(t0 + 0.5 * (t1 - t0));
      Vec3 slope(0.0);
      for (int i = 0; i < 3; ++i)
        slope[i] = mid[i] > 0.0 ? ray.d[i] : mid[i] < 0.0 ? -ray.d[i] : 0.0;
      solver.piece(t0, f0, t1, f1, slope);
    }
    f0 = f1;
  }
}

bool Superellipsoid::intersect(const Ray& ray, Hit& hit) const {
  Roots r;
  roots(ray, ray.tmin, ray.tmax, r, ray.tmin);
  for (int i = 0; i < r.count; ++i) {
    if (ray.tmin < r.t[i] && r.t[i] < ray.tmax) {
      hit.t = r.t[i];
      hit.shape = this;
      hit.part = 0;
      return true;
    }
  }
  return false;
}

void Superellipsoid::crossings(const Ray& ray, CrossingList& out) const {
  Roots r;
  roots(ray, ray.tmin, ray.tmax, r);
  out.startsInside = r.startsInside;
  bool in = r.startsInside;
  for (int i = 0; i < r.count; ++i) {
    Crossing c;
    c.hit.t = r.t[i];
    c.hit.shape = this;
    in = !in;
    c.entering = in;
    out.items.push_back(c);
  }
}

SurfaceInfo Superellipsoid::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo s;
  s.p = ray.at(hit.t);
  // The point's rounding, plus its distance from the surface: |N − 1| is a few ulps and
  // |∇N| >= N/|p| >= 1/√3 (Euler: ∇N·p = N), so that distance is below √3 times it.
  s.pError = gamma(16) * (glm::abs(ray.o) + glm::abs(hit.t * ray.d)) + Vec3(gamma(64));
  Vec3 g = gradient(s.p);
  double m = maxComponent(glm::abs(g));
  if (std::isinf(m)) {
    // On a crease of an exponent above 2: the limit of the normals is along the axis
    // whose component is infinite.
    for (int i = 0; i < 3; ++i) g[i] = std::isinf(g[i]) ? std::copysign(1.0, g[i]) : 0.0;
  } else if (m > 0.0) {
    g /= m;
  } else {
    g = s.p;
  }
  s.ng = glm::normalize(g);
  s.ns = s.ng;
  return s;
}

}  // namespace lucent
