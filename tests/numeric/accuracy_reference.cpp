// Long-double references for the accuracy harness: the same closed forms as the shapes
// where those are well conditioned (the quadrics' distance-form quadratic), and a
// method with no rounding trouble at all where they are not (the torus: bracketing and
// bisection of the tube's distance function instead of a quartic).
#include <algorithm>
#include <cmath>
#include <limits>

#include "accuracy_harness.h"
#include "accuracy_roots.h"

namespace lucent::accuracy {

namespace {

LVec normalizeL(const LVec& v) { return v / std::sqrt(glm::dot(v, v)); }

LD maxAbs(const LVec& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// Two faces met at parameters within this window of each other are an edge hit: which of
// them a double computation picks is up to rounding (the window is ~1e-13 of the
// coordinates' magnitude, ~900 ulps), so the normal there is not defined.
bool edgeTie(const LRay& ray, LD ta, LD tb) {
  LD scale = (maxAbs(ray.o) + std::abs(ta) * maxAbs(ray.d)) / maxAbs(ray.d);
  return std::abs(ta - tb) <= 1e-13L * scale;
}

// Roots of a·s² + 2h·s + c = 0, cancellation-free (quadratic.h's form), ascending.
bool quadraticRoots(LD a, LD h, LD c, LD disc, LD& s0, LD& s1) {
  if (disc < 0) return false;
  LD q = -(h + std::copysign(std::sqrt(disc), h));
  if (q == 0) {
    if (a == 0) return false;
    s0 = s1 = 0;
    return true;
  }
  if (a == 0) {
    s0 = s1 = c / q;
    return true;
  }
  s0 = q / a;
  s1 = c / q;
  if (s0 > s1) std::swap(s0, s1);
  return true;
}

class RefSphereImpl final : public RefShape {
 public:
  RefSphereImpl(const Vec3& c, double r) : c_(toL(c)), r_(r) {}
  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    LVec f = ray.o - c_;
    LD a = glm::dot(ray.d, ray.d);
    if (!(a > 0)) return;
    LD h = glm::dot(f, ray.d);
    // The distance form of the discriminant (Ray Tracing Gems ch. 7), in long double.
    LVec perp = f - (h / a) * ray.d;
    LD disc = a * (r_ * r_ - glm::dot(perp, perp));
    LD s0, s1;
    if (!quadraticRoots(a, h, glm::dot(f, f) - r_ * r_, disc, s0, s1)) return;
    for (LD t : {s0, s1}) out.push_back({t, normalizeL(ray.at(t) - c_)});
  }

 private:
  LVec c_;
  LD r_;
};

class RefBoxImpl final : public RefShape {
 public:
  RefBoxImpl(const Vec3& lo, const Vec3& hi)
      : lo_(toL(glm::min(lo, hi))), hi_(toL(glm::max(lo, hi))) {}
  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    LD tIn = -INFINITY, tOut = INFINITY;
    int axIn = -1, axOut = -1;
    LD sIn = 0, sOut = 0;
    bool tieIn = false, tieOut = false;
    LD ts0[3] = {0, 0, 0}, ts1[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      if (ray.d[k] == 0) {
        if (ray.o[k] < lo_[k] || ray.o[k] > hi_[k]) return;
        continue;
      }
      LD t0 = (lo_[k] - ray.o[k]) / ray.d[k], t1 = (hi_[k] - ray.o[k]) / ray.d[k];
      LD s0 = -1, s1 = 1;  // outward normal sign of the face met at t0, t1
      if (t0 > t1) {
        std::swap(t0, t1);
        std::swap(s0, s1);
      }
      ts0[k] = t0;
      ts1[k] = t1;
      if (t0 > tIn) {
        tIn = t0;
        axIn = k;
        sIn = s0;
      }
      if (t1 < tOut) {
        tOut = t1;
        axOut = k;
        sOut = s1;
      }
    }
    if (!(tIn <= tOut) || axIn < 0 || axOut < 0) return;
    for (int k = 0; k < 3; ++k) {
      if (ray.d[k] == 0) continue;
      if (k != axIn && edgeTie(ray, ts0[k], tIn)) tieIn = true;
      if (k != axOut && edgeTie(ray, ts1[k], tOut)) tieOut = true;
    }
    LVec nIn(0), nOut(0);
    nIn[axIn] = sIn;
    nOut[axOut] = sOut;
    out.push_back({tIn, nIn, !tieIn});
    out.push_back({tOut, nOut, !tieOut});
  }

