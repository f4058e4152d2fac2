#include "isosurface.h"

#include "search_container.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucent {

namespace {

// Halvings at most: 2^-100 of the container's span is far below any accuracy in doubles.
constexpr int kMaxDepth = 100;
// False-position steps at most once a crossing is isolated; each at least halves the
// bracket's far side (Illinois), so a smooth crossing is exact to rounding long before.
constexpr int kMaxRefineSteps = 40;
// Function evaluations per search at most. A function near the threshold along a long
// stretch (f = 0, or a tiny constant) leaves every piece undecided, so halving would visit
// 2^(span/accuracy) pieces; past this budget the search keeps the resolution it reached
// (sign changes between the values it has are still crossings, so they still alternate).
constexpr long kEvaluationBudget = 8192;

bool finitePositive(double v) { return v > 0.0 && std::isfinite(v); }

}  // namespace

Isosurface::Isosurface(Params p) : p_(std::move(p)) {
  if (!p_.field) throw std::invalid_argument("isosurface: no function");
  if (!finitePositive(p_.maxGradient))
    throw std::invalid_argument("isosurface: max-gradient must be > 0");
  if (!finitePositive(p_.accuracy)) throw std::invalid_argument("isosurface: accuracy must be > 0");
  if (!std::isfinite(p_.threshold))
    throw std::invalid_argument("isosurface: threshold must be finite");
  bounds_ = containerBounds(p_.container, "isosurface");
  Vec3 e = bounds_.extent();
  scale_ = std::max({e.x, e.y, e.z});
}

bool Isosurface::containerSpan(const Ray& ray, double& t0, double& t1) const {
  return lucent::containerSpan(p_.container, ray, t0, t1);
}

bool Isosurface::inContainer(const Vec3& p) const {
  const IsosurfaceContainer& c = p_.container;
  if (c.kind == IsosurfaceContainer::Box) return bounds_.contains(p);
  return glm::dot(p - c.center, p - c.center) <= c.radius * c.radius;
}

bool Isosurface::inside(const Vec3& p) const {
  return !p_.open && inContainer(p) && value(p) < 0.0;
}

template <class Emit>
void Isosurface::walk(const Ray& ray, double a, double ga, double b, double gb, Emit&& emit) const {
  if (!(a < b)) return;
  const double dl = glm::length(ray.d);
  const double bound = p_.maxGradient * dl;  // the Lipschitz bound of g per unit t
  const double tAccuracy = p_.accuracy / dl;
  long evaluations = 0;
  auto g = [&](double t) {
    ++evaluations;
    return value(ray.at(t));
  };
  struct Segment {
    double t0, g0, t1, g1;
    int depth;
  };
  Segment stack[kMaxDepth + 2];
  int n = 0;
  stack[n++] = {a, ga, b, gb, 0};
  double steepest = 0.0;
  while (n > 0) {
    const Segment s = stack[--n];
    const double w = s.t1 - s.t0;
    if (!(w > 0.0)) continue;
    // A non-finite value (sqrt of a negative number, say) counts as outside.
    const double g0 = std::isnan(s.g0) ? kInf : s.g0, g1 = std::isnan(s.g1) ? kInf : s.g1;
    if (std::isfinite(g0) && std::isfinite(g1))
      steepest = std::max(steepest, std::abs(g1 - g0) / (w * dl));
    const bool change = (g0 < 0.0) != (g1 < 0.0);
    if (!change && std::abs(g0) + std::abs(g1) > bound * w) continue;  // no crossing fits
    if (w > tAccuracy && s.depth < kMaxDepth && evaluations < kEvaluationBudget) {
      const double m = s.t0 + 0.5 * w;
      const double gm = g(m);
      stack[n++] = {m, gm, s.t1, s.g1, s.depth + 1};
      stack[n++] = {s.t0, s.g0, m, gm, s.depth + 1};
      continue;
    }
    if (!change) continue;  // a pair of crossings closer than the accuracy, or none
    // Illinois false position on [lo, hi], lo on g0's side.
    double lo = s.t0, glo = g0, hi = s.t1, ghi = g1;
    // g = 0 counts as outside: a zero at an end is the crossing itself.
    if (glo == 0.0 || ghi == 0.0) {
      if (!emit(glo == 0.0 ? lo : hi, !(g0 < 0.0), 0.0)) break;
      continue;
    }
    double t = 0.5 * (lo + hi);
    int side = 0;
    for (int k = 0; k < kMaxRefineSteps && evaluations < kEvaluationBudget && std::isfinite(glo) &&
                    std::isfinite(ghi);
         ++k) {
      t = (lo * ghi - hi * glo) / (ghi - glo);
      if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
      if (!(t > lo && t < hi)) break;  // adjacent doubles
      const double gt = g(t);
      if (gt == 0.0) {
        lo = hi = t;
        break;
      }
      if ((gt < 0.0) == (glo < 0.0)) {
        lo = t;
        glo = gt;
        if (side == -1) ghi *= 0.5;
        side = -1;
      } else {
        hi = t;
        ghi = gt;
        if (side == 1) glo *= 0.5;
        side = 1;
      }
      if (hi - lo <= 2.0 * kMachineEps * std::max(std::abs(lo), std::abs(hi))) break;
    }
    double root = lo == hi ? lo
                           : (std::isfinite(glo) && std::isfinite(ghi) ? std::clamp(t, lo, hi)
                                                                       : 0.5 * (lo + hi));
    if (!emit(root, !(g0 < 0.0), hi - lo)) break;
  }
  if (p_.record && steepest > p_.maxGradient) p_.record->note(steepest);
}

