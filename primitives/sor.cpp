#include "sor.h"
#include "pov_uv.h"

#include "centred_line.h"

#include "polynomial.h"
#include "quadratic.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucent {

namespace {

// POV-Ray's EPSILON: the smallest height difference it accepts between the points.
constexpr double kPovEpsilon = 1e-10;

}  // namespace

Sor::Sor(const std::vector<Vec2>& P, bool open) : open_(open) {
  const size_t n = P.size();
  if (n < 4) throw std::invalid_argument("sor: needs at least 4 points");
  for (const Vec2& p : P) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      throw std::invalid_argument("sor: points must be finite");
    if (p.x < 0.0) throw std::invalid_argument("sor: x must be >= 0");
  }
  for (size_t i = 2; i + 1 < n; ++i)
    if (!(P[i].y > P[i - 1].y)) throw std::invalid_argument("sor: the heights must increase");
  for (size_t i = 0; i + 2 < n; ++i)
    if (std::abs(P[i + 2].y - P[i].y) < kPovEpsilon)
      throw std::invalid_argument("sor: a point at its neighbour's neighbour's height");
  bool offAxis = false;
  for (size_t i = 1; i + 1 < n; ++i) offAxis |= P[i].x > 0.0;
  if (!offAxis) throw std::invalid_argument("sor: the curve lies on the axis");
  double R = 0.0;
  for (size_t i = 0; i + 3 < n; ++i) {
    const Vec2 &p0 = P[i], &p1 = P[i + 1], &p2 = P[i + 2], &p3 = P[i + 3];
    const double h = p2.y - p1.y;
    const double F0 = p1.x * p1.x, F1 = p2.x * p2.x;
    const double D0 = 2.0 * p1.x * (p2.x - p0.x) / (p2.y - p0.y);
    const double D1 = 2.0 * p2.x * (p3.x - p1.x) / (p3.y - p1.y);
    const double q = (F1 - F0) / h;  // Hermite cubic on [0, h]
    Segment s{(D0 + D1 - 2.0 * q) / (h * h),
              (3.0 * q - 2.0 * D0 - D1) / h,
              D0,
              F0,
              p1.y,
              h,
              0.0,
              0.0,
              D1,
              F1};
    s.bt = s.b + 3.0 * s.a * h;
    double top = std::max(F0, F1);
    const double dc[3] = {s.c, 2.0 * s.b, 3.0 * s.a};
    const double da[3] = {std::abs(s.c), std::abs(2.0 * s.b), std::abs(3.0 * s.a)};
    const int k = dc[2] != 0.0 ? 2 : dc[1] != 0.0 ? 1 : 0;
    if (k > 0) {
      PolynomialRoot r[2];
      const int found = polynomialRoots(dc, da, k, 0.0, h, r);
      for (int j = 0; j < found; ++j) top = std::max(top, f(s, r[j].x));
    }
    s.r = std::sqrt(top);
    R = std::max(R, s.r);
    segs_.push_back(s);
    joints_.push_back(p1.y);
    jointR2_.push_back(p1.x * p1.x);
  }
  joints_.push_back(P[n - 2].y);
  jointR2_.push_back(P[n - 2].x * P[n - 2].x);
  bottomR2_ = P[1].x * P[1].x;
  topR2_ = P[n - 2].x * P[n - 2].x;
  bounds_ = AABB(Vec3(-R, joints_.front(), -R), Vec3(R, joints_.back(), R));
  scale_ = std::max({R, std::abs(joints_.front()), std::abs(joints_.back()), 1e-300});
}

size_t Sor::segmentAt(double y) const {
  const auto it = std::upper_bound(joints_.begin(), joints_.end(), y);
  const ptrdiff_t i = (it - joints_.begin()) - 1;
  return static_cast<size_t>(std::clamp<ptrdiff_t>(i, 0, static_cast<ptrdiff_t>(segs_.size()) - 1));
}

double Sor::radiusSquaredAt(double y) const {
  const Segment& s = segs_[segmentAt(y)];
  return f(s, y - s.y0);
}

bool Sor::inside(const Vec3& p) const {
  if (open_) return false;  // a surface has no inside (POV-Ray's open sor keeps one)
  if (!(p.y >= joints_.front() && p.y <= joints_.back())) return false;
  return p.x * p.x + p.z * p.z <= radiusSquaredAt(p.y);
}

