#include "prism.h"

#include "polynomial.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucent {

namespace {

bool finite2(const Vec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }

// The roots in (0, 1) of c0 + c1·s + c2·s² (the derivative of a cubic), ascending.
int unitQuadraticRoots(double c0, double c1, double c2, double* r) {
  int n = 0;
  double tmp[2];
  if (c2 == 0.0) {
    if (c1 != 0.0) tmp[n++] = -c0 / c1;
  } else {
    const double disc = c1 * c1 - 4.0 * c2 * c0;
    if (disc >= 0.0) {
      const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
      tmp[n++] = q / c2;
      if (q != 0.0) tmp[n++] = c0 / q;
    }
  }
  int m = 0;
  for (int i = 0; i < n; ++i)
    if (tmp[i] > 0.0 && tmp[i] < 1.0) r[m++] = tmp[i];
  if (m == 2 && r[0] > r[1]) std::swap(r[0], r[1]);
  return m;
}

// The root of a polynomial monotone on [lo, hi] whose sign at lo is `loPositive` and at hi
// the other: bisection with Newton steps kept inside the bracket.
double monotoneRoot(const double* c, int n, double lo, double hi, bool loPositive) {
  double x = 0.5 * (lo + hi);
  for (int it = 0; it < 200 && hi - lo > 0.0; ++it) {
    const double fx = evalPolynomial(c, n, x);
    if (fx == 0.0) return x;
    if ((fx > 0.0) == loPositive) lo = x;
    else hi = x;
    const double d = evalPolynomialDerivative(c, n, x);
    double next = d != 0.0 ? x - fx / d : lo - 1.0;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == x || next == lo || next == hi) break;
    x = next;
  }
  return x;
}

// a·(c.x − q.x) + b·(c.z − q.z) to within a few ulps of its own value (error-free
// differences and products, Ogita, Rump & Oishi 2005, "Accurate sum and dot product"): a
// vertex's side of the ray's line is then right unless it lies within rounding of it, so a
// ray along a side face keeps to the right side of both its ends.
double sideOf(double a, double b, const Vec2& q, const Vec2& c) {
  auto twoDiff = [](double x, double y, double& err) {
    const double s = x - y, bb = s - x;
    err = (x - (s - bb)) - (y + bb);
    return s;
  };
  double ex, ez, es;
  const double dx = twoDiff(c.x, q.x, ex), dz = twoDiff(c.y, q.y, ez);
  const double p1 = a * dx, e1 = std::fma(a, dx, -p1);
  const double p2 = b * dz, e2 = std::fma(b, dz, -p2);
  const double sum = p1 + p2, bv = sum - p1;
  es = (p1 - (sum - bv)) + (p2 - bv);
  return sum + (es + e1 + e2 + a * ex + b * ez);
}

}  // namespace

