#include "lathe.h"
#include "pov_uv.h"

#include "polynomial.h"
#include "quadratic.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucent {

namespace {

constexpr uint32_t kEnteringBit = 0x80000000u;
// How far past [0, 1] a root may be found and still belong to its piece (the joints are
// merged afterwards).
constexpr double kSlack = 1e-9;
// Below this |d.y|/|d| the ray counts as horizontal (the roots in s come in close pairs).
constexpr double kFlat = 1e-6;

// The extent of the cubic ((a·s + b)·s + c)·s + d over s in [0, 1].
void extent(double a, double b, double c, double d, double& lo, double& hi) {
  auto f = [&](double s) { return ((a * s + b) * s + c) * s + d; };
  lo = std::min(f(0.0), f(1.0));
  hi = std::max(f(0.0), f(1.0));
  const double q[3] = {c, 2.0 * b, 3.0 * a};  // the derivative
  const double qa[3] = {std::abs(c), std::abs(2.0 * b), std::abs(3.0 * a)};
  int n = q[2] != 0.0 ? 2 : q[1] != 0.0 ? 1 : 0;
  if (n == 0) return;
  PolynomialRoot r[2];
  const int found = polynomialRoots(q, qa, n, 0.0, 1.0, r);
  for (int i = 0; i < found; ++i) {
    lo = std::min(lo, f(r[i].x));
    hi = std::max(hi, f(r[i].x));
  }
}

// r = f·g for coefficient arrays of degrees df and dg.
void multiply(const double* f, int df, const double* g, int dg, double* r) {
  for (int m = 0; m <= df + dg; ++m) r[m] = 0.0;
  for (int i = 0; i <= df; ++i)
    for (int j = 0; j <= dg; ++j) r[i + j] += f[i] * g[j];
}

}  // namespace

int Lathe::minPoints(LatheSpline spline) {
  switch (spline) {
    case LatheSpline::Linear:
      return 2;
    case LatheSpline::Quadratic:
      return 3;
    case LatheSpline::Cubic:
      return 4;
    case LatheSpline::Bezier:
      return 4;
  }
  return 2;
}

