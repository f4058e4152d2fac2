// The lathe's hard cases (docs/accuracy.md): a Bézier vase and a linear goblet, random
// rays, rays tangent to the silhouette, rays through the axis and rays grazing the rims
// (the circles where two pieces meet), each against a long-double reference.
//
// The reference: the curve as cubic Bézier pieces in long double (a linear piece is its
// segment written as a cubic), each cut at the zeros of y'(s) into parts along which y is
// monotone. On such a part the point of the line at height y(t) lies at distance ρ(t) from
// the axis, and the curve at x(s(y)), s(y) found by bisection; h(t) = ρ(t)² − x(s(y(t)))² is
// sampled over the line's stretch within the part's heights, its extrema refined by
// golden-section search and every sign change bisected to the last bit, so a tangent ray is
// caught at its extremum. A horizontal piece is an annulus (the plane y = const between its
// radii). The open ends are closed by discs to the axis, as Lucent closes them
// (primitives/lathe.h). The formulation shares nothing with the lathe's own (which solves a
// polynomial in s per piece and polishes its roots by Newton steps).
#include "accuracy_cases.h"
#include "accuracy_roots.h"

#include "primitives/lathe.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lucent::accuracy {

namespace {

using LVec2 = glm::vec<2, long double>;
using Bezier = std::array<LVec2, 4>;

LVec2 toL2(const Vec2& v) { return LVec2(v.x, v.y); }

struct Disc {
  double y, radius;
};

class RefLathe final : public RefShape {
 public:
  RefLathe(const std::vector<Bezier>& pieces, std::vector<Disc> discs) : discs_(std::move(discs)) {
    for (const Bezier& b : pieces) {
      for (const LVec2& p : b) xMax_ = std::max(xMax_, std::abs(p.x));
      // y'(s) = 3[(1−s)²(y1−y0) + 2s(1−s)(y2−y1) + s²(y3−y2)]: a quadratic A s² + B s + C.
      const LD a0 = b[1].y - b[0].y, a1 = b[2].y - b[1].y, a2 = b[3].y - b[2].y;
      const LD A = a0 - 2 * a1 + a2, B = 2 * (a1 - a0), C = a0;
      if (A == 0 && B == 0 && C == 0) {  // flat: an annulus
        annuli_.push_back({b[0].y, std::min(b[0].x, b[3].x), std::max(b[0].x, b[3].x)});
        continue;
      }
      std::vector<LD> cuts = {0};
      if (A != 0) {
        const LD disc = B * B - 4 * A * C;
        if (disc > 0)
          for (LD r : {(-B - std::sqrt(disc)) / (2 * A), (-B + std::sqrt(disc)) / (2 * A)})
            if (r > 0 && r < 1) cuts.push_back(r);
      } else if (B != 0 && -C / B > 0 && -C / B < 1) {
        cuts.push_back(-C / B);
      }
      cuts.push_back(1);
      std::sort(cuts.begin(), cuts.end());
      for (size_t i = 0; i + 1 < cuts.size(); ++i) parts_.push_back({b, cuts[i], cuts[i + 1]});
    }
  }

  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    std::vector<LRoot> roots;
    // The axis itself (ρ ≡ 0) meets the surface where the curve touches the axis; at any
    // other height it is inside or outside throughout.
    const bool alongAxis = ray.d.x == 0 && ray.d.z == 0 && ray.o.x == 0 && ray.o.z == 0;
    if (alongAxis) {
      for (const Part& part : parts_)
        for (LD s : {part.s0, part.s1})
          if (at(part.b, s).x == 0 && (s == 0 || s == 1)) axisPoints_.push_back(at(part.b, s).y);
      std::sort(axisPoints_.begin(), axisPoints_.end());
      axisPoints_.erase(std::unique(axisPoints_.begin(), axisPoints_.end()), axisPoints_.end());
      for (LD y : axisPoints_) roots.push_back({(y - ray.o.y) / ray.d.y, LVec(0, 1, 0)});
      axisPoints_.clear();
    } else {
      for (const Part& part : parts_) partRoots(part, ray, roots);
    }
    for (const Annulus& a : annuli_) planeRoot(ray, a.y, a.r0, a.r1, roots);
    for (const Disc& d : discs_) planeRoot(ray, d.y, 0, d.radius, roots);
    std::sort(roots.begin(), roots.end(), [](const LRoot& a, const LRoot& b) { return a.t < b.t; });
    // Outward: against the line where it enters (even places), along it where it leaves.
    for (size_t i = 0; i < roots.size(); ++i) {
      const LD dn = glm::dot(roots[i].n, ray.d);
      if ((dn < 0) != (i % 2 == 0)) roots[i].n = -roots[i].n;
      out.push_back(roots[i]);
    }
  }

