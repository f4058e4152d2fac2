#include "sphere_sweep.h"

#include "centred_line.h"

#include "polynomial.h"
#include "quadratic.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucent {

namespace {

// POV-Ray's basis matrices (sphsweep.cpp): row k gives the weights of the four control
// spheres in the coefficient of u^k.
constexpr double kCatmullRom[4][4] = {
    {0.0, 1.0, 0.0, 0.0}, {-0.5, 0.0, 0.5, 0.0}, {1.0, -2.5, 2.0, -0.5}, {-0.5, 1.5, -1.5, 0.5}};
constexpr double kBSpline[4][4] = {{1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0, 0.0},
                                   {-3.0 / 6.0, 0.0, 3.0 / 6.0, 0.0},
                                   {3.0 / 6.0, -6.0 / 6.0, 3.0 / 6.0, 0.0},
                                   {-1.0 / 6.0, 3.0 / 6.0, -3.0 / 6.0, 1.0 / 6.0}};

// Polynomials as coefficient arrays of fixed room, with the magnitudes behind each
// coefficient (polynomialRoots' error bound).
struct Poly {
  double c[11] = {};
  double a[11] = {};
  int n = 0;
};

Poly product(const Poly& p, const Poly& q) {
  Poly r;
  r.n = p.n + q.n;
  for (int i = 0; i <= p.n; ++i)
    for (int j = 0; j <= q.n; ++j) {
      r.c[i + j] += p.c[i] * q.c[j];
      r.a[i + j] += p.a[i] * q.a[j];
    }
  return r;
}

Poly combine(const Poly& p, double sp, const Poly& q, double sq) {
  Poly r;
  r.n = std::max(p.n, q.n);
  for (int i = 0; i <= r.n; ++i) {
    r.c[i] = sp * (i <= p.n ? p.c[i] : 0.0) + sq * (i <= q.n ? q.c[i] : 0.0);
    r.a[i] = std::abs(sp) * (i <= p.n ? p.a[i] : 0.0) + std::abs(sq) * (i <= q.n ? q.a[i] : 0.0);
  }
  return r;
}

Poly derivative(const Poly& p) {
  Poly r;
  r.n = std::max(0, p.n - 1);
  for (int i = 1; i <= p.n; ++i) {
    r.c[i - 1] = i * p.c[i];
    r.a[i - 1] = i * p.a[i];
  }
  return r;
}

// Leading coefficients within the rounding of their terms count as 0.
void trim(Poly& p) {
  while (p.n > 0 && std::abs(p.c[p.n]) <= gamma(4 * p.n + 8) * p.a[p.n]) --p.n;
}

// The roots of p in (0, 1), ascending; none when p is constant.
int rootsIn01(Poly p, double* out) {
  trim(p);
  if (p.n == 0) return 0;
  PolynomialRoot r[kMaxPolynomialDegree];
  const int found = polynomialRoots(p.c, p.a, p.n, 0.0, 1.0, r);
  for (int i = 0; i < found; ++i) out[i] = r[i].x;
  return found;
}

// A cubic of one coordinate of the centre (or the radius) as a Poly.
Poly cubic(const double* k) {
  Poly p;
  p.n = 3;
  for (int i = 0; i < 4; ++i) {
    p.c[i] = k[i];
    p.a[i] = std::abs(k[i]);
  }
  return p;
}

}  // namespace