Lathe::Lathe(LatheSpline spline, const std::vector<Vec2>& points, bool open) : open_(open) {
  const int n = static_cast<int>(points.size());
  if (n < minPoints(spline)) throw std::invalid_argument("lathe: too few points for the spline");
  if (spline == LatheSpline::Bezier && n % 4 != 0)
    throw std::invalid_argument("lathe: a bezier lathe needs a multiple of 4 points");
  for (const Vec2& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      throw std::invalid_argument("lathe: points must be finite");
    if (p.x < 0.0) throw std::invalid_argument("lathe: x must be >= 0");
  }
  // Each piece's polynomial, and its first and last point (for the joints).
  std::vector<std::pair<Vec2, Vec2>> ends;
  // The ends from the points themselves: a + b + c + d need not round to the last one.
  auto add = [&](Vec2 a, Vec2 b, Vec2 c, Vec2 d, Vec2 first, Vec2 last) {
    Piece p{a, b, c, d, 0, 0.0, 0.0, 0.0, true, segments_++};
    p.degree = (a.x != 0.0 || a.y != 0.0)   ? 3
               : (b.x != 0.0 || b.y != 0.0) ? 2
               : (c.x != 0.0 || c.y != 0.0) ? 1
                                            : 0;
    if (p.degree == 0) return;  // a repeated point: no surface
    if (a.x == 0.0 && b.x == 0.0 && c.x == 0.0 && d.x == 0.0) return;  // along the axis: no surface
    double x1, x2;
    extent(a.x, b.x, c.x, d.x, x1, x2);
    extent(a.y, b.y, c.y, d.y, p.h1, p.h2);
    p.r2 = std::max(std::abs(x1), std::abs(x2));
    pieces_.push_back(p);
    ends.emplace_back(first, last);
  };
  const auto& P = points;
  switch (spline) {
    case LatheSpline::Linear:
      for (int i = 0; i + 1 < n; ++i)
        add(Vec2(0.0), Vec2(0.0), P[i + 1] - P[i], P[i], P[i], P[i + 1]);
      break;
    case LatheSpline::Quadratic:
      for (int i = 0; i + 2 < n; ++i)
        add(Vec2(0.0), 0.5 * P[i] - P[i + 1] + 0.5 * P[i + 2], 0.5 * (P[i + 2] - P[i]), P[i + 1],
            P[i + 1], P[i + 2]);
      break;
    case LatheSpline::Cubic:  // Catmull-Rom from point i+1 to i+2
      for (int i = 0; i + 3 < n; ++i)
        add(-0.5 * P[i] + 1.5 * P[i + 1] - 1.5 * P[i + 2] + 0.5 * P[i + 3],
            P[i] - 2.5 * P[i + 1] + 2.0 * P[i + 2] - 0.5 * P[i + 3], 0.5 * (P[i + 2] - P[i]),
            P[i + 1], P[i + 1], P[i + 2]);
      break;
    case LatheSpline::Bezier:
      for (int i = 0; i + 3 < n; i += 4)
        add(P[i + 3] - 3.0 * P[i + 2] + 3.0 * P[i + 1] - P[i],
            3.0 * P[i + 2] - 6.0 * P[i + 1] + 3.0 * P[i], 3.0 * (P[i + 1] - P[i]), P[i], P[i],
            P[i + 3]);
      break;
  }
  if (pieces_.empty()) throw std::invalid_argument("lathe: the curve has no extent");
  // The joints; an end that meets no other piece's start is closed by a disc to the axis
  // (POV-Ray's parity inside test changes across it).
  const size_t m = pieces_.size();
  next_.assign(m, -1);
  std::vector<bool> startJoined(m, false);
  for (size_t i = 0; i < m; ++i)
    for (size_t k = 0; k < m; ++k) {
      const size_t j = (i + 1 + k) % m;  // the next piece first
      if (!startJoined[j] && ends[i].second == ends[j].first) {
        pieces_[i].endsFree = false;
        next_[i] = static_cast<int>(j);
        startJoined[j] = true;
        break;
      }
    }
  for (size_t i = 0; i < m; ++i) {
    if (pieces_[i].endsFree && ends[i].second.x > 0.0)
      discs_.push_back({ends[i].second.y, ends[i].second.x, pieces_[i].segment + 1.0});
    if (!startJoined[i] && ends[i].first.x > 0.0)
      discs_.push_back({ends[i].first.y, ends[i].first.x, pieces_[i].segment + 0.0});
  }
  double r = 0.0, h1 = kInf, h2 = -kInf;
  for (const Piece& p : pieces_) {
    r = std::max(r, p.r2);
    h1 = std::min(h1, p.h1);
    h2 = std::max(h2, p.h2);
  }
  bounds_ = AABB(Vec3(-r, h1, -r), Vec3(r, h2, r));
  scale_ = std::max({r, std::abs(h1), std::abs(h2), 1e-300});
}

bool Lathe::polish(const Piece& p, const Vec3& o, const Vec3& d, double& s, double& t) const {
  const double rr = d.x * d.x + d.z * d.z, m = o.x * d.x + o.z * d.z;
  for (int it = 0; it < 4; ++it) {
    const Vec2 c = at(p, s), dc = slope(p, s);
    const double px = o.x + t * d.x, pz = o.z + t * d.z;
    const double f1 = c.y - o.y - t * d.y;
    const double f2 = px * px + pz * pz - c.x * c.x;
    const double j11 = dc.y, j12 = -d.y, j21 = -2.0 * c.x * dc.x, j22 = 2.0 * (m + t * rr);
    const double det = j11 * j22 - j12 * j21;
    if (det == 0.0 || !std::isfinite(det)) return it > 0;
    const double ds = (-f1 * j22 + f2 * j12) / det;
    const double dt = (-j11 * f2 + j21 * f1) / det;
    if (!std::isfinite(ds) || !std::isfinite(dt) || std::abs(ds) > 0.05) return it > 0;
    s += ds;
    t += dt;
    if (std::abs(ds) <= 4.0 * kMachineEps &&
        std::abs(dt) <= 4.0 * kMachineEps * (std::abs(t) + scale_ / std::sqrt(glm::dot(d, d))))
      break;
  }
  return true;
}