 private:
  struct Part {
    Bezier b;
    LD s0, s1;  // y is monotone on [s0, s1]
  };
  struct Annulus {
    LD y, r0, r1;
  };

  static LVec2 at(const Bezier& b, LD s) {
    const LD u = 1 - s;
    return u * u * u * b[0] + 3 * u * u * s * b[1] + 3 * u * s * s * b[2] + s * s * s * b[3];
  }
  static LVec2 slope(const Bezier& b, LD s) {
    const LD u = 1 - s;
    return 3.0L * (u * u * (b[1] - b[0]) + 2 * u * s * (b[2] - b[1]) + s * s * (b[3] - b[2]));
  }
  // The s in [s0, s1] where y(s) = y (y within the part's heights), by bisection.
  static LD sAt(const Part& p, LD y) {
    LD a = p.s0, b = p.s1;
    const bool rising = at(p.b, b).y > at(p.b, a).y;
    for (int i = 0; i < 200; ++i) {
      const LD m = (a + b) / 2;
      if (m == a || m == b) break;
      ((at(p.b, m).y < y) == rising ? a : b) = m;
    }
    return (a + b) / 2;
  }

  void partRoots(const Part& p, const LRay& ray, std::vector<LRoot>& out) const {
    const LD ya = at(p.b, p.s0).y, yb = at(p.b, p.s1).y;
    const LD ylo = std::min(ya, yb), yhi = std::max(ya, yb);
    // The stretch of the line within the part's heights and within 1.1 times the curve's
    // largest radius of the axis (the ends of the latter are outside: h > 0 there).
    LD lo = -std::numeric_limits<LD>::infinity(), hi = std::numeric_limits<LD>::infinity();
    if (ray.d.y != 0) {
      LD t0 = (ylo - ray.o.y) / ray.d.y, t1 = (yhi - ray.o.y) / ray.d.y;
      lo = std::min(t0, t1), hi = std::max(t0, t1);
    } else if (!(ray.o.y >= ylo && ray.o.y <= yhi)) {
      return;
    }
    const LD dd = ray.d.x * ray.d.x + ray.d.z * ray.d.z;
    const LD R = 1.1L * xMax_;
    if (dd > 0) {
      const LD tc = -(ray.o.x * ray.d.x + ray.o.z * ray.d.z) / dd;
      const LD cx = ray.o.x + tc * ray.d.x, cz = ray.o.z + tc * ray.d.z;
      const LD rest = R * R - cx * cx - cz * cz;
      if (rest <= 0) return;
      const LD half = std::sqrt(rest / dd);
      lo = std::max(lo, tc - half), hi = std::min(hi, tc + half);
    } else if (ray.o.x * ray.o.x + ray.o.z * ray.o.z >= R * R) {
      return;
    }
    if (!(lo < hi)) return;
    auto h = [&](LD t) {
      const LVec q = ray.at(t);
      const LD y = std::clamp(q.y, ylo, yhi);
      const LD x = at(p.b, sAt(p, y)).x;
      return q.x * q.x + q.z * q.z - x * x;
    };
    const int n = 400;
    std::vector<LD> ts(n + 1), hs(n + 1);
    for (int i = 0; i <= n; ++i) {
      ts[i] = lo + (hi - lo) * i / n;
      hs[i] = h(ts[i]);
    }
    // Breakpoints: the stretch's ends and every refined extremum; h is monotone between
    // consecutive ones, so each sign change between them brackets one root.
    std::vector<std::pair<LD, LD>> breaks = {{ts[0], hs[0]}};
    std::vector<LD> found;
    for (int i = 1; i < n; ++i) {
      const bool isMin = hs[i] < hs[i - 1] && hs[i] <= hs[i + 1];
      const bool isMax = hs[i] > hs[i - 1] && hs[i] >= hs[i + 1];
      if (!isMin && !isMax) continue;
      const LD t = goldenExtremum(h, ts[i - 1], ts[i + 1], isMin ? 1 : -1, 100);
      const LD ht = h(t);
      breaks.push_back({t, ht});
      if (isMin && ht == 0) found.insert(found.end(), {t, t});  // a double root, twice
    }
    breaks.push_back({ts[n], hs[n]});
    // The stretch's ends are the part's end heights, not points outside the surface: a dip
    // of h within the first or last sample interval has its extremum there, unseen above.
    for (int i : {0, n - 1})
      for (int sign : {1, -1}) {
        const LD t = goldenExtremum(h, ts[i], ts[i + 1], sign, 100);
        if (t > ts[i] && t < ts[i + 1]) breaks.push_back({t, h(t)});
      }
    std::sort(breaks.begin(), breaks.end());
    for (size_t i = 0; i + 1 < breaks.size(); ++i) {
      auto [a, ha] = breaks[i];
      auto [b, hb] = breaks[i + 1];
      if ((ha < 0 && hb > 0) || (ha > 0 && hb < 0)) found.push_back(bisectRoot(h, a, b, ha));
    }
    for (LD t : found) {
      // A root at the stretch's end belongs to the neighbouring part (half-open heights).
      const LVec q = ray.at(t);
      if (ray.d.y != 0 && q.y >= yhi && yhi != ylo) continue;
      const LVec2 tan = slope(p.b, sAt(p, std::clamp(q.y, ylo, yhi)));
      const LD rho = std::sqrt(q.x * q.x + q.z * q.z);
      const LVec n3 = rho > 0 ? LVec(tan.y * q.x / rho, -tan.x, tan.y * q.z / rho) : LVec(0, 1, 0);
      // At a rim (within 1e-12 of the part's end heights) the normal of either side is right.
      const bool rim = std::abs(q.y - ylo) <= 1e-12L || std::abs(q.y - yhi) <= 1e-12L;
      out.push_back({t, n3 / std::sqrt(glm::dot(n3, n3)), !rim});
    }
  }