Prism::Prism(const std::vector<PrismContour>& contours, double height1, double height2, Sweep sweep,
             bool open)
    : h1_(std::min(height1, height2)), h2_(std::max(height1, height2)), sweep_(sweep), open_(open) {
  if (!std::isfinite(h1_) || !std::isfinite(h2_) || !(h1_ < h2_))
    throw std::invalid_argument("prism: the heights must be finite and differ");
  outlineLo_ = Vec2(kInf);
  outlineHi_ = Vec2(-kInf);
  for (const PrismContour& contour : contours) {
    if (contour.empty()) continue;
    for (size_t k = 0; k < contour.size(); ++k) {
      const PrismSegment& sg = contour[k];
      if (sg.degree < 1 || sg.degree > 3)
        throw std::invalid_argument("prism: a segment's degree is 1, 2 or 3");
      const PrismSegment& next = contour[(k + 1) % contour.size()];
      if (sg.end() != next.start()) throw std::invalid_argument("prism: a contour is not closed");
      Piece pc{};
      pc.degree = sg.degree;
      pc.p0 = sg.p[0];
      pc.p1 = sg.end();
      pc.lo = Vec2(kInf);
      pc.hi = Vec2(-kInf);
      for (int i = 0; i <= sg.degree; ++i) {
        if (!finite2(sg.p[i])) throw std::invalid_argument("prism: a point is not finite");
        pc.lo = glm::min(pc.lo, sg.p[i]);
        pc.hi = glm::max(pc.hi, sg.p[i]);
      }
      // Bézier to power basis, x and z (p[].y) alike.
      const Vec2* p = sg.p;
      Vec2 c[4];
      c[0] = p[0];
      if (sg.degree == 1) {
        c[1] = p[1] - p[0];
      } else if (sg.degree == 2) {
        c[1] = 2.0 * (p[1] - p[0]);
        c[2] = p[0] - 2.0 * p[1] + p[2];
      } else {
        c[1] = 3.0 * (p[1] - p[0]);
        c[2] = 3.0 * (p[0] - 2.0 * p[1] + p[2]);
        c[3] = p[3] - 3.0 * p[2] + 3.0 * p[1] - p[0];
      }
      for (int i = 0; i <= 3; ++i) {
        pc.x[i] = i <= sg.degree ? c[i].x : 0.0;
        pc.z[i] = i <= sg.degree ? c[i].y : 0.0;
      }
      outlineLo_ = glm::min(outlineLo_, pc.lo);
      outlineHi_ = glm::max(outlineHi_, pc.hi);
      const uint32_t index = static_cast<uint32_t>(pieces_.size());
      pieces_.push_back(pc);
      // z-monotone parts: split at the roots of z'(s).
      double cuts[4] = {0.0};
      int nc = 1;
      if (pc.degree >= 2) nc += unitQuadraticRoots(pc.z[1], 2.0 * pc.z[2], 3.0 * pc.z[3], cuts + 1);
      cuts[nc++] = 1.0;
      Vec2 prev = pc.p0;
      for (int i = 0; i + 1 < nc; ++i) {
        Monotone m{};
        m.piece = index;
        m.s0 = cuts[i];
        m.s1 = cuts[i + 1];
        m.a = prev;
        m.b = i + 2 == nc ? pc.p1 : curve(pc, cuts[i + 1]);
        prev = m.b;
        // x over the part: its ends and x's own extrema inside it bound it.
        m.xlo = std::min(m.a.x, m.b.x);
        m.xhi = std::max(m.a.x, m.b.x);
        double xr[2];
        const int nx =
            pc.degree >= 2 ? unitQuadraticRoots(pc.x[1], 2.0 * pc.x[2], 3.0 * pc.x[3], xr) : 0;
        for (int j = 0; j < nx; ++j)
          if (xr[j] > m.s0 && xr[j] < m.s1) {
            const double xv = curve(pc, xr[j]).x;
            m.xlo = std::min(m.xlo, xv);
            m.xhi = std::max(m.xhi, xv);
          }
        monotone_.push_back(m);
      }
    }
  }
  if (pieces_.empty()) throw std::invalid_argument("prism: the outline is empty");
  if (sweep_ == Sweep::Linear) {
    bounds_ = AABB(Vec3(outlineLo_.x, h1_, outlineLo_.y), Vec3(outlineHi_.x, h2_, outlineHi_.y));
  } else {
    bounds_ = AABB();
    for (double h : {h1_, h2_})
      for (double x : {outlineLo_.x, outlineHi_.x})
        for (double z : {outlineLo_.y, outlineHi_.y}) bounds_.expand(Vec3(h * x, h, h * z));
  }
}

Vec2 Prism::curve(const Piece& pc, double s) const {
  return {evalPolynomial(pc.x, pc.degree, s), evalPolynomial(pc.z, pc.degree, s)};
}

Vec2 Prism::tangent(const Piece& pc, double s) const {
  Vec2 t(evalPolynomialDerivative(pc.x, pc.degree, s),
         evalPolynomialDerivative(pc.z, pc.degree, s));
  if (t.x == 0.0 && t.y == 0.0) t = pc.p1 - pc.p0;  // a cusp: the chord's direction
  return t;
}