void Lathe::pieceRoots(const Piece& p, uint32_t index, const Vec3& o, const Vec3& d,
                       std::vector<LineRoot>& out) const {
  const int k = p.degree;
  auto keep = [&](double s, double t) {
    if (s >= -kSlack && s <= 1.0 + kSlack) out.push_back({t, index, std::clamp(s, 0.0, 1.0)});
  };
  const double yc[4] = {p.d.y - o.y, p.c.y, p.b.y, p.a.y};
  const double ya[4] = {std::abs(p.d.y) + std::abs(o.y), std::abs(p.c.y), std::abs(p.b.y),
                        std::abs(p.a.y)};
  const double len = std::sqrt(glm::dot(d, d));
  if (std::abs(d.y) < kFlat * len) {
    // Nearly horizontal: the heights first, then the two distances along the ray.
    int ky = k;
    while (ky > 0 && yc[ky] == 0.0) --ky;
    if (ky == 0) return;  // a horizontal piece seen edge on
    PolynomialRoot r[3];
    const int found = polynomialRoots(yc, ya, ky, -kSlack, 1.0 + kSlack, r);
    const double rr = d.x * d.x + d.z * d.z, m = o.x * d.x + o.z * d.z;
    for (int i = 0; i < found; ++i) {
      if (r[i].touching) continue;
      const double x = at(p, r[i].x).x;
      const double c = o.x * o.x + o.z * o.z - x * x;
      double t0, t1;
      if (!solveQuadratic(rr, m, c, m * m - rr * c, t0, t1) || t0 == t1) continue;
      for (double t : {t0, t1}) {
        double s = r[i].x;
        if (polish(p, o, d, s, t)) keep(s, t);
      }
    }
    return;
  }
  // |d.y·o_xz + Y(s)·d_xz|² − (d.y·x(s))², with Y = y(s) − o.y.
  double qx[4], qz[4], xx[4], qxa[4], qza[4], xxa[4];
  const double xc[4] = {p.d.x, p.c.x, p.b.x, p.a.x};
  for (int i = 0; i <= k; ++i) {
    qx[i] = yc[i] * d.x;
    qz[i] = yc[i] * d.z;
    xx[i] = xc[i] * d.y;
    qxa[i] = ya[i] * std::abs(d.x);
    qza[i] = ya[i] * std::abs(d.z);
    xxa[i] = std::abs(xc[i] * d.y);
  }
  qx[0] += d.y * o.x;
  qz[0] += d.y * o.z;
  qxa[0] += std::abs(d.y * o.x);
  qza[0] += std::abs(d.y * o.z);
  double g[7], ga[7], tmp[7];
  multiply(qx, k, qx, k, g);
  multiply(qz, k, qz, k, tmp);
  for (int i = 0; i <= 2 * k; ++i) g[i] += tmp[i];
  multiply(xx, k, xx, k, tmp);
  for (int i = 0; i <= 2 * k; ++i) g[i] -= tmp[i];
  multiply(qxa, k, qxa, k, ga);
  multiply(qza, k, qza, k, tmp);
  for (int i = 0; i <= 2 * k; ++i) ga[i] += tmp[i];
  multiply(xxa, k, xxa, k, tmp);
  for (int i = 0; i <= 2 * k; ++i) ga[i] += tmp[i];
  int n = 2 * k;
  while (n > 0 && std::abs(g[n]) <= gamma(2 * n + 6) * ga[n]) --n;
  if (n == 0) return;
  PolynomialRoot r[kMaxPolynomialDegree];
  const int found = polynomialRoots(g, ga, n, -kSlack, 1.0 + kSlack, r);
  for (int i = 0; i < found; ++i) {
    double s = r[i].x;
    double t = (at(p, s).y - o.y) / d.y;
    // Where the curve meets the axis both squares vanish: a double root of the polynomial
    // but a simple crossing of the surface (a ray through the pole). Elsewhere a double
    // root is a tangent ray: no crossing.
    if (onAxis(p, s)) {
      keep(s, t);
      continue;
    }
    // A double root within rounding of the surface: a pair at the contact, which
    // decideByInside keeps (a zero-length chord) or drops by the inside test there.
    if (r[i].touching) {
      keep(s, t);
      keep(s, t);
      continue;
    }
    if (polish(p, o, d, s, t)) keep(s, t);
  }
}