 private:
  LVec lo_, hi_;
};

// The axis frame of a cylinder or cone: origin at the base, unit axis towards the cap.
struct LAxis {
  LVec base, a;
  LD height;
  LAxis(const Vec3& b, const Vec3& c) : base(toL(b)) {
    LVec v = toL(c) - base;
    height = std::sqrt(glm::dot(v, v));
    a = v / height;
  }
  // Splits a point (relative to the base) or a vector into its axial and radial parts.
  LD along(const LVec& v) const { return glm::dot(v, a); }
  LVec across(const LVec& v) const { return v - glm::dot(v, a) * a; }
};

// Clips [lo, hi] (with the parts it was entered and left through) to the slab between the
// end discs, for a line whose origin lies zb above the base plane and zc below the cap
// plane (passed separately so each keeps its own precision) and whose direction has the
// axial component dz. Returns false when nothing is left. tieLo/tieHi: that end lies on a
// rim, within rounding (edgeTie) of both the side and a disc.
bool clipToSlab(const LRay& ray, LD zb, LD zc, LD dz, LD& lo, LD& hi, int& partLo, int& partHi,
                bool& tieLo, bool& tieHi) {
  tieLo = tieHi = false;
  if (dz == 0) return 0 <= zb && 0 <= zc && lo <= hi;
  LD tb = -zb / dz, tc = zc / dz;
  int pb = 1, pc = 2;
  if (tb > tc) {
    std::swap(tb, tc);
    std::swap(pb, pc);
  }
  tieLo = std::isfinite(lo) && edgeTie(ray, tb, lo);
  tieHi = std::isfinite(hi) && edgeTie(ray, tc, hi);
  if (tb > lo) {
    lo = tb;
    partLo = pb;
  }
  if (tc < hi) {
    hi = tc;
    partHi = pc;
  }
  return lo <= hi;
}

class RefCylinderImpl final : public RefShape {
 public:
  RefCylinderImpl(const Vec3& base, const Vec3& cap, double r) : ax_(base, cap), r_(r) {}
  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    LVec fp = ax_.across(ray.o - ax_.base), dp = ax_.across(ray.d);
    LD lo, hi;
    LD a = glm::dot(dp, dp);
    if (a == 0) {
      if (glm::dot(fp, fp) > r_ * r_) return;
      lo = -INFINITY;
      hi = INFINITY;
    } else {
      LD h = glm::dot(fp, dp);
      LVec perp = fp - (h / a) * dp;
      LD disc = a * (r_ * r_ - glm::dot(perp, perp));
      if (!quadraticRoots(a, h, glm::dot(fp, fp) - r_ * r_, disc, lo, hi)) return;
    }
    int pLo = 0, pHi = 0;
    bool tieLo, tieHi;
    LD zb = ax_.along(ray.o - ax_.base);
    if (!clipToSlab(ray, zb, ax_.height - zb, ax_.along(ray.d), lo, hi, pLo, pHi, tieLo, tieHi))
      return;
    out.push_back({lo, normalAt(ray.at(lo), pLo), !tieLo});
    out.push_back({hi, normalAt(ray.at(hi), pHi), !tieHi});
  }

 private:
  LVec normalAt(const LVec& p, int part) const {
    if (part == 1) return -ax_.a;
    if (part == 2) return ax_.a;
    return normalizeL(ax_.across(p - ax_.base));
  }
  LAxis ax_;
  LD r_;
};

