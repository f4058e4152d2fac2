// The sor's hard cases (docs/accuracy.md): a vase of four segments, random rays, rays
// tangent to its silhouette (moved off by 1e-16 to 1e-1), rays along and parallel to the
// axis, rays through the rims of its caps and a joint's circle; a bulb closing at the axis, rays
// through its poles. Each against RefSor (long double: POV-Ray's Hermite cubic per segment; along
// the line g = x² + z² − r²(y) on each segment's heights, split at g's critical points, every sign
// change bisected to the last bit; the caps where the line meets them inside their rims).
#include "accuracy_cases.h"

#include "primitives/sor.h"

#include <algorithm>
#include <cmath>

namespace lucent::accuracy {

namespace {

using V = std::vector<Vec2>;

class RefSor final : public RefShape {
 public:
  explicit RefSor(const V& P) {
    for (size_t i = 0; i + 3 < P.size(); ++i) {
      const LD x0 = P[i].x, x1 = P[i + 1].x, x2 = P[i + 2].x, x3 = P[i + 3].x;
      const LD y0 = P[i].y, y1 = P[i + 1].y, y2 = P[i + 2].y, y3 = P[i + 3].y;
      const LD h = y2 - y1, F0 = x1 * x1, F1 = x2 * x2;
      const LD D0 = 2 * x1 * (x2 - x0) / (y2 - y0), D1 = 2 * x2 * (x3 - x1) / (y3 - y1),
               q = (F1 - F0) / h;
      seg_.push_back({(D0 + D1 - 2 * q) / (h * h), (3 * q - 2 * D0 - D1) / h, D0, F0, y1, y2});
    }
    bottom_ = (LD)P[1].x * P[1].x;
    top_ = (LD)P[P.size() - 2].x * P[P.size() - 2].x;
  }

  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    std::vector<LRoot> roots;
    const LD dy = ray.d.y;
    for (const Seg& s : seg_) {
      LD ta, tb;
      if (dy != 0) {
        ta = (s.y1 - ray.o.y) / dy;
        tb = (s.y2 - ray.o.y) / dy;
        if (ta > tb) std::swap(ta, tb);
      } else {
        if (!(ray.o.y >= s.y1 && ray.o.y < s.y2)) continue;
        const LD far = 100 / std::sqrt(ray.d.x * ray.d.x + ray.d.z * ray.d.z) + std::abs(ray.o.x) +
                       std::abs(ray.o.z);
        ta = -far * 1e3L;
        tb = far * 1e3L;
      }
      addSegment(s, ray, ta, tb, roots);
    }
    if (dy != 0) {
      const LD t1 = (seg_.front().y1 - ray.o.y) / dy, t2 = (seg_.back().y2 - ray.o.y) / dy;
      // On a rim (to 1e-12) the cap's and the side's normals are both right.
      if (rho2(ray, t1) < bottom_)
        roots.push_back({t1, LVec(0, -1, 0), bottom_ - rho2(ray, t1) > 1e-12L});
      if (rho2(ray, t2) < top_) roots.push_back({t2, LVec(0, 1, 0), top_ - rho2(ray, t2) > 1e-12L});
    }
    std::sort(roots.begin(), roots.end(), [](const LRoot& a, const LRoot& b) { return a.t < b.t; });
    for (size_t i = 0; i < roots.size(); ++i) {
      const LD dn = roots[i].n.x * ray.d.x + roots[i].n.y * ray.d.y + roots[i].n.z * ray.d.z;
      if ((dn < 0) != (i % 2 == 0)) roots[i].n = -roots[i].n;
      out.push_back(roots[i]);
    }
  }