SphereSweep::SphereSweep(SweepSpline spline, const std::vector<SweepSphere>& spheres)
    : spline_(spline), spheres_(spheres) {
  const size_t n = spheres.size();
  if (n < static_cast<size_t>(minSpheres(spline)))
    throw std::invalid_argument("sphere-sweep: too few spheres for the spline");
  bool any = false;
  for (const SweepSphere& s : spheres) {
    if (!isFinite(s.center) || !std::isfinite(s.radius))
      throw std::invalid_argument("sphere-sweep: the spheres must be finite");
    if (s.radius < 0.0) throw std::invalid_argument("sphere-sweep: a radius is negative");
    any |= s.radius > 0.0;
  }
  if (!any) throw std::invalid_argument("sphere-sweep: every radius is 0");

  const bool linear = spline == SweepSpline::Linear;
  const size_t count = linear ? n - 1 : n - 3;
  const auto& M = spline == SweepSpline::Cubic ? kCatmullRom : kBSpline;
  for (size_t i = 0; i < count; ++i) {
    Segment s{};
    if (linear) {
      s.c[0] = spheres[i].center;
      s.c[1] = spheres[i + 1].center - spheres[i].center;
      s.r[0] = spheres[i].radius;
      s.r[1] = spheres[i + 1].radius - spheres[i].radius;
    } else {
      for (int k = 0; k < 4; ++k)
        for (int m = 0; m < 4; ++m) {
          s.c[k] += M[k][m] * spheres[i + m].center;
          s.r[k] += M[k][m] * spheres[i + m].radius;
        }
    }
    // The Bézier form's control points hold the curve, and its radii bound |r(u)|.
    const Vec3 b[4] = {s.c[0], s.c[0] + s.c[1] / 3.0, s.c[0] + (2.0 * s.c[1] + s.c[2]) / 3.0,
                       s.c[0] + s.c[1] + s.c[2] + s.c[3]};
    const double rb[4] = {s.r[0], s.r[0] + s.r[1] / 3.0, s.r[0] + (2.0 * s.r[1] + s.r[2]) / 3.0,
                          s.r[0] + s.r[1] + s.r[2] + s.r[3]};
    AABB hull;
    for (const Vec3& p : b) hull.expand(p);
    double rmax = 0.0;
    for (double r : rb) rmax = std::max(rmax, std::abs(r));
    s.bc = hull.center();
    s.br = 0.5 * glm::length(hull.extent()) + rmax;
    if (!linear) bounds_.expand(AABB(hull.lo - Vec3(rmax), hull.hi + Vec3(rmax)));
    segs_.push_back(s);
  }
  if (linear) {
    for (const SweepSphere& s : spheres)
      bounds_.expand(AABB(s.center - Vec3(s.radius), s.center + Vec3(s.radius)));
    for (size_t j = 0; j + 1 < n; ++j) {
      // The envelope of the balls c0 + u·Δc, r0 + u·Δr touches ball u on the circle at
      // (p − c(u))·a = −r(u)·k, k = Δr / L, of radius r(u)·√(1 − k²): a cone whose radius
      // grows by k / √(1 − k²) along a. No envelope when one ball holds the other (|k| >= 1).
      Frustum f;
      const Vec3 dc = spheres[j + 1].center - spheres[j].center;
      const double L = glm::length(dc), r0 = spheres[j].radius, r1 = spheres[j + 1].radius;
      const double k = L > 0.0 ? (r1 - r0) / L : 1.0;
      if (std::abs(k) < 1.0) {
        const double cosA = std::sqrt((1.0 - k) * (1.0 + k));
        f.present = true;
        f.c0 = spheres[j].center;
        f.a = dc / L;
        f.s0 = -r0 * k;
        f.s1 = L - r1 * k;
        f.R0 = r0 * cosA;
        f.g = k / cosA;
      }
      frusta_.push_back(f);
    }
  }
  scale_ = std::max({glm::length(bounds_.extent()), glm::length(bounds_.center()), 1e-300});
}

Vec3 SphereSweep::centerAt(size_t seg, double u) const {
  const Segment& s = segs_[seg];
  return ((s.c[3] * u + s.c[2]) * u + s.c[1]) * u + s.c[0];
}

double SphereSweep::radiusAt(size_t seg, double u) const {
  const Segment& s = segs_[seg];
  return ((s.r[3] * u + s.r[2]) * u + s.r[1]) * u + s.r[0];
}

bool SphereSweep::insideFrustum(const Frustum& f, const Vec3& p) const {
  if (!f.present) return false;
  const Vec3 w = p - f.c0;
  const double s = glm::dot(w, f.a);
  if (!(s >= f.s0 && s <= f.s1)) return false;
  const double R = f.R0 + (s - f.s0) * f.g;
  return glm::dot(w, w) - s * s <= R * R;
}

// Inside when some ball of the segment holds p: the least of F(u) = |p − c(u)|² − r(u)²
// over [0, 1] (at an end or a root of F') is at most 0.
bool SphereSweep::insideSegment(const Segment& s, const Vec3& p) const {
  Poly F;
  F.n = 0;
  for (int axis = 0; axis < 3; ++axis) {
    double k[4] = {s.c[0][axis] - p[axis], s.c[1][axis], s.c[2][axis], s.c[3][axis]};
    const Poly q = cubic(k);
    F = combine(F, 1.0, product(q, q), 1.0);
  }
  const Poly r = cubic(s.r);
  F = combine(F, 1.0, product(r, r), -1.0);
  double u[6];
  const int nu = rootsIn01(derivative(F), u);
  auto value = [&](double x) {
    const Vec3 c = ((s.c[3] * x + s.c[2]) * x + s.c[1]) * x + s.c[0];
    const double rr = ((s.r[3] * x + s.r[2]) * x + s.r[1]) * x + s.r[0];
    const Vec3 w = p - c;
    return glm::dot(w, w) - rr * rr;
  };
  if (value(0.0) <= 0.0 || value(1.0) <= 0.0) return true;
  for (int i = 0; i < nu; ++i)
    if (value(u[i]) <= 0.0) return true;
  return false;
}