class RefConeImpl final : public RefShape {
 public:
  RefConeImpl(const Vec3& base, double r0, const Vec3& cap, double r1)
      : ax_(base, cap), r0_(r0), k_((LD(r1) - LD(r0)) / ax_.height) {
    // A pointed end is the apex (r = 0 there); its position along the axis is exact.
    if (r1 == 0.0) zApex_ = ax_.height;
    if (r0 == 0.0) zApex_ = 0;
    apex_ = ax_.base + zApex_ * ax_.a;
  }

  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    LD dd = glm::dot(ray.d, ray.d);
    if (!(dd > 0)) return;
    // The origin is moved along the line to its closest approach to a centre point, so the
    // coefficients are of the cone's size however far the ray starts (as cone.cpp does;
    // without it a ray from 1e5 away cancels even in long double). The centre is the
    // apex when the line passes near it: the side's function x² + y² − r(z)² has a zero
    // gradient there, so its value must be formed relative to the apex, where all its
    // terms are small and exact to long double's relative precision, or the roots of a
    // line passing 1e-12 from the apex would be off by √ε_LD.
    const bool hasApex = zApex_ >= 0;
    LVec centre = ax_.base + (ax_.height / 2) * ax_.a;
    LD shift = -glm::dot(ray.o - centre, ray.d) / dd;
    if (hasApex) {
      LD toApex = -glm::dot(ray.o - apex_, ray.d) / dd;
      LVec miss = ray.at(toApex) - apex_;
      if (glm::dot(miss, miss) < 0.0625L * ax_.height * ax_.height) {
        centre = apex_;
        shift = toApex;
      }
    }
    const LVec o = ray.o + shift * ray.d;
    const LVec f = o - centre;
    const LVec fp = ax_.across(f), dp = ax_.across(ray.d);
    const LD fz = ax_.along(f), dz = ax_.along(ray.d);
    // r at the shifted origin: k·(z − z_apex) when measured from the apex.
    const LD zc0 = ax_.along(centre - ax_.base);  // exact: 0, h/2 or h up to rounding
    const LD r = centre == apex_ && hasApex ? k_ * fz : r0_ + k_ * (zc0 + fz);
    const LD a = glm::dot(dp, dp) - k_ * k_ * dz * dz;
    const LD h = glm::dot(fp, dp) - k_ * dz * r;
    const LD c = glm::dot(fp, fp) - r * r;
    // Where x² + y² − r(z)² <= 0 along the line: one or two pieces.
    LD pieces[2][2];
    int n = 0;
    if (a == 0) {
      if (h == 0) {
        if (c > 0) return;
        pieces[n][0] = -INFINITY, pieces[n][1] = INFINITY, ++n;
      } else {
        LD s0 = -c / (2 * h);
        if (h > 0) pieces[n][0] = -INFINITY, pieces[n][1] = s0, ++n;
        else pieces[n][0] = s0, pieces[n][1] = INFINITY, ++n;
      }
    } else {
      LD s0, s1;
      bool real = quadraticRoots(a, h, c, h * h - a * c, s0, s1);
      if (a > 0) {
        if (!real) return;
        pieces[n][0] = s0, pieces[n][1] = s1, ++n;
      } else if (!real) {
        pieces[n][0] = -INFINITY, pieces[n][1] = INFINITY, ++n;
      } else {
        pieces[n][0] = -INFINITY, pieces[n][1] = s0, ++n;
        pieces[n][0] = s1, pieces[n][1] = INFINITY, ++n;
      }
    }
    // The slab between the end discs, from the shifted origin: its heights above the base
    // plane and below the cap plane, each formed from the nearer reference so a plane
    // through the apex is met exactly where the line passes it.
    const LD zb = zc0 + fz, zcap = (ax_.height - zc0) - fz;
    // Between the end discs r(z) >= 0, so only the real nappe is left, and the solid is
    // convex: one piece survives (two only when both touch the apex; keep the longer).
    const LRay shifted(o, ray.d);
    LD bestLo = 0, bestHi = -1, bestLen = -1;
    int bestPLo = 0, bestPHi = 0;
    bool bestTieLo = false, bestTieHi = false;
    for (int i = 0; i < n; ++i) {
      LD lo = pieces[i][0], hi = pieces[i][1];
      int pLo = 0, pHi = 0;
      bool tieLo, tieHi;
      if (!clipToSlab(shifted, zb, zcap, dz, lo, hi, pLo, pHi, tieLo, tieHi) || hi - lo <= bestLen)
        continue;
      bestLo = lo, bestHi = hi, bestLen = hi - lo, bestPLo = pLo, bestPHi = pHi;
      bestTieLo = tieLo, bestTieHi = tieHi;
    }
    if (bestLen < 0) return;
    // At the apex the normal is not defined either.
    auto nearApex = [&](LD s) {
      return hasApex && maxAbs(shifted.at(s) - apex_) <= 1e-12L * (ax_.height + maxAbs(apex_));
    };
    out.push_back(
        {shift + bestLo, normalAt(shifted.at(bestLo), bestPLo), !bestTieLo && !nearApex(bestLo)});
    out.push_back(
        {shift + bestHi, normalAt(shifted.at(bestHi), bestPHi), !bestTieHi && !nearApex(bestHi)});
  }

 private:
  LVec normalAt(const LVec& p, int part) const {
    if (part == 1) return -ax_.a;
    if (part == 2) return ax_.a;
    // The gradient of x² + y² − r(z)²: (radial unit, −dr/dz) up to a positive factor.
    LVec radial = ax_.across(p - ax_.base);
    LD len = std::sqrt(glm::dot(radial, radial));
    if (!(len > 0)) return -ax_.a * std::copysign(LD(1), k_);  // the apex: along the axis
    return normalizeL(radial / len - k_ * ax_.a);
  }
  LAxis ax_;
  LD r0_, k_;
  LD zApex_ = -1;  // the apex's height above the base, or −1 for a truncated cone
  LVec apex_;
};