void Sor::segmentSpans(size_t i, const Vec3& o, const Vec3& d, double ta, double tb, int ja, int jb,
                       std::vector<Span>& out) const {
  const Segment& s = segs_[i];
  const double rr = d.x * d.x + d.z * d.z, m = o.x * d.x + o.z * d.z, oo = o.x * o.x + o.z * o.z;
  // g along the line, from the point itself (not the expanded cubic).
  auto g = [&](double t) {
    const double px = o.x + t * d.x, pz = o.z + t * d.z;
    return px * px + pz * pz - fNear(s, (o.y + t * d.y) - s.y0);
  };
  auto dg = [&](double t) {
    const double px = o.x + t * d.x, pz = o.z + t * d.z;
    return 2.0 * (px * d.x + pz * d.z) - d.y * dfNear(s, (o.y + t * d.y) - s.y0);
  };
  double roots[3];
  int nr = 0;
  if (rr == 0.0) {
    // Along the axis: f(w) = x² + z², a cubic in w; t follows from the height.
    const double c[4] = {s.e - oo, s.c, s.b, s.a};
    const double ca[4] = {std::abs(s.e) + oo, std::abs(s.c), std::abs(s.b), std::abs(s.a)};
    int k = 3;
    while (k > 0 && c[k] == 0.0) --k;
    if (k > 0) {
      PolynomialRoot r[3];
      const int found = polynomialRoots(c, ca, k, 0.0, s.h, r);
      for (int j = 0; j < found; ++j)
        if (!r[j].touching) roots[nr++] = (s.y0 + r[j].x - o.y) / d.y;
      if (d.y < 0.0) std::reverse(roots, roots + nr);
    }
  } else {
    // The magnitudes behind each coefficient (for the tangent test), W's own rounding
    // (an ulp of o.y and y0, moving f by f'·δW) included in the constant term.
    const double W = o.y - s.y0, aw = std::abs(W), wErr = (std::abs(o.y) + std::abs(s.y0)) / 12.0;
    const double A = std::abs(s.a), B = std::abs(s.b), C = std::abs(s.c), ady = std::abs(d.y);
    const double c[4] = {oo - f(s, W), 2.0 * m - d.y * df(s, W),
                         rr - d.y * d.y * (3.0 * s.a * W + s.b), -s.a * d.y * d.y * d.y};
    const double ca[4] = {
        oo + ((A * aw + B) * aw + C) * aw + std::abs(s.e) + std::abs(df(s, W)) * wErr,
        2.0 * std::abs(m) + ady * ((3.0 * A * aw + 2.0 * B) * aw + C),
        rr + d.y * d.y * (3.0 * A * aw + B), A * ady * ady * ady};
    int k = 3;
    while (k > 0 && std::abs(c[k]) <= gamma(2 * k + 6) * ca[k]) --k;
    if (k > 0) {
      PolynomialRoot r[3];
      const int found = polynomialRoots(c, ca, k, ta, tb, r);
      for (int j = 0; j < found; ++j) {
        if (r[j].touching) continue;  // a tangent ray: g keeps its sign
        // Newton on g itself, kept while it improves and stays in the interval: a step or
        // two for a simple root; near a pole, where g has a double root, it halves the
        // error each step (the cubic's own root is only good to the square root of its
        // rounding there).
        double t = r[j].x, gt = g(t);
        for (int it = 0; it < 60 && gt != 0.0; ++it) {
          const double dgt = dg(t);
          if (dgt == 0.0) break;
          const double next = t - gt / dgt;
          const double gn = next > ta && next < tb ? g(next) : kInf;
          if (!(std::abs(gn) < std::abs(gt))) break;
          t = next;
          gt = gn;
        }
        roots[nr++] = t;
      }
      for (int j = 1; j < nr; ++j)  // the polish may swap two close roots
        for (int q = j; q > 0 && roots[q] < roots[q - 1]; --q) std::swap(roots[q], roots[q - 1]);
    }
  }
  // The sign of g at each end: at a joint from the point's own x² (so both segments and
  // the cap agree on it, whatever their cubics round to there); past the bounding
  // cylinder positive; 0 where it is exactly 0 (unknown).
  auto endSign = [&](double t, int joint, double& mag) {
    if (joint < 0) {
      mag = kInf;
      return 1;
    }
    const double px = o.x + t * d.x, pz = o.z + t * d.z;
    const double v = px * px + pz * pz - jointR2_[static_cast<size_t>(joint)];
    mag = std::abs(v);
    return v > 0.0 ? 1 : v < 0.0 ? -1 : 0;
  };
  double magA, magB;
  const int sa = endSign(ta, ja, magA), sb = endSign(tb, jb, magB);
  // An odd count of roots must change the sign between known ends. Where it does not, the
  // cubic rounded the other way at the less certain end: a root found within rounding of
  // that end goes, else the sign changes at the end itself (a root there).
  if (sa != 0 && sb != 0 && ((nr & 1) == 0) != (sa == sb)) {
    const bool atA = magA < magB;
    const double near = 1e-6 * scale_;
    if (nr > 0 && (atA ? roots[0] - ta : tb - roots[nr - 1]) <= near) {
      if (atA) std::copy(roots + 1, roots + nr, roots);
      --nr;
    } else if (nr < 3) {
      if (atA) {
        std::copy_backward(roots, roots + nr, roots + nr + 1);
        roots[0] = ta;
      } else {
        roots[nr] = tb;
      }
      ++nr;
    }
  }
  double pts[5];
  pts[0] = ta;
  for (int j = 0; j < nr; ++j) pts[j + 1] = roots[j];
  pts[nr + 1] = tb;
  // The pieces' signs alternate across the roots, from a known end, else from g at the
  // middle of the longest piece.
  int longest = 0;
  bool negLongest;
  if (sa != 0 && (sb == 0 || nr > 0 || magA >= magB)) {
    negLongest = sa < 0;
  } else if (sb != 0) {
    longest = nr;
    negLongest = sb < 0;
  } else {
    for (int j = 1; j <= nr; ++j)
      if (pts[j + 1] - pts[j] > pts[longest + 1] - pts[longest]) longest = j;
    negLongest = g(0.5 * (pts[longest] + pts[longest + 1])) < 0.0;
  }
  for (int j = 0; j <= nr; ++j) {
    if (negLongest != (((j - longest) & 1) == 0)) continue;
    if (!(pts[j] < pts[j + 1])) continue;
    const int seg = static_cast<int>(i);
    out.push_back({{pts[j], j == 0 ? ja : -1, seg}, {pts[j + 1], j == nr ? jb : -1, seg}});
  }
}