bool Prism::insideOutline(double u, double v) const {
  if (!(u >= outlineLo_.x && u <= outlineHi_.x && v >= outlineLo_.y && v <= outlineHi_.y))
    return false;
  bool in = false;
  for (const Monotone& m : monotone_) {
    const bool up = m.a.y < m.b.y;
    const double zlo = up ? m.a.y : m.b.y, zhi = up ? m.b.y : m.a.y;
    if (!(v >= zlo && v < zhi) || u >= m.xhi) continue;  // half-open in z: a vertex counts once
    if (u < m.xlo) {
      in = !in;
      continue;
    }
    const Piece& pc = pieces_[m.piece];
    double x;
    if (pc.degree == 1) {
      x = m.a.x + (v - m.a.y) * (m.b.x - m.a.x) / (m.b.y - m.a.y);
    } else {
      double c[4] = {pc.z[0] - v, pc.z[1], pc.z[2], pc.z[3]};
      // z(s) - v is monotone on the part, negative at the lower end.
      const double s = monotoneRoot(c, pc.degree, m.s0, m.s1, !up);
      x = evalPolynomial(pc.x, pc.degree, s);
    }
    if (x > u) in = !in;
  }
  return in;
}

bool Prism::inside(const Vec3& p) const {
  if (open_) return false;  // a surface has no inside (POV-Ray's open prism keeps one)
  if (!(p.y >= h1_ && p.y <= h2_)) return false;
  if (sweep_ == Sweep::Linear) return insideOutline(p.x, p.z);
  if (p.y == 0.0) return false;  // the apex
  return insideOutline(p.x / p.y, p.z / p.y);
}

// Where the ray meets the sweep's line over the outline point c (on L).
double Prism::eventT(const Ray& ray, const Vec2& c) const {
  const Vec3& o = ray.o;
  const Vec3& d = ray.d;
  if (sweep_ == Sweep::Linear)
    return ((c.x - o.x) * d.x + (c.y - o.z) * d.z) / (d.x * d.x + d.z * d.z);
  // o + t·d = y·(c.x, 1, c.y): from x or z, whichever is better conditioned.
  const double dx = d.x - d.y * c.x, dz = d.z - d.y * c.y;
  if (std::abs(dx) >= std::abs(dz)) return (o.y * c.x - o.x) / dx;
  return (o.y * c.y - o.z) / dz;
}

void Prism::addPieceCrossings(const Piece& pc, uint32_t index, const Ray& ray, double a, double b,
                              const Vec2& q, std::vector<Event>& ev) const {
  auto g = [&](const Vec2& c) { return a * (c.x - q.x) + b * (c.y - q.y); };
  const double g0 = sideOf(a, b, q, pc.p0), g1 = sideOf(a, b, q, pc.p1);
  const bool pos0 = g0 >= 0.0, pos1 = g1 >= 0.0;
  if (pos0 == pos1) {
    // Both ends on one side: nothing crosses if the control box is strictly there too.
    const double c00 = g(pc.lo), c11 = g(pc.hi), c01 = g({pc.lo.x, pc.hi.y}),
                 c10 = g({pc.hi.x, pc.lo.y});
    if (pc.degree == 1) return;
    if (pos0 && c00 > 0.0 && c11 > 0.0 && c01 > 0.0 && c10 > 0.0) return;
    if (!pos0 && c00 < 0.0 && c11 < 0.0 && c01 < 0.0 && c10 < 0.0) return;
  }
  if (pc.degree == 1) {
    const double s = g0 / (g0 - g1);
    const Vec2 c = pc.p0 + s * (pc.p1 - pc.p0);
    ev.push_back({eventT(ray, c), index, s});
    return;
  }
  // f(s) = g(curve(s)), its constant term g at the start point.
  double f[4] = {g0, a * pc.x[1] + b * pc.z[1], a * pc.x[2] + b * pc.z[2],
                 a * pc.x[3] + b * pc.z[3]};
  int deg = pc.degree;
  double cuts[4] = {0.0};
  int nc = 1 + unitQuadraticRoots(f[1], 2.0 * f[2], 3.0 * f[3], cuts + 1);
  cuts[nc++] = 1.0;
  bool prevPos = pos0;
  for (int i = 1; i < nc; ++i) {
    const bool pos = i + 1 == nc ? pos1 : evalPolynomial(f, deg, cuts[i]) >= 0.0;
    if (pos != prevPos) {
      const double s = monotoneRoot(f, deg, cuts[i - 1], cuts[i], prevPos);
      ev.push_back({eventT(ray, curve(pc, s)), index, s});
    }
    prevPos = pos;
  }
}