bool SphereSweep::inside(const Vec3& p) const {
  if (!bounds_.contains(p)) return false;
  if (spline_ == SweepSpline::Linear) {
    for (const SweepSphere& s : spheres_) {
      const Vec3 w = p - s.center;
      if (glm::dot(w, w) <= s.radius * s.radius) return true;
    }
    for (const Frustum& f : frusta_)
      if (insideFrustum(f, p)) return true;
    return false;
  }
  for (const Segment& s : segs_)
    if (insideSegment(s, p)) return true;
  return false;
}

void SphereSweep::linearSpans(const Vec3& o, const Vec3& d, std::vector<Span>& out) const {
  const uint32_t n = static_cast<uint32_t>(spheres_.size());
  for (uint32_t i = 0; i < n; ++i) {
    const SweepSphere& s = spheres_[i];
    Span sp;
    if (s.radius > 0.0 &&
        solveDistanceQuadratic(o - s.center, d, s.radius * s.radius, sp.tIn, sp.tOut)) {
      sp.partIn = sp.partOut = i;
      out.push_back(sp);
    }
  }
  for (uint32_t j = 0; j + 1 < n; ++j) {
    const Frustum& f = frusta_[j];
    if (!f.present) continue;
    // The slab between the tangent circles' planes; its ends lie within the spheres, so
    // a span ending there is named after the sphere (a surface only by rounding).
    const Vec3 w = o - f.c0;
    const double sw = glm::dot(w, f.a), sd = glm::dot(d, f.a);
    double lo = -kInf, hi = kInf;
    uint32_t partLo = n + j, partHi = n + j;
    if (sd != 0.0) {
      const double ta = (f.s0 - sw) / sd, tb = (f.s1 - sw) / sd;
      lo = std::min(ta, tb);
      hi = std::max(ta, tb);
      partLo = sd > 0.0 ? j : j + 1;
      partHi = sd > 0.0 ? j + 1 : j;
    } else if (!(sw >= f.s0 && sw <= f.s1)) {
      continue;
    }
    // |w⊥ + t·d⊥|² = (A + B·t)², the cone's radius along the line.
    const Vec3 wp = w - sw * f.a, dp = d - sd * f.a;
    const double A = f.R0 + (sw - f.s0) * f.g, B = sd * f.g;
    const double qa = glm::dot(dp, dp) - B * B, qh = glm::dot(wp, dp) - A * B,
                 qc = glm::dot(wp, wp) - A * A;
    double t0, t1;
    // Where the quadratic is at most 0: between its roots (qa > 0), outside them (qa < 0).
    Span pieces[2];
    int np = 0;
    if (qa == 0.0 && qh == 0.0) {
      if (qc <= 0.0) pieces[np++] = {lo, hi, partLo, partHi};
    } else if (!solveQuadratic(qa, qh, qc, qh * qh - qa * qc, t0, t1)) {
      if (qa < 0.0) pieces[np++] = {lo, hi, partLo, partHi};
    } else if (qa > 0.0) {
      pieces[np++] = {t0, t1, n + j, n + j};
    } else if (qa < 0.0) {
      pieces[np++] = {-kInf, t0, n + j, n + j};
      pieces[np++] = {t1, kInf, n + j, n + j};
    } else {
      // Linear: 2·qh·t + qc <= 0 on one side of its root.
      pieces[np++] = qh > 0.0 ? Span{-kInf, t0, n + j, n + j} : Span{t0, kInf, n + j, n + j};
    }
    for (int k = 0; k < np; ++k) {
      Span sp = pieces[k];
      if (sp.tIn < lo) {
        sp.tIn = lo;
        sp.partIn = partLo;
      }
      if (sp.tOut > hi) {
        sp.tOut = hi;
        sp.partOut = partHi;
      }
      if (sp.tIn <= sp.tOut) out.push_back(sp);
    }
  }
}