bool Lathe::alternates(const std::vector<LineRoot>& roots, double dd) const {
  // The order alone decides (the line starts outside and each root flips it) unless a root
  // can have been found twice or not at all: an odd count; two roots within `close` (one
  // crossing found on both pieces of a joint, or a corner clipped on both, or a tangent
  // contact's pair); a root within 1e-6 of a piece's end, where a neighbour's root may be
  // missing; a closing disc's root at its rim, where the curve's end meets it.
  if (roots.size() % 2 != 0) return false;
  const double close = 1e-9 * (scale_ / std::sqrt(dd));
  for (size_t i = 0; i < roots.size(); ++i) {
    const LineRoot& r = roots[i];
    if (i > 0 && r.t - roots[i - 1].t <= close) return false;
    if (r.part < pieces_.size() ? (r.s < 1e-6 || r.s > 1.0 - 1e-6) : r.s > 1.0 - 1e-9) return false;
  }
  return true;
}

void Lathe::decideByInside(const Vec3& o, const Vec3& d, std::vector<LineRoot>& roots) const {
  // Each root is kept where the inside test differs on its two sides (between it and its
  // neighbours; outside beyond the first and the last): the kept roots then alternate by
  // construction, whatever was found twice or missed.
  bool before = false;
  size_t w = 0;
  for (size_t i = 0; i < roots.size(); ++i) {
    const bool after =
        i + 1 < roots.size() && solidInside(o + 0.5 * (roots[i].t + roots[i + 1].t) * d);
    if (after != before) roots[w++] = roots[i];
    before = after;
  }
  roots.resize(w);
}

void Lathe::lineRoots(const Ray& ray, std::vector<LineRoot>& out) const {
  out.clear();
  // From the line's point closest to the lathe's origin, so the coefficients stay of the
  // shape's size for a far ray.
  const Vec3& d = ray.d;
  const double dd = glm::dot(d, d);
  if (!(dd > 0.0)) return;
  const double s0 = -glm::dot(ray.o, d) / dd;
  const Vec3 o = ray.o + s0 * d;
  const Ray line(o, d, -kInf, kInf);
  if (!bounds_.hit(line, 1.0 / d)) return;
  const double rr = d.x * d.x + d.z * d.z, m = o.x * d.x + o.z * d.z, oo = o.x * o.x + o.z * o.z;
  for (size_t i = 0; i < pieces_.size(); ++i) {
    const Piece& p = pieces_[i];
    // The piece's bounding cylinder, a little widened.
    const double pad = 1e-9 * scale_;
    double lo = -kInf, hi = kInf;
    if (d.y != 0.0) {
      const double a = (p.h1 - pad - o.y) / d.y, b = (p.h2 + pad - o.y) / d.y;
      lo = std::min(a, b);
      hi = std::max(a, b);
    } else if (o.y < p.h1 - pad || o.y > p.h2 + pad) {
      continue;
    }
    const double c = oo - (p.r2 + pad) * (p.r2 + pad);
    if (rr > 0.0) {
      const double disc = m * m - rr * c;
      if (disc < 0.0) continue;
      const double q = std::sqrt(disc);
      lo = std::max(lo, (-m - q) / rr);
      hi = std::min(hi, (-m + q) / rr);
      if (lo > hi) continue;
    } else if (c > 0.0) {
      continue;
    }
    pieceRoots(p, static_cast<uint32_t>(i), o, d, out);
  }
  for (size_t i = 0; i < discs_.size(); ++i) {
    if (d.y == 0.0) continue;
    const double u = (discs_[i].y - o.y) / d.y;
    const double px = o.x + u * d.x, pz = o.z + u * d.z;
    const double r2 = discs_[i].radius * discs_[i].radius;
    // s: the squared fraction of the radius, for the rim test of alternates().
    if (px * px + pz * pz < r2)
      out.push_back({u, static_cast<uint32_t>(pieces_.size() + i), (px * px + pz * pz) / r2});
  }
  std::sort(out.begin(), out.end(), [](const LineRoot& a, const LineRoot& b) { return a.t < b.t; });
  if (!alternates(out, dd)) decideByInside(o, d, out);
  for (size_t i = 0; i < out.size(); ++i) {
    out[i].t += s0;
    if (i % 2 == 0) out[i].part |= kEnteringBit;
  }
}

namespace {
thread_local std::vector<Lathe::LineRoot> scratch;
}  // namespace

bool Lathe::isDisc(const LineRoot& r) const { return (r.part & ~kEnteringBit) >= pieces_.size(); }

bool Lathe::intersect(const Ray& ray, Hit& hit) const {
  lineRoots(ray, scratch);
  for (const LineRoot& r : scratch)
    if (ray.tmin < r.t && r.t < ray.tmax && !(open_ && isDisc(r))) {
      hit.t = r.t;
      hit.shape = this;
      hit.part = r.part;
      hit.b1 = r.s;
      hit.b2 = 0.0;
      return true;
    }
  return false;
}