void Sor::lineEvents(const Ray& ray, std::vector<Event>& out) const {
  out.clear();
  CentredLine line;
  if (!centredLine(ray, bounds_, line)) return;
  const Vec3 o = line.o, d = line.d;
  const double s0 = line.s0, len = line.len;
  const double rr = d.x * d.x + d.z * d.z, m = o.x * d.x + o.z * d.z, oo = o.x * o.x + o.z * o.z;
  thread_local std::vector<Span> spans;
  spans.clear();
  const size_t ns = segs_.size();
  if (d.y == 0.0) {
    // Horizontal: one height, one circle.
    if (!(o.y >= joints_.front() && o.y <= joints_.back())) return;
    const size_t i = segmentAt(o.y);
    const double c = oo - f(segs_[i], o.y - segs_[i].y0);
    double t0, t1;
    if (!solveQuadratic(rr, m, c, m * m - rr * c, t0, t1) || !(t0 < t1)) return;
    const int seg = static_cast<int>(i);
    spans.push_back({{t0, -1, seg}, {t1, -1, seg}});
  } else {
    const double pad = 1e-9 * scale_;
    for (size_t i = 0; i < ns; ++i) {
      const Segment& s = segs_[i];
      const double tl = (joints_[i] - o.y) / d.y, th = (joints_[i + 1] - o.y) / d.y;
      double ta = std::min(tl, th), tb = std::max(tl, th);
      int ja = static_cast<int>(d.y > 0.0 ? i : i + 1),
          jb = static_cast<int>(d.y > 0.0 ? i + 1 : i);
      // The segment's bounding cylinder, a little widened: g > 0 outside it.
      const double rp = s.r + pad, c = oo - rp * rp;
      if (rr > 0.0) {
        const double disc = m * m - rr * c;
        if (disc < 0.0) continue;
        const double q = std::sqrt(disc);
        const double lo = (-m - q) / rr, hi = (-m + q) / rr;
        if (lo > ta) {
          ta = lo;
          ja = -1;
        }
        if (hi < tb) {
          tb = hi;
          jb = -1;
        }
        if (!(ta < tb)) continue;
      } else if (c > 0.0) {
        continue;
      }
      segmentSpans(i, o, d, ta, tb, ja, jb, spans);
    }
  }
  std::sort(spans.begin(), spans.end(),
            [](const Span& a, const Span& b) { return a.in.t < b.in.t; });
  // Join spans that meet (at a shared joint the two segments use the same t) or leave a
  // gap within rounding (a ray through a joint's circle, seen by both segments), then drop
  // what is left of rounding-sized spans.
  const double close = 16.0 * kMachineEps * (scale_ + std::abs(s0));
  size_t w = 0;
  for (size_t k = 0; k < spans.size(); ++k) {
    if (w > 0 && spans[k].in.t <= spans[w - 1].out.t + close) {
      if (spans[k].out.t > spans[w - 1].out.t) spans[w - 1].out = spans[k].out;
      continue;
    }
    spans[w++] = spans[k];
  }
  spans.resize(w);
  spans.erase(std::remove_if(spans.begin(), spans.end(),
                             [&](const Span& sp) { return sp.out.t - sp.in.t <= close; }),
              spans.end());
  const int top = static_cast<int>(ns);
  auto part = [&](const End& e, bool& cap) -> uint32_t {
    cap = false;
    if (e.joint < 0) return static_cast<uint32_t>(e.seg);
    if (e.joint == 0 || e.joint == top) {
      cap = true;
      return static_cast<uint32_t>(e.joint == 0 ? ns : ns + 1);
    }
    return static_cast<uint32_t>(e.seg);  // crossing the curve exactly at a joint
  };
  for (const Span& sp : spans) {
    bool capIn, capOut;
    const uint32_t pin = part(sp.in, capIn), pout = part(sp.out, capOut);
    const double tin = (sp.in.t + s0) / len, tout = (sp.out.t + s0) / len;
    if (open_) {
      if (!capIn) out.push_back({tin, pin, true});
      if (!capOut) out.push_back({tout, pout, true});
    } else {
      out.push_back({tin, pin, true});
      out.push_back({tout, pout, false});
    }
  }
}

