// The sphere sweep's cases (docs/accuracy.md): a linear, a Catmull-Rom and a B-spline sweep
// through the same six spheres, random rays, and rays tangent to the surface moved off by
// 1e-16 to 1e-1. Each against RefSweep (long double: the balls from the textbook forms of
// the splines; the line is inside where min over the segments and u of
// |p − c(u)|² − r(u)² is below 0, that minimum by sampling u and golden-section search;
// its sign sampled along the line and every change bisected to the last bit). The
// reference shares nothing with Lucent's method (cones, the degree-10 envelope condition).
#include "accuracy_cases.h"

#include "../support/sweep_spline_weights.h"
#include "primitives/sphere_sweep.h"

#include <algorithm>
#include <cmath>

namespace lucent::accuracy {

namespace {

using S = std::vector<SweepSphere>;

class RefSweep final : public RefShape {
 public:
  RefSweep(SweepSpline spline, const S& p) : spline_(spline), p_(p) {}

  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    // The line's stretch within the spheres' reach (a generous box about them).
    LVec lo(1e30L), hi(-1e30L);
    for (const SweepSphere& s : p_)
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], (LD)s.center[a] - 2 * (LD)s.radius - 0.5L);
        hi[a] = std::max(hi[a], (LD)s.center[a] + 2 * (LD)s.radius + 0.5L);
      }
    LD t0 = -1e30L, t1 = 1e30L;
    for (int a = 0; a < 3; ++a) {
      if (ray.d[a] == 0) {
        if (ray.o[a] < lo[a] || ray.o[a] > hi[a]) return;
        continue;
      }
      LD ta = (lo[a] - ray.o[a]) / ray.d[a], tb = (hi[a] - ray.o[a]) / ray.d[a];
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
    }
    if (!(t0 < t1)) return;
    const int n = 600;
    std::vector<LD> ts(n + 1), gs(n + 1);
    for (int k = 0; k <= n; ++k) {
      ts[k] = t0 + (t1 - t0) * k / n;
      gs[k] = gauge(ray.at(ts[k]));
    }
    for (int k = 1; k <= n; ++k) {
      if ((gs[k] < 0) != (gs[k - 1] < 0)) {
        out.push_back(root(ray, ts[k - 1], ts[k], gs[k - 1] < 0));
      } else if (k < n && ((gs[k] >= 0 && gs[k] <= gs[k - 1] && gs[k] <= gs[k + 1]) ||
                           (gs[k] < 0 && gs[k] >= gs[k - 1] && gs[k] >= gs[k + 1]))) {
        // A local extreme on one side of 0: a tangent pass may cross it between the
        // samples (a dip inside, or a sliver outside between two stretches inside).
        // Golden-section search for the extreme; across 0, two roots about it.
        const LD sgn = gs[k] >= 0 ? 1 : -1;  // minimise sgn · gauge
        LD a = ts[k - 1], b = ts[k + 1];
        const LD g = 0.6180339887498948482L;
        LD x1 = b - g * (b - a), x2 = a + g * (b - a), f1 = sgn * gauge(ray.at(x1)),
           f2 = sgn * gauge(ray.at(x2));
        for (int it = 0; it < 120 && f1 >= 0 && f2 >= 0; ++it) {
          if (f1 < f2) {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - g * (b - a);
            f1 = sgn * gauge(ray.at(x1));
          } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + g * (b - a);
            f2 = sgn * gauge(ray.at(x2));
          }
        }
        const LD tm = f1 < f2 ? x1 : x2;
        if (std::min(f1, f2) < 0) {
          out.push_back(root(ray, ts[k - 1], tm, sgn < 0));
          out.push_back(root(ray, tm, ts[k + 1], sgn > 0));
        }
      }
    }
  }

 private:
  size_t segments() const { return spline_ == SweepSpline::Linear ? p_.size() - 1 : p_.size() - 3; }

  void ball(size_t i, LD u, LVec& c, LD& r) const {
    LD w[4];
    test::sweepSplineWeights(spline_, u, w);
    c = LVec(0);
    r = 0;
    for (size_t k = 0; k < 4; ++k) {
      if (w[k] == 0) continue;
      c += w[k] * toL(p_[i + k].center);
      r += w[k] * (LD)p_[i + k].radius;
    }
  }

  LD F(const LVec& p, size_t i, LD u) const {
    LVec c;
    LD r;
    ball(i, u, c, r);
    const LVec w = p - c;
    return w.x * w.x + w.y * w.y + w.z * w.z - r * r;
  }

  // min over the segments and u of F: 64 samples a segment, each local minimum among them
  // refined by golden-section search.
  LD minimum(const LVec& p, size_t& segOut, LD& uOut) const {
    LD best = 1e300L;
    const int n = 64;
    for (size_t i = 0; i < segments(); ++i) {
      LD v[n + 1];
      for (int k = 0; k <= n; ++k) v[k] = F(p, i, (LD)k / n);
      for (int k = 0; k <= n; ++k) {
        if ((k > 0 && v[k - 1] < v[k]) || (k < n && v[k + 1] < v[k])) continue;
        LD a = (LD)std::max(0, k - 1) / n, b = (LD)std::min(n, k + 1) / n;
        const LD g = 0.6180339887498948482L;
        LD x1 = b - g * (b - a), x2 = a + g * (b - a), f1 = F(p, i, x1), f2 = F(p, i, x2);
        for (int it = 0; it < 90; ++it) {
          if (f1 < f2) {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - g * (b - a);
            f1 = F(p, i, x1);
          } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + g * (b - a);
            f2 = F(p, i, x2);
          }
        }
        for (LD u : {a, b, (LD)k / n}) {
          const LD f = F(p, i, u);
          if (f < best) {
            best = f;
            segOut = i;
            uOut = u;
          }
        }
      }
    }
    return best;
  }

  // The sign change of the gauge in (a, b), bisected to the last bit; its outward normal
  // is the minimising ball's.
  LRoot root(const LRay& ray, LD a, LD b, bool negA) const {
    for (int it = 0; it < 200; ++it) {
      const LD mid = 0.5L * (a + b);
      if (mid == a || mid == b) break;
      ((gauge(ray.at(mid)) < 0) == negA ? a : b) = mid;
    }
    const LD tr = 0.5L * (a + b);
    const LVec p = ray.at(tr);
    size_t seg = 0;
    LD u = 0;
    minimum(p, seg, u);
    LVec c;
    LD r;
    ball(seg, u, c, r);
    LVec nrm = p - c;
    const LD len = std::sqrt(nrm.x * nrm.x + nrm.y * nrm.y + nrm.z * nrm.z);
    nrm = len > 0 ? nrm / len : LVec(0, 1, 0);
    // No normal where the ball has no size (a cone's point).
    return {tr, nrm, std::abs(r) > 1e-9L};
  }

  LD gauge(const LVec& p) const {
    size_t seg;
    LD u;
    return minimum(p, seg, u);
  }

  SweepSpline spline_;
  S p_;
};