class RefTorusImpl final : public RefShape {
 public:
  RefTorusImpl(double R, double r) : R_(R), r_(r) {}

  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    LD dd = glm::dot(ray.d, ray.d);
    if (!(dd > 0)) return;
    LD tc = -glm::dot(ray.o, ray.d) / dd;
    LVec oc = ray.at(tc);
    LD bound = R_ + r_;
    LD o2 = glm::dot(oc, oc);
    if (o2 > bound * bound) return;  // outside the bounding sphere: no root
    // A chord of a larger sphere: its ends are outside the tube (g > 0 there).
    LD half = std::sqrt(1.21L * bound * bound - o2) / std::sqrt(dd);
    const int n = 3000;
    std::vector<LD> ts(n + 1), gs(n + 1);
    for (int i = 0; i <= n; ++i) {
      ts[i] = tc - half + 2 * half * i / n;
      gs[i] = g(ray, ts[i]);
    }
    // Breakpoints: the chord's ends and every refined critical point. g is monotonic
    // between consecutive ones, so each sign change between them brackets one root.
    std::vector<std::pair<LD, LD>> breaks = {{ts[0], gs[0]}};
    std::vector<LD> touching;
    for (int i = 1; i < n; ++i) {
      bool isMin = gs[i] < gs[i - 1] && gs[i] <= gs[i + 1];
      bool isMax = gs[i] > gs[i - 1] && gs[i] >= gs[i + 1];
      if (!isMin && !isMax) continue;
      LD t = golden(ray, ts[i - 1], ts[i + 1], isMin ? 1 : -1);
      LD gt = g(ray, t);
      breaks.push_back({t, gt});
      if (isMin && gt == 0) touching.push_back(t);
    }
    breaks.push_back({ts[n], gs[n]});
    std::vector<LD> roots = touching;
    for (LD t : touching) roots.push_back(t);  // a double root is listed twice
    for (size_t i = 0; i + 1 < breaks.size(); ++i) {
      auto [a, ga] = breaks[i];
      auto [b, gb] = breaks[i + 1];
      if ((ga < 0 && gb > 0) || (ga > 0 && gb < 0)) roots.push_back(bisect(ray, a, b, ga));
    }
    std::sort(roots.begin(), roots.end());
    for (LD t : roots) out.push_back({t, normalAt(ray.at(t))});
  }

 private:
  // The tube's distance function (ρ − R)² + y² − r²: negative inside. Its product with
  // (ρ + R)² + y² − r² (positive for a ring torus) is the quartic.
  LD g(const LRay& ray, LD t) const {
    LVec p = ray.at(t);
    LD rho = std::sqrt(p.x * p.x + p.z * p.z);
    return (rho - R_) * (rho - R_) + p.y * p.y - r_ * r_;
  }
  // The minimum (sign 1) or maximum (sign −1) of g on [a, b], to long double precision.
  LD golden(const LRay& ray, LD a, LD b, int sign) const {
    return goldenExtremum([&](LD t) { return g(ray, t); }, a, b, sign, 100);
  }
  LD bisect(const LRay& ray, LD a, LD b, LD ga) const {
    return bisectRoot([&](LD t) { return g(ray, t); }, a, b, ga);
  }
  LVec normalAt(const LVec& p) const {
    LD rho = std::sqrt(p.x * p.x + p.z * p.z);
    LVec c = rho > 0 ? LVec(p.x, 0, p.z) * (R_ / rho) : LVec(R_, 0, 0);
    return normalizeL(p - c);
  }
  LD R_, r_;
};

