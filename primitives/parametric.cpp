#include "parametric.h"

#include "search_container.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucent {

namespace {

// Halvings of the rectangle at most along one path (2^-60 of a side is far below any
// accuracy in doubles); the search's stack holds one part per level and one more.
constexpr int kMaxLevels = 120;
// Newton steps at most when a leaf's hit is refined.
constexpr int kMaxNewtonSteps = 16;

bool finitePositive(double v) { return v > 0.0 && std::isfinite(v); }

// The values along an edge of length `len` between end values a and b lie within
// [min(a, b) − ofs, max(a, b) + ofs], ofs = (g·len − |a − b|)/2 (not below 0): a function
// of slope at most g that leaves a and rises must come back down to b.
void edgeInterval(double a, double b, double len, double g, double& low, double& high) {
  const double ofs = std::max(0.0, 0.5 * (g * len - std::abs(a - b)));
  low = std::min(a, b) - ofs;
  high = std::max(a, b) + ofs;
}

// Fills part `sector` of `t` and the parts below it, halving as the search halves.
void precomputePart(const Parametric::Params& p, ParametricIntervals& t, size_t sector, double u0,
                    double u1, double v0, double v1) {
  if (sector >= t.parts / 2) {  // the last level: from the corners
    for (int i = 0; i < 3; ++i) {
      if (!p.precompute[i]) continue;
      const ScalarField& f = *p.functions[i];
      const double c[2][2] = {{f.value(Vec3(u0, v0, 0.0)), f.value(Vec3(u0, v1, 0.0))},
                              {f.value(Vec3(u1, v0, 0.0)), f.value(Vec3(u1, v1, 0.0))}};
      parametricInterval(c, u1 - u0, v1 - v0, p.maxGradient, t.low[i][sector], t.high[i][sector]);
    }
    return;
  }
  // The search's halving: the longer side, u when they are equal.
  if (v1 - v0 > u1 - u0) {
    const double m = 0.5 * (v0 + v1);
    precomputePart(p, t, 2 * sector, u0, u1, v0, m);
    precomputePart(p, t, 2 * sector + 1, u0, u1, m, v1);
  } else {
    const double m = 0.5 * (u0 + u1);
    precomputePart(p, t, 2 * sector, u0, m, v0, v1);
    precomputePart(p, t, 2 * sector + 1, m, u1, v0, v1);
  }
  for (int i = 0; i < 3; ++i) {
    if (!p.precompute[i]) continue;
    t.low[i][sector] = std::min(t.low[i][2 * sector], t.low[i][2 * sector + 1]);
    t.high[i][sector] = std::max(t.high[i][2 * sector], t.high[i][2 * sector + 1]);
  }
}

}  // namespace

std::shared_ptr<const ParametricIntervals> precomputeParametric(const Parametric::Params& p) {
  if (p.precomputeDepth <= 0 || !(p.precompute[0] || p.precompute[1] || p.precompute[2]))
    return nullptr;
  if (p.precomputeDepth > Parametric::kMaxPrecompute)
    throw std::invalid_argument("parametric: precompute depth must be from 0 to 20");
  for (int i = 0; i < 3; ++i)
    if (p.precompute[i] && !p.functions[i])
      throw std::invalid_argument("parametric: a coordinate function is missing");
  if (!(p.uvMin.x < p.uvMax.x && p.uvMin.y < p.uvMax.y))
    throw std::invalid_argument("parametric: the (u, v) rectangle needs min < max in u and v");
  auto t = std::make_shared<ParametricIntervals>();
  t->parts = size_t(1) << p.precomputeDepth;
  for (int i = 0; i < 3; ++i)
    if (p.precompute[i]) {
      t->low[i].assign(t->parts, 0.0);
      t->high[i].assign(t->parts, 0.0);
    }
  precomputePart(p, *t, 1, p.uvMin.x, p.uvMax.x, p.uvMin.y, p.uvMax.y);
  return t;
}

void parametricInterval(const double f[2][2], double du, double dv, double g, double& low,
                        double& high) {
  // A corner where a function is undefined (NaN) or infinite bounds nothing.
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      if (!std::isfinite(f[i][j])) {
        low = -kInf;
        high = kInf;
        return;
      }
  double low0, high0, low1, high1, unused;
  edgeInterval(f[0][0], f[0][1], dv, g, low0, high0);  // the edge u = u0
  edgeInterval(f[1][0], f[1][1], dv, g, low1, high1);  // the edge u = u1
  // Across u, from bounds of the two edges: the worst case is both bounds met at one v.
  edgeInterval(high0, high1, du, g, unused, high);
  edgeInterval(low0, low1, du, g, low, unused);
}