  static void planeRoot(const LRay& ray, LD y, LD r0, LD r1, std::vector<LRoot>& out) {
    if (ray.d.y == 0) return;
    const LD t = (y - ray.o.y) / ray.d.y;
    const LVec q = ray.at(t);
    const LD rho2 = q.x * q.x + q.z * q.z;
    if (!(rho2 >= r0 * r0 && rho2 < r1 * r1)) return;
    const LD rho = std::sqrt(rho2);
    const bool rim = std::abs(rho - r1) <= 1e-12L || (r0 > 0 && std::abs(rho - r0) <= 1e-12L);
    out.push_back({t, LVec(0, 1, 0), !rim});
  }

  std::vector<Part> parts_;
  std::vector<Annulus> annuli_;
  std::vector<Disc> discs_;
  LD xMax_ = 0;
  mutable std::vector<LD> axisPoints_;
};

// Bounds as the prism's: 1e-14 for t and 1e-12 for the normal away from grazing (measured
// at most 6.8e-16 and 6.8e-15), except at the rims: a root found up to 1e-9 in s beyond a
// piece's end (lathe.cpp's slack) takes the end's normal, 2e-9 off there (measured).
CaseResult newCase(const std::string& name, double boundAngle = 1e-12) {
  return makeCase("Lathes", name, 1e-14, boundAngle);
}

// A ray through `target` from a random direction about 3 units away.
Ray rayThrough(Rng& rng, const Vec3& target) {
  const Vec3 o = target + 3.0 * randomUnit(rng);
  return Ray(o, (target - o) * uniform(rng, 0.5, 2.0));
}

}  // namespace