// The superellipsoid (x, y, z in POV-Ray's axes, poles on z): the roots of its gauge
// N(p) − 1, N = ‖(‖(|x|, |y|)‖_{2/e}, |z|)‖_{2/n}, along the line cut at the planes x = 0,
// y = 0, z = 0 (where N has kinks or cusps); on each piece N is sampled densely, its
// extrema refined by golden-section search, and every sign change between them bisected
// to the last long-double bit. The normal is the gradient of the equation's other form,
// (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n), independent of the gauge's formulas.
class RefSuperellipsoidImpl final : public RefShape {
 public:
  RefSuperellipsoidImpl(double e, double n) : e_(e), n_(n), p_(2 / e_), q_(2 / n_) {}

  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    const LD B = 1.0625L;
    LD t0 = -std::numeric_limits<LD>::infinity(), t1 = std::numeric_limits<LD>::infinity();
    for (int i = 0; i < 3; ++i) {
      if (ray.d[i] == 0) {
        if (std::abs(ray.o[i]) > B) return;
        continue;
      }
      LD a = (-B - ray.o[i]) / ray.d[i], b = (B - ray.o[i]) / ray.d[i];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a);
      t1 = std::min(t1, b);
    }
    if (!(t0 < t1)) return;
    std::vector<LD> cuts = {t0, t1};
    for (int i = 0; i < 3; ++i)
      if (ray.d[i] != 0) {
        LD t = -ray.o[i] / ray.d[i];
        if (t0 < t && t < t1) cuts.push_back(t);
      }
    std::sort(cuts.begin(), cuts.end());
    std::vector<std::pair<LD, LD>> breaks;  // monotone between consecutive ones
    std::vector<LD> touching;
    for (size_t k = 0; k + 1 < cuts.size(); ++k) {
      const LD a = cuts[k], b = cuts[k + 1];
      const int n = 600;
      std::vector<LD> ts(n + 1), gs(n + 1);
      for (int i = 0; i <= n; ++i) {
        ts[i] = i == n ? b : a + (b - a) * i / n;
        gs[i] = g(ray, ts[i]);
      }
      breaks.push_back({ts[0], gs[0]});
      // Every sample that is a local extremum of the samples, the piece's ends included
      // (an extremum just past a cut lies between the first two samples).
      for (int i = 0; i <= n; ++i) {
        const int l = std::max(i - 1, 0), r = std::min(i + 1, n);
        bool isMin = (i == 0 || gs[i] < gs[l]) && gs[i] <= gs[r] && (i > 0 || gs[i] < gs[r]);
        bool isMax = (i == 0 || gs[i] > gs[l]) && gs[i] >= gs[r] && (i > 0 || gs[i] > gs[r]);
        if (i == n) {
          isMin = gs[i] < gs[l];
          isMax = gs[i] > gs[l];
        }
        if (!isMin && !isMax) continue;
        LD t = golden(ray, ts[l], ts[r], isMin ? 1 : -1);
        LD gt = g(ray, t);
        breaks.push_back({t, gt});
        if (isMin && gt == 0) touching.push_back(t);
      }
    }
    breaks.push_back({cuts.back(), g(ray, cuts.back())});
    std::sort(breaks.begin(), breaks.end());
    std::vector<LD> roots = touching;
    for (LD t : touching) roots.push_back(t);
    for (size_t i = 0; i + 1 < breaks.size(); ++i) {
      auto [a, ga] = breaks[i];
      auto [b, gb] = breaks[i + 1];
      if ((ga < 0 && gb > 0) || (ga > 0 && gb < 0)) roots.push_back(bisect(ray, a, b, ga));
    }
    std::sort(roots.begin(), roots.end());
    for (LD t : roots) {
      LRoot r{t, LVec(0), true};
      if (!normalAt(ray.at(t), r.n)) r.normalDefined = false;
      out.push_back(r);
    }
  }

 private:
  static LD norm(LD a, LD b, LD p) {
    LD m = std::max(a, b), s = std::min(a, b);
    if (!(s > 0)) return m;
    return m * std::pow(1 + std::pow(s / m, p), 1 / p);
  }
  LD g(const LRay& ray, LD t) const {
    LVec p = ray.at(t);
    return norm(norm(std::abs(p.x), std::abs(p.y), p_), std::abs(p.z), q_) - 1;
  }
  LD golden(const LRay& ray, LD a, LD b, int sign) const {
    return goldenExtremum([&](LD t) { return g(ray, t); }, a, b, sign, 120);
  }
  LD bisect(const LRay& ray, LD a, LD b, LD ga) const {
    return bisectRoot([&](LD t) { return g(ray, t); }, a, b, ga);
  }
  // ∇((X^a + Y^a)^b + Z^c), a = 2/e, b = e/n, c = 2/n; false where it is not finite and
  // non-zero (a crease or tip of exponents above 2).
  bool normalAt(const LVec& p, LVec& n) const {
    const LD a = 2 / e_, b = e_ / n_, c = 2 / n_;
    LD X = std::abs(p.x), Y = std::abs(p.y), Z = std::abs(p.z);
    LD S = std::pow(X, a) + std::pow(Y, a);
    LD common = S > 0 ? b * std::pow(S, b - 1) * a : 0;
    LD gx = X > 0 ? common * std::pow(X, a - 1) : (a > 1 ? 0 : std::numeric_limits<LD>::infinity());
    LD gy = Y > 0 ? common * std::pow(Y, a - 1) : (a > 1 ? 0 : std::numeric_limits<LD>::infinity());
    LD gz = Z > 0 ? c * std::pow(Z, c - 1) : (c > 1 ? 0 : std::numeric_limits<LD>::infinity());
    LVec v(std::copysign(gx, p.x), std::copysign(gy, p.y), std::copysign(gz, p.z));
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return false;
    if (glm::dot(v, v) == 0) return false;
    n = normalizeL(v);
    return true;
  }

  LD e_, n_, p_, q_;
};