// One part of the rectangle on the search's stack, with its corners' values once known.
struct Parametric::Part {
  double u0, u1, v0, v1;
  double f[3][2][2];  // f[coordinate][u0 or u1][v0 or v1]
  bool corners;
  size_t sector;  // its number (ParametricIntervals), saturating past the precomputed ones
  int level;
  // The ray's stretch inside the box of the part's bounds, the longest of its slabs' (in
  // t), and whether every bound is finite.
  double tIn, tOut, widest;
  bool bounded;
};

Parametric::Parametric(Params p) : p_(std::move(p)) {
  for (const auto& f : p_.functions)
    if (!f) throw std::invalid_argument("parametric: a coordinate function is missing");
  if (!(isFinite(Vec3(p_.uvMin, 0.0)) && isFinite(Vec3(p_.uvMax, 0.0)) && p_.uvMin.x < p_.uvMax.x &&
        p_.uvMin.y < p_.uvMax.y))
    throw std::invalid_argument("parametric: the (u, v) rectangle needs min < max in u and v");
  if (!finitePositive(p_.maxGradient))
    throw std::invalid_argument("parametric: max-gradient must be > 0");
  if (!finitePositive(p_.accuracy)) throw std::invalid_argument("parametric: accuracy must be > 0");
  if (p_.precomputeDepth < 0 || p_.precomputeDepth > kMaxPrecompute)
    throw std::invalid_argument("parametric: precompute depth must be from 0 to 20");
  bounds_ = containerBounds(p_.container, "parametric");
  const Vec3 e = bounds_.extent();
  scale_ = std::max({e.x, e.y, e.z});
  // Central differences: truncation O(h²), rounding O(eps/h); 1e-6 of the side balances
  // them for functions that vary on the rectangle's scale.
  h_ = 1e-6 * (p_.uvMax - p_.uvMin);
  if (!p_.intervals) p_.intervals = precomputeParametric(p_);
  if (p_.intervals) preParts_ = p_.intervals->parts;
}

Vec3 Parametric::point(double u, double v) const {
  const Vec3 q(u, v, 0.0);
  return Vec3(p_.functions[0]->value(q), p_.functions[1]->value(q), p_.functions[2]->value(q));
}

Vec3 Parametric::normal(double u, double v) const {
  const Vec3 su = (point(u + h_.x, v) - point(u - h_.x, v)) / (2.0 * h_.x);
  const Vec3 sv = (point(u, v + h_.y) - point(u, v - h_.y)) / (2.0 * h_.y);
  return glm::cross(su, sv);
}

bool Parametric::containerSpan(const Ray& ray, double& t0, double& t1) const {
  return lucent::containerSpan(p_.container, ray, t0, t1);
}