 private:
  struct Seg {
    LD a, b, c, e, y1, y2;  // r² = ((a·w + b)·w + c)·w + e, w = y − y1
  };
  static LD rho2(const LRay& r, LD t) {
    const LD x = r.o.x + t * r.d.x, z = r.o.z + t * r.d.z;
    return x * x + z * z;
  }
  static LD g(const Seg& s, const LRay& r, LD t) {
    const LD w = (r.o.y - s.y1) + t * r.d.y;
    return rho2(r, t) - (((s.a * w + s.b) * w + s.c) * w + s.e);
  }
  // The roots of g on (ta, tb]: g's critical points from its derivative (a quadratic in t,
  // expanded in long double), each monotone piece with a sign change bisected.
  void addSegment(const Seg& s, const LRay& r, LD ta, LD tb, std::vector<LRoot>& out) const {
    const LD W = r.o.y - s.y1, dy = r.d.y;
    const LD rr = r.d.x * r.d.x + r.d.z * r.d.z, m = r.o.x * r.d.x + r.o.z * r.d.z;
    // g'(t) = q2·t² + q1·t + q0
    const LD q2 = -3 * s.a * dy * dy * dy, q1 = 2 * (rr - dy * dy * (3 * s.a * W + s.b)),
             q0 = 2 * m - dy * ((3 * s.a * W + 2 * s.b) * W + s.c);
    std::vector<LD> pts = {ta};
    if (q2 != 0) {
      const LD disc = q1 * q1 - 4 * q2 * q0;
      if (disc >= 0) {
        const LD sq = std::sqrt(disc), qq = -0.5L * (q1 + (q1 < 0 ? -sq : sq));
        for (LD c : {qq / q2, qq != 0 ? q0 / qq : LD(0)})
          if (c > ta && c < tb) pts.push_back(c);
      }
    } else if (q1 != 0) {
      const LD c = -q0 / q1;
      if (c > ta && c < tb) pts.push_back(c);
    }
    pts.push_back(tb);
    std::sort(pts.begin(), pts.end());
    for (size_t k = 0; k + 1 < pts.size(); ++k) {
      LD lo = pts[k], hi = pts[k + 1];
      const LD glo = g(s, r, lo), ghi = g(s, r, hi);
      if (!((glo < 0) != (ghi < 0))) continue;
      // A sign change at the segment's upper end belongs to the next segment (or the cap).
      if (k + 2 == pts.size() && ghi == 0) continue;
      const bool negLo = glo < 0;
      for (int it = 0; it < 200; ++it) {
        const LD mid = 0.5L * (lo + hi);
        if (mid == lo || mid == hi) break;
        ((g(s, r, mid) < 0) == negLo ? lo : hi) = mid;
      }
      const LD t = 0.5L * (lo + hi);
      const LVec p = r.at(t);
      const LD w = std::clamp((r.o.y - s.y1) + t * dy, LD(0), s.y2 - s.y1);
      LVec n(p.x, -0.5L * ((3 * s.a * w + 2 * s.b) * w + s.c), p.z);
      const LD len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
      // No normal at a rim (either face's is right) or at a pole, where the curve meets the
      // axis with r² of zero slope (a cone's apex).
      const bool rim =
          std::abs(p.y - seg_.front().y1) < 1e-12L || std::abs(p.y - seg_.back().y2) < 1e-12L;
      const bool pole = p.x * p.x + p.z * p.z < 1e-12L;
      out.push_back({t, len > 0 ? n / len : LVec(0, 1, 0), len > 0 && !rim && !pole});
    }
  }

  std::vector<Seg> seg_;
  LD bottom_, top_;
};

CaseResult newCase(const std::string& name, double boundRelT, double boundAngle) {
  return makeCase("Surfaces of revolution", name, boundRelT, boundAngle);
}

}  // namespace