void Prism::lineCrossings(const Ray& ray, double a, double b, const Vec2& q,
                          std::vector<Event>& ev) const {
  for (uint32_t i = 0; i < pieces_.size(); ++i) addPieceCrossings(pieces_[i], i, ray, a, b, q, ev);
}

void Prism::spans(const Ray& ray, std::vector<Span>& out) const {
  out.clear();
  const Vec3& o = ray.o;
  const Vec3& d = ray.d;
  // The slab height1 <= y <= height2 along the ray, and its caps.
  double ta = -kInf, tb = kInf;
  uint32_t capA = kLowCap, capB = kHighCap;
  if (d.y != 0.0) {
    const double t1 = (h1_ - o.y) / d.y, t2 = (h2_ - o.y) / d.y;
    if (d.y > 0.0) {
      ta = t1;
      tb = t2;
    } else {
      ta = t2;
      tb = t1;
      capA = kHighCap;
      capB = kLowCap;
    }
  } else if (!(o.y >= h1_ && o.y <= h2_)) {
    return;
  }
  // Quick rejection by the bounds, over the whole line.
  {
    Ray whole(o, d, -kInf, kInf);
    const Vec3 inv(1.0 / d.x, 1.0 / d.y, 1.0 / d.z);
    const Interval box = bounds_.slab(whole, inv);
    if (box.empty() || box.hi < ray.tmin || box.lo > ray.tmax) return;
  }

  // The line L over the outline, and where the toggling starts.
  double a, b;
  Vec2 q;
  bool conicApex = false;  // order along L starts just after the apex
  double tApex = 0.0;
  if (sweep_ == Sweep::Linear) {
    a = d.z;
    b = -d.x;
    q = Vec2(o.x, o.z);
  } else {
    const Vec3 n = glm::cross(o, d);
    a = n.x;
    b = n.z;
    const double ab = a * a + b * b;
    if (ab == 0.0) {
      if (n.y != 0.0 || d.y == 0.0) return;  // in the apex plane y = 0, or no direction
      // Through the apex: the whole ray projects to one outline point.
      if (!insideOutline(d.x / d.y, d.z / d.y)) return;
      if (!open_) out.push_back({ta, tb, capA, capB, 0.0, 0.0});
      return;
    }
    q = Vec2(-n.y * a / ab, -n.y * b / ab);
    if (d.y != 0.0) {
      conicApex = true;
      tApex = -o.y / d.y;
    } else if (o.y == 0.0) {
      return;
    }
  }
  if (a == 0.0 && b == 0.0) {  // a linear sweep's vertical ray
    if (!insideOutline(o.x, o.z)) return;
    if (!open_) out.push_back({ta, tb, capA, capB, 0.0, 0.0});
    return;
  }

  thread_local std::vector<Event> ev;
  ev.clear();
  lineCrossings(ray, a, b, q, ev);
  if (open_) {  // the side crossings within the slab, as points
    for (const Event& e : ev)
      if (e.t >= ta && e.t <= tb) out.push_back({e.t, e.t, e.piece, e.piece, e.s, e.s});
    std::sort(out.begin(), out.end(), [](const Span& x, const Span& y) { return x.t0 < y.t0; });
    return;
  }
  // Order along L: by t; for a conic sweep L is run through from the apex (t just above
  // tApex) to t = +inf, then from -inf up to the apex.
  auto key = [&](const Event& e) { return conicApex && e.t < tApex ? 1 : 0; };
  std::sort(ev.begin(), ev.end(), [&](const Event& x, const Event& y) {
    const int kx = key(x), ky = key(y);
    return kx != ky ? kx < ky : x.t < y.t;
  });
  auto clip = [&](double t0, uint32_t p0, double s0, double t1, uint32_t p1, double s1) {
    if (t0 < ta) {
      t0 = ta;
      p0 = capA;
      s0 = 0.0;
    }
    if (t1 > tb) {
      t1 = tb;
      p1 = capB;
      s1 = 0.0;
    }
    if (t0 <= t1) out.push_back({t0, t1, p0 | (p0 < kLowCap ? kEntering : 0u), p1, s0, s1});
  };
  for (size_t i = 0; i + 1 < ev.size(); i += 2) {
    const Event& e0 = ev[i];
    const Event& e1 = ev[i + 1];
    if (key(e0) == key(e1)) {
      clip(e0.t, e0.piece, e0.s, e1.t, e1.piece, e1.s);
    } else {  // through t = ±inf
      clip(e0.t, e0.piece, e0.s, kInf, 0, 0.0);
      clip(-kInf, 0, 0.0, e1.t, e1.piece, e1.s);
    }
  }
  if (conicApex)
    std::sort(out.begin(), out.end(), [](const Span& x, const Span& y) { return x.t0 < y.t0; });
}