namespace {
thread_local std::vector<Sor::Event> scratch;
}  // namespace

bool Sor::intersect(const Ray& ray, Hit& hit) const {
  lineEvents(ray, scratch);
  for (const Event& e : scratch)
    if (ray.tmin < e.t && e.t < ray.tmax) {
      hit.t = e.t;
      hit.shape = this;
      hit.part = e.part;
      hit.b1 = 0.0;
      hit.b2 = 0.0;
      return true;
    }
  return false;
}

void Sor::crossings(const Ray& ray, CrossingList& out) const {
  lineEvents(ray, scratch);
  bool in = false;
  for (const Event& e : scratch) {
    if (e.t < ray.tmin) {
      if (!open_) in = e.entering;
      continue;
    }
    if (e.t > ray.tmax) break;
    Hit h;
    h.t = e.t;
    h.shape = this;
    h.part = e.part;
    out.items.push_back({h, e.entering});
  }
  out.startsInside = in;
}

SurfaceInfo Sor::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo si;
  si.p = ray.at(hit.t);
  const Vec3& p = si.p;
  const size_t ns = segs_.size();
  const double rho = std::sqrt(p.x * p.x + p.z * p.z);
  Vec3 n(0.0, 1.0, 0.0);
  double v = 0.0;
  if (hit.part < ns) {
    // The gradient of x² + z² − f(y), halved: outward, as POV-Ray's normal.
    const Segment& s = segs_[hit.part];
    const double w = std::clamp(p.y - s.y0, 0.0, s.h);
    n = Vec3(p.x, -0.5 * dfNear(s, w), p.z);
    const double l = glm::length(n);
    n = l > 0.0 ? n / l : Vec3(0.0, 1.0, 0.0);
    v = (w / s.h + static_cast<double>(hit.part)) / static_cast<double>(ns);
  } else if (hit.part == ns) {
    n = Vec3(0.0, -1.0, 0.0);
    v = rho / std::sqrt(bottomR2_) -
        1.0;  // POV-Ray's v on the base: -1 at the centre, 0 at the rim
  } else {
    v = 2.0 - rho / std::sqrt(topR2_);  // on the cap: 1 at the rim, 2 at the centre
  }
  si.ng = n;
  si.ns = n;
  // u: the angle about the axis from +x towards +z, in turns (POV-Ray's sor).
  double u = 0.0;
  if (rho * rho > 1e-10) {
    u = std::atan2(p.z, p.x) / (2.0 * kPi);
    if (u < 0.0) u += 1.0;
  }
  si.uv = Vec2(u, v);
  si.hasUV = true;
  si.pError =
      gamma(32) * (glm::abs(ray.o) + glm::abs(hit.t * ray.d) + glm::abs(si.p) + Vec3(scale_));
  return si;
}

// POV-Ray's sor: its v is the one surface() gives; u the angle about +y in POV-Ray's space.
bool Sor::povUV(const SurfaceInfo& s, const Hit& /*hit*/, Vec2& uv) const {
  uv = Vec2(povTurnsAboutY(s.p.x, -s.p.z), s.uv.y);
  return true;
}

}  // namespace lucent