std::vector<CaseResult> latheCases(double effort) {
  // A Bézier vase: two pieces from the axis at the foot to an open mouth at y = 1.5 (closed
  // by a disc of radius 0.5), its waist pinched.
  const std::vector<Vec2> vasePoints = {{0, 0},     {0.9, 0},   {0.9, 0.3}, {0.6, 0.6},
                                        {0.6, 0.6}, {0.3, 0.9}, {0.7, 1.2}, {0.5, 1.5}};
  std::vector<Bezier> vasePieces;
  for (size_t i = 0; i < vasePoints.size(); i += 4)
    vasePieces.push_back({toL2(vasePoints[i]), toL2(vasePoints[i + 1]), toL2(vasePoints[i + 2]),
                          toL2(vasePoints[i + 3])});
  // A linear goblet: a foot (a disc from the axis, a short cylinder), a stem, a cup whose
  // rim turns back inside and ends on the axis; every segment a cone, cylinder or annulus.
  const std::vector<Vec2> gobletPoints = {{0, 0},       {0.8, 0},    {0.8, 0.1},
                                          {0.15, 0.2},  {0.15, 0.9}, {0.7, 1.4},
                                          {0.65, 1.45}, {0.1, 1.0},  {0, 1.0}};
  std::vector<Bezier> gobletPieces;
  for (size_t i = 0; i + 1 < gobletPoints.size(); ++i) {
    const LVec2 a = toL2(gobletPoints[i]), b = toL2(gobletPoints[i + 1]);
    gobletPieces.push_back({a, a + (b - a) / 3.0L, a + 2.0L * (b - a) / 3.0L, b});
  }
  const Lathe vase(LatheSpline::Bezier, vasePoints), goblet(LatheSpline::Linear, gobletPoints);
  const RefLathe vaseRef(vasePieces, {{1.5, 0.5}}), gobletRef(gobletPieces, {});
  struct Shape2 {
    const char* name;
    const Lathe& lathe;
    const RefLathe& ref;
    const std::vector<Bezier>& pieces;
    double height;
  };
  const Shape2 shapes[] = {{"Bézier vase", vase, vaseRef, vasePieces, 1.5},
                           {"linear goblet", goblet, gobletRef, gobletPieces, 1.45}};
  const double size = 3.0;
  const int n = rayCount(400, effort);
  std::vector<CaseResult> out;
  uint64_t seed = 2101;
  for (const Shape2& sh : shapes) {
    auto surfacePoint = [&](Rng& rng, Vec3& p, Vec3& normal) {
      const Bezier& b = sh.pieces[size_t(rng() % sh.pieces.size())];
      const LD s = uniform(rng, 0.02, 0.98), u = 1 - s;
      const LVec2 q =
          u * u * u * b[0] + 3 * u * u * s * b[1] + 3 * u * s * s * b[2] + s * s * s * b[3];
      const LVec2 tan =
          3.0L * (u * u * (b[1] - b[0]) + 2 * u * s * (b[2] - b[1]) + s * s * (b[3] - b[2]));
      const double phi = uniform(rng, 0, 2 * kPi);
      p = Vec3(double(q.x) * std::cos(phi), double(q.y), double(q.x) * std::sin(phi));
      normal = glm::normalize(
          Vec3(double(tan.y) * std::cos(phi), -double(tan.x), double(tan.y) * std::sin(phi)));
    };
    {
      Rng rng(seed++);
      CaseResult r = newCase(std::string(sh.name) + ": random rays");
      for (int i = 0; i < n; ++i) {
        const Vec3 target(uniform(rng, -0.9, 0.9), uniform(rng, 0, sh.height),
                          uniform(rng, -0.9, 0.9));
        measureRay(r, sh.lathe, sh.ref, rayThrough(rng, target), size);
      }
      out.push_back(std::move(r));
    }
    {
      // In the tangent plane at a random surface point, moved 1e-16 to 1e-1 along the
      // normal (inside or outside): the silhouette's tangents and near misses.
      Rng rng(seed++);
      CaseResult r = newCase(std::string(sh.name) +
                             ": tangent to the silhouette, 1e-16 to 1e-1 inside or outside");
      for (int i = 0; i < n; ++i) {
        Vec3 p, normal;
        surfacePoint(rng, p, normal);
        const double off = (rng() % 2 ? 1 : -1) * logUniform(rng, -16, -1);
        const Vec3 w = randomPerpendicular(rng, normal);
        const Vec3 q = p + off * normal;
        measureRay(r, sh.lathe, sh.ref, Ray(q - 3.0 * w, w * uniform(rng, 0.5, 2.0)), size);
      }
      out.push_back(std::move(r));
    }
    {
      // Through a point of the axis, from every direction (horizontal ones included).
      Rng rng(seed++);
      CaseResult r = newCase(std::string(sh.name) + ": through the axis");
      for (int i = 0; i < n; ++i) {
        const Vec3 target(0.0, uniform(rng, -0.1, sh.height + 0.1), 0.0);
        Vec3 d = randomUnit(rng);
        if (i % 4 == 0) d.y = 0.0;
        if (i % 4 == 1) d = Vec3(0.0, 1.0, 0.0);  // along the axis itself
        const Vec3 o = target - 3.0 * d;
        measureRay(r, sh.lathe, sh.ref, Ray(o, d * uniform(rng, 0.5, 2.0)), size);
      }
      out.push_back(std::move(r));
    }
    {
      // Aimed at the rims where pieces meet (and the curve's ends), 1e-16 to 1e-1 off.
      Rng rng(seed++);
      CaseResult r = newCase(
          std::string(sh.name) + ": at the rims where pieces meet, 1e-16 to 1e-1 off", 1e-8);
      for (int i = 0; i < n; ++i) {
        const Bezier& b = sh.pieces[size_t(rng() % sh.pieces.size())];
        const LVec2 q = rng() % 2 ? b[0] : b[3];
        const double phi = uniform(rng, 0, 2 * kPi);
        Vec3 target(double(q.x) * std::cos(phi), double(q.y), double(q.x) * std::sin(phi));
        target += (rng() % 2 ? 1 : -1) * logUniform(rng, -16, -1) * randomUnit(rng);
        measureRay(r, sh.lathe, sh.ref, rayThrough(rng, target), size);
      }
      out.push_back(std::move(r));
    }
  }
  return out;
}

}  // namespace lucent::accuracy