class RefQuadricImpl final : public RefShape {
 public:
  RefQuadricImpl(const Vec3& sq, const Vec3& mx, const Vec3& lin, double j)
      : m_(LD(sq.x), LD(mx.x) / 2, LD(mx.y) / 2, LD(mx.x) / 2, LD(sq.y), LD(mx.z) / 2, LD(mx.y) / 2,
           LD(mx.z) / 2, LD(sq.z)),
        g_(toL(lin)),
        j_(j) {}
  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    Line l = line(ray);
    LD s0, s1;
    if (l.a != 0) {
      if (!quadraticRoots(l.a, l.h, l.c, l.h * l.h - l.a * l.c, s0, s1)) return;
      for (LD s : {s0, s1}) out.push_back(rootAt(ray, l.shift + s));
    } else if (l.h != 0) {
      out.push_back(rootAt(ray, l.shift - l.c / (2 * l.h)));
    }
  }
  bool insideAtStart(const LRay& ray) const override {
    Line l = line(ray);
    if (l.a != 0) return l.a < 0;  // Q → −∞ at both ends
    if (l.h != 0) return l.h > 0;  // Q → −∞ as s → −∞
    return l.c < 0;
  }

 private:
  struct Line {
    LD shift, a, h, c;
  };
  // Q(o' + s·d) = a s² + 2h s + c, o' the line's point closest to the origin.
  Line line(const LRay& ray) const {
    LD dd = glm::dot(ray.d, ray.d);
    LD shift = dd > 0 ? -glm::dot(ray.o, ray.d) / dd : 0;
    LVec o = ray.at(shift);
    LVec md = m_ * ray.d;
    return {shift, glm::dot(ray.d, md), glm::dot(o, md) + glm::dot(g_, ray.d) / 2, value(o)};
  }
  LD value(const LVec& p) const { return glm::dot(p, m_ * p) + glm::dot(g_, p) + j_; }
  LRoot rootAt(const LRay& ray, LD t) const {
    LVec p = ray.at(t);
    LVec n = LD(2) * (m_ * p) + g_;
    bool defined = glm::dot(n, n) > 0;
    return {t, defined ? normalizeL(n) : LVec(1, 0, 0), defined};
  }
  LMat3 m_;
  LVec g_;
  LD j_;
};

class RefPolyImpl final : public RefShape {
 public:
  RefPolyImpl(int order, const std::vector<double>& c, double radius) : radius_(radius) {
    size_t index = 0;
    for (int i = order; i >= 0; --i)
      for (int j = order - i; j >= 0; --j)
        for (int k = order - i - j; k >= 0; --k) {
          const double v = c.at(index++);
          if (v != 0.0) terms_.push_back({i, j, k, v});
        }
  }
  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    LD lo, hi;
    if (!chord(ray, lo, hi)) return;
    const int n = 4000;
    std::vector<LD> ts(n + 1), gs(n + 1);
    for (int i = 0; i <= n; ++i) {
      ts[i] = lo + (hi - lo) * i / n;
      gs[i] = g(ray.at(ts[i]));
    }
    // Breakpoints: the chord's ends and every refined extremum; g is monotonic between
    // consecutive ones, so each sign change between them brackets one root.
    std::vector<std::pair<LD, LD>> breaks = {{ts[0], gs[0]}};
    std::vector<LD> roots;
    for (int i = 1; i < n; ++i) {
      bool isMin = gs[i] < gs[i - 1] && gs[i] <= gs[i + 1];
      bool isMax = gs[i] > gs[i - 1] && gs[i] >= gs[i + 1];
      if (!isMin && !isMax) continue;
      LD t = goldenExtremum([&](LD s) { return g(ray.at(s)); }, ts[i - 1], ts[i + 1],
                            isMin ? 1 : -1, 120);
      LD gt = g(ray.at(t));
      breaks.push_back({t, gt});
      if (gt == 0) roots.insert(roots.end(), {t, t});  // a double root is listed twice
    }
    breaks.push_back({ts[n], gs[n]});
    for (size_t i = 0; i + 1 < breaks.size(); ++i) {
      auto [a, ga] = breaks[i];
      auto [b, gb] = breaks[i + 1];
      if ((ga < 0 && gb > 0) || (ga > 0 && gb < 0))
        roots.push_back(bisectRoot([&](LD s) { return g(ray.at(s)); }, a, b, ga));
    }
    std::sort(roots.begin(), roots.end());
    for (LD t : roots) out.push_back({t, normalizeL(gradient(ray.at(t)))});
  }
  bool insideAtStart(const LRay& ray) const override {
    LD lo, hi;
    if (!chord(ray, lo, hi)) return g(ray.o) < 0;  // never near the surface: P keeps its sign
    return g(ray.at(lo)) < 0;
  }

 private:
  struct Term {
    int i, j, k;
    LD c;
  };
  // The line's chord of the sphere of 1.1 times the radius (outside which P keeps a sign).
  bool chord(const LRay& ray, LD& lo, LD& hi) const {
    LD dd = glm::dot(ray.d, ray.d);
    if (!(dd > 0)) return false;
    LD tc = -glm::dot(ray.o, ray.d) / dd;
    LD o2 = glm::dot(ray.at(tc), ray.at(tc)), r2 = 1.21L * radius_ * radius_;
    if (o2 >= r2) return false;
    LD half = std::sqrt((r2 - o2) / dd);
    lo = tc - half;
    hi = tc + half;
    return true;
  }
  LD g(const LVec& p) const {
    LD v = 0;
    for (const Term& t : terms_) v += t.c * ipow(p.x, t.i) * ipow(p.y, t.j) * ipow(p.z, t.k);
    return v;
  }
  LVec gradient(const LVec& p) const {
    LVec d(0);
    for (const Term& t : terms_) {
      if (t.i) d.x += t.c * t.i * ipow(p.x, t.i - 1) * ipow(p.y, t.j) * ipow(p.z, t.k);
      if (t.j) d.y += t.c * t.j * ipow(p.x, t.i) * ipow(p.y, t.j - 1) * ipow(p.z, t.k);
      if (t.k) d.z += t.c * t.k * ipow(p.x, t.i) * ipow(p.y, t.j) * ipow(p.z, t.k - 1);
    }
    return d;
  }
  static LD ipow(LD x, int k) {
    LD r = 1;
    for (int m = 0; m < k; ++m) r *= x;
    return r;
  }
  std::vector<Term> terms_;
  LD radius_;
};