CaseResult newCase(const std::string& name, double boundRelT, double boundAngle) {
  return makeCase("Sphere sweeps", name, boundRelT, boundAngle);
}

}  // namespace

std::vector<CaseResult> sweepCases(double effort) {
  const S wiggle = {{Vec3(-1, -0.6, 0), 0.1},  {Vec3(-0.6, 0, 0), 0.3},
                    {Vec3(0, 0.4, 0.2), 0.2},  {Vec3(0.6, -0.1, 0), 0.35},
                    {Vec3(1, 0.5, -0.3), 0.1}, {Vec3(1.3, 0.2, 0.4), 0}};
  const double size = 3.0;
  const int n = rayCount(150, effort);
  // Bounds: measured maxima with a margin (docs/accuracy.md).
  // The normals' bound is the reference's: its ball's u comes from golden-section search,
  // good to about the square root of long double's precision.
  const double kT = 1e-13, kN = 1e-8;
  std::vector<CaseResult> out;
  const struct {
    SweepSpline spline;
    const char* name;
  } kinds[] = {{SweepSpline::Linear, "linear"},
               {SweepSpline::Cubic, "cubic (Catmull-Rom)"},
               {SweepSpline::BSpline, "b-spline"}};
  uint64_t seed = 4100;
  for (const auto& kind : kinds) {
    const SphereSweep shape(kind.spline, wiggle);
    const RefSweep ref(kind.spline, wiggle);
    const AABB b = shape.bounds();
    {
      Rng rng(seed++);
      CaseResult r = newCase(std::string(kind.name) + ": random rays", kT, kN);
      for (int i = 0; i < n; ++i) {
        const Vec3 target(uniform(rng, b.lo.x, b.hi.x), uniform(rng, b.lo.y, b.hi.y),
                          uniform(rng, b.lo.z, b.hi.z));
        const Vec3 o = b.center() + 4.0 * randomUnit(rng);
        measureRay(r, shape, ref, Ray(o, (target - o) * uniform(rng, 0.5, 2.0)), size);
      }
      out.push_back(std::move(r));
    }
    {
      // Tangent rays: at a surface point Lucent finds, along a direction across its normal,
      // moved off along the normal (the reference judges the ray, whatever built it).
      Rng rng(seed++);
      CaseResult r = newCase(
          std::string(kind.name) + ": tangent to the surface, 1e-16 to 1e-1 inside or outside", kT,
          kN);
      for (int i = 0; i < n;) {
        const Vec3 target(uniform(rng, b.lo.x, b.hi.x), uniform(rng, b.lo.y, b.hi.y),
                          uniform(rng, b.lo.z, b.hi.z));
        const Vec3 o = b.center() + 4.0 * randomUnit(rng);
        const Ray probe(o, target - o);
        Hit h;
        if (!shape.intersect(probe, h)) continue;
        const SurfaceInfo si = shape.surface(probe, h);
        const Vec3 w = randomPerpendicular(rng, si.ng);
        const double side = rng() % 2 ? 1.0 : -1.0;
        const Vec3 q = si.p + side * logUniform(rng, -16.0, -1.0) * si.ng;
        measureRay(r, shape, ref, Ray(q - uniform(rng, 3.0, 5.0) * w, w * uniform(rng, 0.5, 2.0)),
                   size);
        ++i;
      }
      out.push_back(std::move(r));
    }
  }
  return out;
}

}  // namespace lucent::accuracy