void SphereSweep::splineSpans(size_t seg, const Vec3& o, const Vec3& d,
                              std::vector<Span>& out) const {
  const Segment& s = segs_[seg];
  // Quick miss: the line passes the segment's bounding sphere.
  const Vec3 wb = s.bc - o;
  const Vec3 perp = wb - glm::dot(wb, d) * d;
  if (glm::dot(perp, perp) > s.br * s.br * (1.0 + 1e-9)) return;
  // D(u) = r(u)² − |q⊥(u)|², q = c − o, ⊥ across d; m(u) = d·q(u).
  Poly D = product(cubic(s.r), cubic(s.r));
  double mk[4];
  for (int k = 0; k < 4; ++k) {
    const Vec3 q = k == 0 ? s.c[0] - o : s.c[k];
    mk[k] = glm::dot(q, d);
  }
  Vec3 qp[4];
  for (int k = 0; k < 4; ++k) qp[k] = (k == 0 ? s.c[0] - o : s.c[k]) - mk[k] * d;
  for (int axis = 0; axis < 3; ++axis) {
    const double k[4] = {qp[0][axis], qp[1][axis], qp[2][axis], qp[3][axis]};
    D = combine(D, 1.0, product(cubic(k), cubic(k)), -1.0);
  }
  auto ball = [&](double u, Vec3& c, double& r2) {
    c = centerAt(seg, u);
    const double r = radiusAt(seg, u);
    r2 = r * r;
  };
  auto Dat = [&](double u) {
    Vec3 c;
    double r2;
    ball(u, c, r2);
    const Vec3 w = c - o;
    const Vec3 wp = w - glm::dot(w, d) * d;
    return r2 - glm::dot(wp, wp);
  };
  // The intervals of u where D >= 0, between D's roots.
  double split[8];
  int ns = 0;
  split[ns++] = 0.0;
  ns += rootsIn01(D, split + 1);
  split[ns++] = 1.0;
  // The candidates for the extremes of t0 and t1: roots of P = 4·D·m'² − D'².
  const Poly m1 = derivative(cubic(mk)), D1 = derivative(D);
  const Poly P = combine(product(D, product(m1, m1)), 4.0, product(D1, D1), -1.0);
  double crit[10];
  const int nc = rootsIn01(P, crit);
  for (int i = 0; i + 1 < ns; ++i) {
    const double a = split[i], b = split[i + 1];
    if (!(a < b)) continue;
    if (!(Dat(0.5 * (a + b)) >= 0.0)) continue;
    Span sp;
    auto consider = [&](double u) {
      Vec3 c;
      double r2, t0, t1;
      ball(u, c, r2);
      if (!solveDistanceQuadratic(o - c, d, r2, t0, t1)) t0 = t1 = glm::dot(c - o, d);
      if (t0 < sp.tIn) {
        sp.tIn = t0;
        sp.b1In = u;
      }
      if (t1 > sp.tOut) {
        sp.tOut = t1;
        sp.b1Out = u;
      }
    };
    consider(a);
    consider(b);
    for (int k = 0; k < nc; ++k)
      if (crit[k] > a && crit[k] < b) consider(crit[k]);
    sp.partIn = sp.partOut = static_cast<uint32_t>(seg);
    out.push_back(sp);
  }
}

void SphereSweep::lineSpans(const Ray& ray, std::vector<Span>& out) const {
  out.clear();
  CentredLine line;
  if (!centredLine(ray, bounds_, line)) return;
  const Vec3 o = line.o, d = line.d;
  const double s0 = line.s0, len = line.len;
  if (spline_ == SweepSpline::Linear) {
    linearSpans(o, d, out);
  } else {
    for (size_t i = 0; i < segs_.size(); ++i) splineSpans(i, o, d, out);
  }
  std::sort(out.begin(), out.end(), [](const Span& a, const Span& b) { return a.tIn < b.tIn; });
  // Join the parts' spans where they overlap or leave a gap within rounding.
  const double close = 64.0 * kMachineEps * scale_;
  size_t w = 0;
  for (size_t k = 0; k < out.size(); ++k) {
    if (w > 0 && out[k].tIn <= out[w - 1].tOut + close) {
      Span& last = out[w - 1];
      if (out[k].tOut > last.tOut) {
        last.tOut = out[k].tOut;
        last.partOut = out[k].partOut;
        last.b1Out = out[k].b1Out;
      }
      continue;
    }
    out[w++] = out[k];
  }
  out.resize(w);
  for (Span& sp : out) {
    sp.tIn = (sp.tIn + s0) / len;
    sp.tOut = (sp.tOut + s0) / len;
  }
}

namespace {
thread_local std::vector<Span> scratch;
}  // namespace