bool Parametric::search(const Ray& ray, double lower, double upper, Leaf& best) const {
  const double dl = glm::length(ray.d);
  const double g = p_.maxGradient;
  auto value = [&](int i, double u, double v) { return p_.functions[i]->value(Vec3(u, v, 0.0)); };
  // Bounds the part's coordinates and finds the ray's stretch inside their box; false when
  // the ray misses the box within (lower, upper).
  auto place = [&](Part& q) {
    const bool stored = q.sector < preParts_;
    double low[3], high[3];
    for (int i = 0; i < 3; ++i) {
      if (stored && p_.precompute[i]) {
        low[i] = p_.intervals->low[i][q.sector];
        high[i] = p_.intervals->high[i][q.sector];
        continue;
      }
      if (!q.corners) {
        for (int k = 0; k < 3; ++k) {
          q.f[k][0][0] = value(k, q.u0, q.v0);
          q.f[k][0][1] = value(k, q.u0, q.v1);
          q.f[k][1][0] = value(k, q.u1, q.v0);
          q.f[k][1][1] = value(k, q.u1, q.v1);
        }
        q.corners = true;
      }
      parametricInterval(q.f[i], q.u1 - q.u0, q.v1 - q.v0, g, low[i], high[i]);
    }
    q.tIn = -kInf;
    q.tOut = kInf;
    q.widest = 0.0;
    q.bounded = true;
    for (int i = 0; i < 3; ++i) {
      q.bounded = q.bounded && std::isfinite(low[i]) && std::isfinite(high[i]);
      if (std::abs(ray.d[i]) <= 1e-12 * dl) {  // parallel to this slab
        if (ray.o[i] < low[i] || ray.o[i] > high[i]) return false;
        continue;
      }
      double a = (low[i] - ray.o[i]) / ray.d[i], b = (high[i] - ray.o[i]) / ray.d[i];
      if (a > b) std::swap(a, b);
      q.tIn = std::max(q.tIn, a);
      q.tOut = std::min(q.tOut, b);
      q.widest = std::max(q.widest, b - a);
    }
    return q.tIn <= q.tOut && q.tIn < upper && q.tOut > lower;
  };
  Part stack[kMaxLevels + 2];
  int n = 0;
  Part& root = stack[0];
  root.u0 = p_.uvMin.x;
  root.u1 = p_.uvMax.x;
  root.v0 = p_.uvMin.y;
  root.v1 = p_.uvMax.y;
  root.corners = false;
  root.sector = 1;
  root.level = 0;
  if (place(root)) n = 1;
  bool found = false;
  long visited = 0;
  while (n > 0 && visited < kMaxPartsPerSearch) {
    const Part q = stack[--n];
    ++visited;
    if (q.tIn >= best.t) continue;  // a nearer hit was found meanwhile
    const double du = q.u1 - q.u0, dv = q.v1 - q.v0;
    if (std::min(std::max(du, dv), q.widest * dl) < p_.accuracy || q.level >= kMaxLevels) {
      // A leaf. Its entry must lie past `lower`: a leaf the ray starts in is the surface
      // it leaves from.
      if (q.bounded && q.tIn > lower) {
        best = {q.tIn, q.u0, q.u1, q.v0, q.v1};
        found = true;
      }
      continue;
    }
    // Halve the longer side (u when equal: the precomputed table's numbering).
    Part lo = q, hi = q;
    lo.level = hi.level = q.level + 1;
    const size_t cap = size_t(1) << 40;
    lo.sector = std::min(2 * q.sector, cap);
    hi.sector = std::min(2 * q.sector + 1, cap);
    if (dv > du) {
      const double m = 0.5 * (q.v0 + q.v1);
      lo.v1 = hi.v0 = m;
      if (q.corners)
        for (int k = 0; k < 3; ++k) {
          lo.f[k][0][1] = hi.f[k][0][0] = value(k, q.u0, m);
          lo.f[k][1][1] = hi.f[k][1][0] = value(k, q.u1, m);
        }
    } else {
      const double m = 0.5 * (q.u0 + q.u1);
      lo.u1 = hi.u0 = m;
      if (q.corners)
        for (int k = 0; k < 3; ++k) {
          lo.f[k][1][0] = hi.f[k][0][0] = value(k, m, q.v0);
          lo.f[k][1][1] = hi.f[k][0][1] = value(k, m, q.v1);
        }
    }
    // The half whose box the ray enters first is searched first (pushed last): a near hit
    // found early drops the parts behind it.
    const bool loIn = place(lo) && lo.tIn < best.t, hiIn = place(hi) && hi.tIn < best.t;
    if (loIn && hiIn) {
      const bool hiFirst = hi.tIn < lo.tIn;
      stack[n++] = hiFirst ? lo : hi;
      stack[n++] = hiFirst ? hi : lo;
    } else if (loIn) {
      stack[n++] = lo;
    } else if (hiIn) {
      stack[n++] = hi;
    }
  }
  return found;
}