void Lathe::crossings(const Ray& ray, CrossingList& out) const {
  lineRoots(ray, scratch);
  bool in = false;
  for (const LineRoot& r : scratch) {
    if (open_ && isDisc(r)) continue;
    // An open lathe is a surface: its crossings all enter.
    const bool entering = open_ || (r.part & kEnteringBit) != 0;
    if (r.t < ray.tmin) {
      in = entering && !open_;
      continue;
    }
    if (r.t > ray.tmax) break;
    Hit h;
    h.t = r.t;
    h.shape = this;
    h.part = r.part;
    h.b1 = r.s;
    out.items.push_back({h, entering});
  }
  out.startsInside = in;
}

// A surface (open) has no inside.
bool Lathe::inside(const Vec3& q) const { return !open_ && solidInside(q); }

bool Lathe::solidInside(const Vec3& q) const {
  if (!bounds_.contains(q)) return false;
  const double rho = std::sqrt(q.x * q.x + q.z * q.z);
  int count = 0;
  for (const Piece& p : pieces_) {
    if (q.y < p.h1 || q.y > p.h2 || rho > p.r2) continue;
    double yc[4] = {p.d.y - q.y, p.c.y, p.b.y, p.a.y};
    const double ya[4] = {std::abs(p.d.y) + std::abs(q.y), std::abs(p.c.y), std::abs(p.b.y),
                          std::abs(p.a.y)};
    int k = 3;
    while (k > 0 && yc[k] == 0.0) --k;
    if (k == 0) continue;
    PolynomialRoot r[3];
    const int found = polynomialRoots(yc, ya, k, -kSlack, 1.0 + kSlack, r);
    for (int i = 0; i < found; ++i) {
      if (r[i].touching) continue;
      const double s = r[i].x;
      // Each joint belongs to the piece it starts.
      if (s < 0.0 || s > 1.0 || (s >= 1.0 && !p.endsFree)) continue;
      // |x|: where a spline swings past the axis the surface is its mirror (POV-Ray draws
      // it so), and the parity must count it to stay the solid the crossings bound.
      if (std::abs(at(p, s).x) >= rho) ++count;
    }
  }
  return (count & 1) != 0;
}

SurfaceInfo Lathe::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo si;
  si.p = ray.at(hit.t);
  const uint32_t part = hit.part & ~kEnteringBit;
  const bool entering = (hit.part & kEnteringBit) != 0;
  Vec3 n(0.0, 1.0, 0.0);
  if (part < pieces_.size()) {
    const Vec2 dc = slope(pieces_[part], hit.b1);
    const double rho = std::sqrt(si.p.x * si.p.x + si.p.z * si.p.z);
    if (rho > 1e-12 * scale_) {
      n = Vec3(dc.y * si.p.x / rho, -dc.x, dc.y * si.p.z / rho);
    } else {
      n = Vec3(0.0, dc.x != 0.0 ? -dc.x : 1.0, 0.0);
    }
    const double len = glm::length(n);
    n = len > 0.0 ? n / len : Vec3(0.0, 1.0, 0.0);
  }
  // Outward: against the ray where it enters, along it where it leaves.
  if ((glm::dot(n, ray.d) < 0.0) != entering) n = -n;
  si.ng = n;
  si.ns = n;
  si.pError =
      gamma(32) * (glm::abs(ray.o) + glm::abs(hit.t * ray.d) + glm::abs(si.p) + Vec3(scale_));
  return si;
}

// POV-Ray's lathe: u the angle about +y in POV-Ray's space, v the spline parameter plus
// the segment's number over the number of segments, at most 1. A closing disc (which
// POV-Ray does not draw) takes the v of the curve's end it closes.
bool Lathe::povUV(const SurfaceInfo& s, const Hit& hit, Vec2& uv) const {
  const uint32_t part = hit.part & ~kEnteringBit;
  const double n = static_cast<double>(segments_);
  const double v = part < pieces_.size() ? (hit.b1 + pieces_[part].segment) / n
                                         : discs_[part - pieces_.size()].v / n;
  uv = Vec2(povTurnsAboutY(s.p.x, -s.p.z), std::min(v, 1.0));
  return true;
}

}  // namespace lucent