bool Isosurface::intersect(const Ray& ray, Hit& hit) const {
  double c0, c1;
  if (!containerSpan(ray, c0, c1)) return false;
  const double a = std::max(c0, ray.tmin), b = std::min(c1, ray.tmax);
  if (!(a < b)) return false;
  auto take = [&](double t, uint32_t part, double width) {
    hit.t = t;
    hit.shape = this;
    hit.part = part;
    hit.b1 = width;
    hit.b2 = 0.0;
    hit.flip = false;
    return true;
  };
  const double ga = value(ray.at(a));
  if (!p_.open && c0 > ray.tmin && ga < 0.0) return take(c0, kContainerSurface, 0.0);
  const double gb = value(ray.at(b));
  bool found = false;
  walk(ray, a, ga, b, gb, [&](double t, bool, double width) {
    if (t > ray.tmin && t < ray.tmax) found = take(t, kFunctionSurface, width);
    return !found;
  });
  if (found) return true;
  if (!p_.open && c1 < ray.tmax && gb < 0.0) return take(c1, kContainerSurface, 0.0);
  return false;
}

void Isosurface::crossings(const Ray& ray, CrossingList& out) const {
  out.startsInside = false;
  double c0, c1;
  if (!containerSpan(ray, c0, c1)) return;
  const double a = std::max(c0, ray.tmin), b = std::min(c1, ray.tmax);
  if (a > b) return;
  auto push = [&](double t, bool entering, uint32_t part, double width) {
    Crossing c;
    c.hit.t = t;
    c.hit.shape = this;
    c.hit.part = part;
    c.hit.b1 = width;
    c.entering = p_.open || entering;
    out.items.push_back(c);
  };
  const double ga = value(ray.at(a));
  const double gb = value(ray.at(b));
  if (!p_.open) {
    if (c0 >= ray.tmin) {
      if (ga < 0.0) push(c0, true, kContainerSurface, 0.0);
    } else {
      out.startsInside = ga < 0.0;
    }
  }
  walk(ray, a, ga, b, gb, [&](double t, bool entering, double width) {
    push(t, entering, kFunctionSurface, width);
    return true;
  });
  if (!p_.open && c1 <= ray.tmax && gb < 0.0) push(c1, false, kContainerSurface, 0.0);
}

Vec3 Isosurface::gradient(const Vec3& p) const {
  // Central differences: truncation error O(h²), rounding O(eps·|f|/h); h at 1e-5 of the
  // container balances the two for functions of the container's size.
  const double h = 1e-5 * scale_;
  return Vec3(value(p + Vec3(h, 0, 0)) - value(p - Vec3(h, 0, 0)),
              value(p + Vec3(0, h, 0)) - value(p - Vec3(0, h, 0)),
              value(p + Vec3(0, 0, h)) - value(p - Vec3(0, 0, h))) /
         (2.0 * h);
}

SurfaceInfo Isosurface::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo s;
  s.p = ray.at(hit.t);
  const double dl = glm::length(ray.d);
  // Rounding of the point, plus how far the root may lie from it (the final bracket).
  s.pError =
      gamma(32) * (glm::abs(ray.o) + glm::abs(hit.t * ray.d) + Vec3(scale_)) + Vec3(hit.b1 * dl);
  Vec3 n(0.0);
  if (hit.part == kContainerSurface) {
    const IsosurfaceContainer& c = p_.container;
    if (c.kind == IsosurfaceContainer::Sphere) {
      n = s.p - c.center;
    } else {
      // The face the point is nearest to, relative to the box's size.
      Vec3 half = 0.5 * (c.max - c.min), q = (s.p - 0.5 * (c.max + c.min)) / half;
      int axis = 0;
      for (int i = 1; i < 3; ++i)
        if (std::abs(q[i]) > std::abs(q[axis])) axis = i;
      n[axis] = q[axis] < 0.0 ? -1.0 : 1.0;
    }
  } else {
    n = gradient(s.p);
  }
  const double len = glm::length(n);
  s.ng = len > 0.0 && std::isfinite(len) ? n / len : -ray.d / dl;
  s.ns = s.ng;
  return s;
}

}  // namespace lucent