bool SphereSweep::intersect(const Ray& ray, Hit& hit) const {
  lineSpans(ray, scratch);
  for (const Span& sp : scratch) {
    if (intersectSpan(sp, ray, this, hit)) return true;
    if (sp.tIn >= ray.tmax) break;
  }
  return false;
}

void SphereSweep::crossings(const Ray& ray, CrossingList& out) const {
  lineSpans(ray, scratch);
  bool in = false;
  for (const Span& sp : scratch) {
    if (sp.tIn < ray.tmin && ray.tmin <= sp.tOut) in = true;
    const struct {
      double t;
      uint32_t part;
      double b1;
      bool entering;
    } ends[2] = {{sp.tIn, sp.partIn, sp.b1In, true}, {sp.tOut, sp.partOut, sp.b1Out, false}};
    for (const auto& e : ends) {
      if (e.t < ray.tmin || e.t > ray.tmax) continue;
      Hit h;
      h.t = e.t;
      h.shape = this;
      h.part = e.part;
      h.b1 = e.b1;
      out.items.push_back({h, e.entering});
    }
  }
  out.startsInside = in;
}

// The u of the ball of segment `seg` that touches the swept surface at p, from a nearby u:
// Newton steps on the slope of f(u) = |p − c(u)| − r(u), whose least value is p's gauge
// distance from the surface. The u found with a hit comes from a root of a tenth-degree
// polynomial that may be ill-conditioned (off by 1e-6), and the ball at a u that far from
// the contact lies inside the surface by 1e-13 there: a ray leaving the hit found the
// surface again.
double SphereSweep::contactParameter(size_t seg, const Vec3& p, double u) const {
  const Segment& s = segs_[seg];
  for (int it = 0; it < 4; ++it) {
    const Vec3 c = ((s.c[3] * u + s.c[2]) * u + s.c[1]) * u + s.c[0];
    const Vec3 c1 = (3.0 * s.c[3] * u + 2.0 * s.c[2]) * u + s.c[1];
    const Vec3 c2 = 6.0 * s.c[3] * u + 2.0 * s.c[2];
    const double r2 = 6.0 * s.r[3] * u + 2.0 * s.r[2];
    const double r1 = (3.0 * s.r[3] * u + 2.0 * s.r[2]) * u + s.r[1];
    const Vec3 q = p - c;
    const double len = glm::length(q);
    if (!(len > 0.0)) break;
    const double qc1 = glm::dot(q, c1);
    const double slope = -qc1 / len - r1;
    const double curvature =
        (glm::dot(c1, c1) - glm::dot(q, c2)) / len - qc1 * qc1 / (len * len * len) - r2;
    if (!(curvature > 0.0)) break;  // not near a least value: keep the u found
    const double next = std::clamp(u - slope / curvature, 0.0, 1.0);
    if (next == u) break;
    u = next;
  }
  return u;
}

SurfaceInfo SphereSweep::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo si;
  si.p = ray.at(hit.t);
  Vec3 n(0.0);
  const size_t ns = spheres_.size();
  if (spline_ != SweepSpline::Linear) {
    // The point moved onto the ball that touches the surface there (as the torus does onto
    // its tube), so that it lies on the surface to the rounding of that ball.
    const double u = contactParameter(hit.part, si.p, hit.b1);
    const Vec3 c = centerAt(hit.part, u);
    const double r = radiusAt(hit.part, u);
    n = si.p - c;
    const double len = glm::length(n);
    if (len > 0.0) {
      si.p = c + (r / len) * n;
      si.pError = gamma(32) * (glm::abs(c) + Vec3(r) + glm::abs(si.p) + Vec3(scale_));
    }
  } else if (hit.part < ns) {
    n = si.p - spheres_[hit.part].center;
  } else {
    // The gradient of ρ − R(s) on the frustum: outward across the axis, tilted by the slope.
    const Frustum& f = frusta_[hit.part - ns];
    const Vec3 w = si.p - f.c0;
    const Vec3 radial = w - glm::dot(w, f.a) * f.a;
    const double l = glm::length(radial);
    if (l > 0.0) n = radial / l - f.g * f.a;
  }
  const double l = glm::length(n);
  n = l > 0.0 ? n / l : Vec3(0.0, 1.0, 0.0);
  si.ng = n;
  si.ns = n;
  if (si.pError == Vec3(0.0))
    si.pError =
        gamma(32) * (glm::abs(ray.o) + glm::abs(hit.t * ray.d) + glm::abs(si.p) + Vec3(scale_));
  return si;
}

}  // namespace lucent