bool Prism::intersect(const Ray& ray, Hit& hit) const {
  thread_local std::vector<Span> sp;
  spans(ray, sp);
  for (const Span& s : sp) {
    for (int end = 0; end < 2; ++end) {
      const double t = end ? s.t1 : s.t0;
      if (t > ray.tmin && t < ray.tmax) {
        hit.t = t;
        hit.shape = this;
        hit.part = end ? s.part1 : s.part0;
        hit.b1 = end ? s.s1 : s.s0;
        return true;
      }
      if (open_) break;
    }
  }
  return false;
}

void Prism::crossings(const Ray& ray, CrossingList& out) const {
  thread_local std::vector<Span> sp;
  spans(ray, sp);
  auto hitAt = [this](double t, uint32_t part, double s) {
    Hit h;
    h.t = t;
    h.shape = this;
    h.part = part;
    h.b1 = s;
    return h;
  };
  for (const Span& s : sp) {
    if (open_) {
      if (s.t0 >= ray.tmin && s.t0 <= ray.tmax)
        out.items.push_back({hitAt(s.t0, s.part0, s.s0), true});
      continue;
    }
    if (s.t0 < ray.tmin && ray.tmin <= s.t1) out.startsInside = true;
    if (s.t0 >= ray.tmin && s.t0 <= ray.tmax)
      out.items.push_back({hitAt(s.t0, s.part0, s.s0), true});
    if (s.t1 >= ray.tmin && s.t1 <= ray.tmax)
      out.items.push_back({hitAt(s.t1, s.part1, s.s1), false});
  }
}

SurfaceInfo Prism::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo si;
  si.p = ray.at(hit.t);
  Vec3 n;
  if (hit.part == kLowCap) {
    n = Vec3(0.0, -1.0, 0.0);
  } else if (hit.part == kHighCap) {
    n = Vec3(0.0, 1.0, 0.0);
  } else {
    const Piece& pc = pieces_[hit.part & ~kEntering];
    const Vec2 tg = tangent(pc, hit.b1);
    if (sweep_ == Sweep::Linear) {
      n = Vec3(tg.y, 0.0, -tg.x);
    } else {
      const Vec2 c = curve(pc, hit.b1);
      n = Vec3(tg.y, -(c.x * tg.y - c.y * tg.x), -tg.x);
    }
    n = glm::normalize(n);
    if (!open_) {  // outward: against the ray where it enters, along it where it leaves
      const bool entering = (hit.part & kEntering) != 0;
      if ((glm::dot(n, ray.d) < 0.0) != entering) n = -n;
    }
  }
  // The point is off the surface by the rounding of t·d and of the outline's numbers.
  const double scale =
      std::max({std::abs(outlineLo_.x), std::abs(outlineHi_.x), std::abs(outlineLo_.y),
                std::abs(outlineHi_.y), std::abs(h1_), std::abs(h2_)});
  si.pError = gamma(32) * (glm::abs(ray.o) + glm::abs(hit.t * ray.d) +
                           Vec3(scale * (sweep_ == Sweep::Conic ? scale : 1.0)));
  si.ng = n;
  si.ns = n;
  return si;
}

}  // namespace lucent