bool Parametric::refine(const Ray& ray, const Leaf& leaf, double lower, double upper, double& t,
                        double& u, double& v) const {
  u = 0.5 * (leaf.u0 + leaf.u1);
  v = 0.5 * (leaf.v0 + leaf.v1);
  t = leaf.t;
  const double tolerance = 1e-10 * scale_;
  bool settled = false;
  for (int k = 0; k < kMaxNewtonSteps; ++k) {
    const Vec3 r = point(u, v) - ray.at(t);
    const double slack =
        tolerance + 64.0 * kMachineEps * (glm::length(ray.o) + std::abs(t) * glm::length(ray.d));
    if (!isFinite(r)) return false;
    if (glm::length(r) <= slack) {
      settled = true;
      break;
    }
    const Vec3 su = (point(u + h_.x, v) - point(u - h_.x, v)) / (2.0 * h_.x);
    const Vec3 sv = (point(u, v + h_.y) - point(u, v - h_.y)) / (2.0 * h_.y);
    // Solve su·du + sv·dv − d·dt = −r by Cramer's rule.
    const Vec3 md = -ray.d;
    const double det = glm::dot(su, glm::cross(sv, md));
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return false;
    const Vec3 b = -r;
    u += glm::dot(b, glm::cross(sv, md)) / det;
    v += glm::dot(su, glm::cross(b, md)) / det;
    t += glm::dot(su, glm::cross(sv, b)) / det;
    if (!std::isfinite(u) || !std::isfinite(v) || !std::isfinite(t)) return false;
  }
  if (!settled) return false;
  // The crossing the leaf stands for: on the rectangle, near the leaf's entry point. No
  // crossing lies before that entry (every surface point is in some leaf's box), but a ray
  // at a glancing angle enters boxes of parts it passes near before it crosses the surface,
  // up to about accuracy / sin(angle) before: near means within 32 leaves' sizes (accuracy
  // in u and v or in length, times the functions' slope); beyond, the entry stands.
  const double near = 32.0 * p_.accuracy * std::max(1.0, p_.maxGradient);
  return t > lower && t < upper && u >= p_.uvMin.x && u <= p_.uvMax.x && v >= p_.uvMin.y &&
         v <= p_.uvMax.y && glm::length(ray.d) * std::abs(t - leaf.t) <= near;
}

bool Parametric::firstHit(const Ray& ray, double lower, double upper, Hit& hit) const {
  Leaf leaf;
  if (!search(ray, lower, upper, leaf)) return false;
  double t, u, v;
  const bool exact = refine(ray, leaf, lower, upper, t, u, v);
  if (!exact) {
    t = leaf.t;
    u = 0.5 * (leaf.u0 + leaf.u1);
    v = 0.5 * (leaf.v0 + leaf.v1);
  }
  hit.t = t;
  hit.shape = this;
  hit.part = exact ? 0 : 1;
  hit.b1 = u;
  hit.b2 = v;
  hit.flip = false;
  return true;
}

bool Parametric::intersect(const Ray& ray, Hit& hit) const {
  double c0, c1;
  if (!containerSpan(ray, c0, c1)) return false;
  const double guard = 4.0 * p_.accuracy / glm::length(ray.d);
  const double lower = std::max(c0, ray.tmin) + guard, upper = std::min(c1, ray.tmax);
  if (!(lower < upper)) return false;
  return firstHit(ray, lower, upper, hit);
}

void Parametric::crossings(const Ray& ray, CrossingList& out) const {
  // The first crossing only, as POV-Ray's parametric gives (its All_Intersections stops at
  // the nearest): clipped or cut away, it leaves the ray to the surfaces behind, not to the
  // parametric's own farther crossings.
  out.startsInside = false;
  Crossing c;
  if (!intersect(ray, c.hit)) return;
  c.entering = true;
  out.items.push_back(c);
}

SurfaceInfo Parametric::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo s;
  s.p = ray.at(hit.t);
  const double dl = glm::length(ray.d);
  // A refined hit lies on the surface to rounding, an unrefined one within its leaf's box;
  // either way rays leaving it must start clear of the boxes of the parts around it (about
  // accuracy times the slope from the surface), or a glancing ray finds them (a shadow
  // ray near the terminator would shadow the point it leaves).
  s.pError = gamma(32) * (glm::abs(ray.o) + glm::abs(hit.t * ray.d) + Vec3(scale_)) +
             Vec3(2.0 * p_.accuracy * std::max(1.0, p_.maxGradient));
  const Vec3 n = normal(hit.b1, hit.b2);
  const double len = glm::length(n);
  s.ng = len > 0.0 && std::isfinite(len) ? n / len : -ray.d / dl;
  s.ns = s.ng;
  s.uv = (Vec2(hit.b1, hit.b2) - p_.uvMin) / (p_.uvMax - p_.uvMin);
  s.hasUV = true;
  return s;
}

bool Parametric::povUV(const SurfaceInfo&, const Hit& hit, Vec2& uv) const {
  uv = Vec2(hit.b1, hit.b2);
  return true;
}

}  // namespace lucent