class RefInstanceImpl final : public RefShape {
 public:
  RefInstanceImpl(std::shared_ptr<RefShape> inner, const Mat4& m) : inner_(std::move(inner)) {
    LMat4 w;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) w[c][r] = m[c][r];
    inv_ = glm::inverse(w);
    normal_ = glm::transpose(glm::inverse(LMat3(w)));
  }
  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    LVec o = LVec(inv_ * glm::vec<4, LD>(ray.o, 1));
    LVec d = LMat3(inv_) * ray.d;
    size_t first = out.size();
    inner_->lineRoots(LRay(o, d), out);
    for (size_t i = first; i < out.size(); ++i) out[i].n = normalizeL(normal_ * out[i].n);
  }
  bool insideAtStart(const LRay& ray) const override {
    return inner_->insideAtStart(LRay(LVec(inv_ * glm::vec<4, LD>(ray.o, 1)), LMat3(inv_) * ray.d));
  }

 private:
  std::shared_ptr<RefShape> inner_;
  LMat4 inv_;
  LMat3 normal_;
};

// The blob: the field Σ s·(1 − r²/R²)², r the distance to a sphere's centre or to a
// cylinder's segment (computed here as the distance to the clamped closest point of the
// segment, not from Lucent's three pieces), minus the threshold. The line is cut where it
// enters or leaves a component's radius and where it crosses the planes through a
// cylinder's ends (where the distance changes formula); on each cut the field is one
// quartic, sampled, its extrema refined and its sign changes bisected as for the others.
class RefBlobImpl final : public RefShape {
 public:
  RefBlobImpl(double threshold, std::vector<BlobComponent> cs)
      : T_(threshold), cs_(std::move(cs)) {}

  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    std::vector<LD> cuts;
    for (const BlobComponent& c : cs_) {
      LD R2 = (LD)c.radius * c.radius;
      LVec a = toL(c.a), b = toL(c.b);
      auto ball = [&](const LVec& ctr) {
        LVec w = ray.o - ctr;
        LD dd = glm::dot(ray.d, ray.d), tc = -glm::dot(w, ray.d) / dd;
        LVec pc = w + tc * ray.d;
        LD h2 = (R2 - glm::dot(pc, pc)) / dd;
        if (h2 > 0) {
          cuts.push_back(tc - std::sqrt(h2));
          cuts.push_back(tc + std::sqrt(h2));
        }
      };
      if (c.kind == BlobComponent::Sphere) {
        ball(a);
        continue;
      }
      ball(a);
      ball(b);
      LVec ax = b - a;
      LD len = std::sqrt(glm::dot(ax, ax));
      ax /= len;
      LD z0 = glm::dot(ray.o - a, ax), zd = glm::dot(ray.d, ax);
      LVec wp = (ray.o - a) - z0 * ax, dp = ray.d - zd * ax;
      LD dd = glm::dot(dp, dp);
      if (dd > 0) {
        LD tc = -glm::dot(wp, dp) / dd;
        LVec pc = wp + tc * dp;
        LD h2 = (R2 - glm::dot(pc, pc)) / dd;
        if (h2 > 0) {
          cuts.push_back(tc - std::sqrt(h2));
          cuts.push_back(tc + std::sqrt(h2));
        }
      }
      if (zd != 0) {
        cuts.push_back(-z0 / zd);
        cuts.push_back((len - z0) / zd);
      }
    }
    if (cuts.empty()) return;
    std::sort(cuts.begin(), cuts.end());
    std::vector<std::pair<LD, LD>> breaks;
    std::vector<LD> touching;
    for (size_t k = 0; k + 1 < cuts.size(); ++k) {
      const LD a = cuts[k], b = cuts[k + 1];
      if (!(a < b)) continue;
      const int n = 200;
      std::vector<LD> ts(n + 1), gs(n + 1);
      for (int i = 0; i <= n; ++i) {
        ts[i] = i == n ? b : a + (b - a) * i / n;
        gs[i] = g(ray, ts[i]);
      }
      breaks.push_back({ts[0], gs[0]});
      for (int i = 1; i < n; ++i) {
        bool isMin = gs[i] < gs[i - 1] && gs[i] <= gs[i + 1];
        bool isMax = gs[i] > gs[i - 1] && gs[i] >= gs[i + 1];
        if (!isMin && !isMax) continue;
        LD t = goldenExtremum([&](LD x) { return g(ray, x); }, ts[i - 1], ts[i + 1], isMax ? -1 : 1,
                              120);
        LD gt = g(ray, t);
        breaks.push_back({t, gt});
        if (isMax && gt == 0) touching.push_back(t);
      }
      // A cut is a kink of the field, not a point outside the surface: an extremum within
      // the first or last sample interval of the piece is unseen above.
      for (int i : {0, n - 1})
        for (int sign : {1, -1}) {
          const LD t = goldenExtremum([&](LD x) { return g(ray, x); }, ts[i], ts[i + 1], sign, 120);
          if (t > ts[i] && t < ts[i + 1]) breaks.push_back({t, g(ray, t)});
        }
    }
    breaks.push_back({cuts.back(), g(ray, cuts.back())});
    std::sort(breaks.begin(), breaks.end());
    std::vector<LD> roots = touching;
    for (LD t : touching) roots.push_back(t);
    for (size_t i = 0; i + 1 < breaks.size(); ++i) {
      auto [a, ga] = breaks[i];
      auto [b, gb] = breaks[i + 1];
      if ((ga < 0 && gb > 0) || (ga > 0 && gb < 0))
        roots.push_back(bisectRoot([&](LD x) { return g(ray, x); }, a, b, ga));
    }
    std::sort(roots.begin(), roots.end());
    for (LD t : roots) {
      LVec grad = gradient(ray.at(t));
      LD len = std::sqrt(glm::dot(grad, grad));
      out.push_back({t, len > 0 ? -grad / len : LVec(0), len > 0});
    }
  }

 private:
  // p minus its closest point on the component's centre or segment.
  LVec offset(const BlobComponent& c, const LVec& p) const {
    LVec a = toL(c.a);
    if (c.kind == BlobComponent::Sphere) return p - a;
    LVec ax = toL(c.b) - a;
    LD z = std::clamp(glm::dot(p - a, ax) / glm::dot(ax, ax), (LD)0, (LD)1);
    return p - (a + z * ax);
  }
  LD g(const LRay& ray, LD t) const {
    LVec p = ray.at(t);
    LD f = 0;
    for (const BlobComponent& c : cs_) {
      LVec w = offset(c, p);
      LD q = glm::dot(w, w) / ((LD)c.radius * c.radius);
      if (q < 1) f += c.strength * (1 - q) * (1 - q);
    }
    return f - T_;
  }
  LVec gradient(const LVec& p) const {
    LVec grad(0);
    for (const BlobComponent& c : cs_) {
      LVec w = offset(c, p);
      LD R2 = (LD)c.radius * c.radius, q = glm::dot(w, w) / R2;
      if (q < 1) grad += (-4 * c.strength * (1 - q) / R2) * w;
    }
    return grad;
  }
  LD T_;
  std::vector<BlobComponent> cs_;
};
}  // namespace