std::vector<CaseResult> sorCases(double effort) {
  const V vase = {{0, -0.5}, {0.6, 0}, {0.9, 0.4}, {0.4, 1}, {0.5, 1.4}, {0.7, 1.6}, {0.8, 1.8}};
  const V bulb = {{0.5, -0.5}, {0, 0}, {0.8, 0.5}, {0, 1}, {0.5, 1.5}};
  const Sor sv(vase, false), sb(bulb, false);
  const RefSor rv(vase), rb(bulb);
  const double size = 2.0;
  const int n = rayCount(1200, effort);
  // Bounds: measured maxima with a margin (docs/accuracy.md).
  const double kT = 1e-13, kN = 1e-12;
  std::vector<CaseResult> out;
  {
    Rng rng(2101);
    CaseResult r = newCase("vase: random rays", kT, kN);
    for (int i = 0; i < n; ++i) {
      Vec3 o = Vec3(0, 0.8, 0) + 3.0 * randomUnit(rng);
      Vec3 target(uniform(rng, -0.9, 0.9), uniform(rng, 0, 1.6), uniform(rng, -0.9, 0.9));
      measureRay(r, sv, rv, Ray(o, (target - o) * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r));
  }
  {
    Rng rng(2102);
    CaseResult r =
        newCase("vase: tangent to the silhouette, 1e-16 to 1e-1 inside or outside", kT, kN);
    for (int i = 0; i < n; ++i) {
      const double y = uniform(rng, 0.02, 1.58), phi = uniform(rng, 0, 2 * kPi);
      const double r2 = sv.radiusSquaredAt(y), rho = std::sqrt(r2);
      const double e = 1e-7;  // the slope of r² by a central difference: only to build rays
      const double slope = (sv.radiusSquaredAt(y + e) - sv.radiusSquaredAt(y - e)) / (2 * e);
      const Vec3 p(rho * std::cos(phi), y, rho * std::sin(phi));
      const Vec3 nrm = glm::normalize(Vec3(p.x, -0.5 * slope, p.z));
      const Vec3 w = randomPerpendicular(rng, nrm);
      const double side = rng() % 2 ? 1.0 : -1.0;
      const Vec3 q = p + side * logUniform(rng, -16.0, -1.0) * nrm;
      measureRay(r, sv, rv, Ray(q - uniform(rng, 2.0, 4.0) * w, w * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r));
  }
  {
    Rng rng(2103);
    CaseResult r =
        newCase("vase: along the axis and parallel to it (exactly, and tilted by 1e-9)", kT, kN);
    for (int i = 0; i < n; ++i) {
      const double rho = i % 5 == 0 ? 0.0 : uniform(rng, 0.0, 0.95), phi = uniform(rng, 0, 2 * kPi);
      const double tilt = (i / 2) % 2 ? 1e-9 : 0.0, up = i % 2 ? 1.0 : -1.0;
      const Vec3 q(rho * std::cos(phi), 0.8, rho * std::sin(phi));
      const Vec3 d(tilt * std::cos(3 * phi), up, tilt * std::sin(3 * phi));
      measureRay(r, sv, rv, Ray(q - 2.5 * d, d * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r));
  }
  {
    Rng rng(2104);
    CaseResult r = newCase(
        "vase: through the caps' rims and a joint's circle, 1e-16 to 1e-1 off in radius and height",
        kT, kN);
    for (int i = 0; i < n; ++i) {
      // The bottom rim (0.6 at y = 0), the top rim (0.7 at 1.6), the joint at (0.5, 1.4).
      const int which = i % 3;
      const double rim = which == 0   ? 0.6
                         : which == 1 ? 0.7
                                      : 0.5,
                   h = which == 0   ? 0.0
                       : which == 1 ? 1.6
                                    : 1.4;
      const double phi = uniform(rng, 0, 2 * kPi);
      const double dr = (rng() % 3 == 0 ? 0.0 : (rng() % 2 ? 1 : -1) * logUniform(rng, -16, -1));
      const double dh = (rng() % 3 == 0 ? 0.0 : (rng() % 2 ? 1 : -1) * logUniform(rng, -16, -1));
      const Vec3 q((rim + dr) * std::cos(phi), h + dh, (rim + dr) * std::sin(phi));
      const Vec3 d = randomUnit(rng);
      measureRay(r, sv, rv, Ray(q - 2.5 * d, d * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r));
  }
  {
    Rng rng(2105);
    // At a pole both x² + z² and r² vanish quadratically along the ray: g has a double root
    // there, which the cubic's rounding moves by about the square root of its error (1e-8);
    // Newton steps on g from the pole's end of the segment bring it to about 2e-10, not to
    // the last bits (docs/accuracy.md).
    CaseResult r = newCase("bulb closing at the axis: rays through its poles", 1e-9, kN);
    for (int i = 0; i < n; ++i) {
      const Vec3 pole(0.0, i % 2 ? 1.0 : 0.0, 0.0);
      const Vec3 d = randomUnit(rng);
      measureRay(r, sb, rb, Ray(pole - 2.5 * d, d * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace lucent::accuracy