std::shared_ptr<RefShape> refSphere(const Vec3& c, double r) {
  return std::make_shared<RefSphereImpl>(c, r);
}
std::shared_ptr<RefShape> refBox(const Vec3& lo, const Vec3& hi) {
  return std::make_shared<RefBoxImpl>(lo, hi);
}
std::shared_ptr<RefShape> refCylinder(const Vec3& base, const Vec3& cap, double r) {
  return std::make_shared<RefCylinderImpl>(base, cap, r);
}
std::shared_ptr<RefShape> refCone(const Vec3& base, double r0, const Vec3& cap, double r1) {
  return std::make_shared<RefConeImpl>(base, r0, cap, r1);
}
std::shared_ptr<RefShape> refTorus(double R, double r) {
  return std::make_shared<RefTorusImpl>(R, r);
}
std::shared_ptr<RefShape> refSuperellipsoid(double e, double n) {
  return std::make_shared<RefSuperellipsoidImpl>(e, n);
}
std::shared_ptr<RefShape> refQuadric(const Vec3& squares, const Vec3& mixed, const Vec3& linear,
                                     double constant) {
  return std::make_shared<RefQuadricImpl>(squares, mixed, linear, constant);
}
std::shared_ptr<RefShape> refPoly(int order, const std::vector<double>& coefficients,
                                  double radius) {
  return std::make_shared<RefPolyImpl>(order, coefficients, radius);
}
std::shared_ptr<RefShape> refBlob(double threshold, const std::vector<BlobComponent>& components) {
  return std::make_shared<RefBlobImpl>(threshold, components);
}
std::shared_ptr<RefShape> refInstance(std::shared_ptr<RefShape> inner, const Mat4& m) {
  return std::make_shared<RefInstanceImpl>(std::move(inner), m);
}

}  // namespace lucent::accuracy
