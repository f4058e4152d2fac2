#include "accuracy_harness.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace lucent::accuracy {

double Samples::max() const { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

double Samples::median() const {
  if (v.empty()) return 0.0;
  std::vector<double> c = v;
  auto mid = c.begin() + static_cast<std::ptrdiff_t>(c.size() / 2);
  std::nth_element(c.begin(), mid, c.end());
  return *mid;
}

void CaseResult::merge(const CaseResult& o) {
  rays += o.rays;
  compared += o.compared;
  wrong += o.wrong;
  withinRounding += o.withinRounding;
  nonFinite += o.nonFinite;
  for (auto [to, from] : {std::pair{&relT, &o.relT},
                          {&relTClear, &o.relTClear},
                          {&angle, &o.angle},
                          {&angleClear, &o.angleClear}})
    to->v.insert(to->v.end(), from->v.begin(), from->v.end());
  if (firstProblem.empty()) firstProblem = o.firstProblem;
}

LD angleBetween(const LVec& a, const LVec& b) {
  LVec c = glm::cross(a, b);
  return std::atan2(std::sqrt(glm::dot(c, c)), glm::dot(a, b));
}

double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

Vec3 randomUnit(Rng& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  for (;;) {
    Vec3 v(n(rng), n(rng), n(rng));
    double l = glm::length(v);
    if (l > 1e-6) return v / l;
  }
}

Vec3 randomPerpendicular(Rng& rng, const Vec3& n) {
  for (;;) {
    Vec3 v = glm::cross(n, randomUnit(rng));
    double l = glm::length(v);
    if (l > 1e-3) return v / l;
  }
}

double logUniform(Rng& rng, double lo, double hi) { return std::pow(10.0, uniform(rng, lo, hi)); }

namespace {

// What the reference decides for a ray: how many roots lie in [tmin, tmax] and whether
// the ray starts inside (an odd number of roots before tmin, for a solid).
struct Decision {
  size_t count = 0;
  bool startsInside = false;
  bool operator==(const Decision& o) const {
    return count == o.count && startsInside == o.startsInside;
  }
};

Decision decide(const RefShape& ref, const LRay& ray, LD tmin, LD tmax, bool solid,
                std::vector<LRoot>* inRange = nullptr) {
  std::vector<LRoot> roots;
  ref.lineRoots(ray, roots);
  Decision d;
  size_t before = 0;
  for (const LRoot& r : roots) {
    if (r.t < tmin) {
      ++before;
    } else if (r.t <= tmax) {
      ++d.count;
      if (inRange) inRange->push_back(r);
    }
  }
  if (!solid) {
    // A surface: every root counts, nothing is inside.
    return d;
  }
  d.startsInside = (before % 2 == 1) != ref.insideAtStart(ray);
  return d;
}

// Does a rounding-sized move of the ray change the reference's decision?
bool withinRounding(const RefShape& ref, const Ray& ray, double size, Perturb mode,
                    const Decision& base, bool solid) {
  const LD eta = kPerturbation;
  const LD oScale = eta * (maxComponent(glm::abs(ray.o)) + size);
  const LD dScale = eta * maxComponent(glm::abs(ray.d));
  for (int axis = 0; axis < 3; ++axis)
    for (LD sign : {LD(-1), LD(1)}) {
      LRay moved(ray);
      moved.d[axis] += sign * dScale;
      if (!(decide(ref, moved, ray.tmin, ray.tmax, solid) == base)) return true;
      if (mode == Perturb::OriginAndDirection) {
        LRay shifted(ray);
        shifted.o[axis] += sign * oScale;
        if (!(decide(ref, shifted, ray.tmin, ray.tmax, solid) == base)) return true;
      }
    }
  return false;
}

std::string describe(const Ray& ray, const std::string& what) {
  return fmt::format(
      "{}: ray o=({:.17g}, {:.17g}, {:.17g}) d=({:.17g}, {:.17g}, {:.17g}) "
      "tmin={:.17g}",
      what, ray.o.x, ray.o.y, ray.o.z, ray.d.x, ray.d.y, ray.d.z, ray.tmin);
}

}  // namespace

bool sameT(double a, double b) { return std::abs(a - b) <= 16.0 * kMachineEps * std::abs(b); }

void measureRay(CaseResult& out, const Shape& shape, const RefShape& ref, const Ray& ray,
                double size, Perturb perturb) {
  ++out.rays;
  const bool solid = shape.isSolid();
  std::vector<LRoot> refRoots;
  const Decision expected = decide(ref, LRay(ray), ray.tmin, ray.tmax, solid, &refRoots);

  CrossingList cl;
  shape.crossings(ray, cl);
  Decision got{cl.items.size(), cl.startsInside};

  // intersect() must return the first crossing strictly inside (tmin, tmax).
  const Crossing* first = nullptr;
  for (const Crossing& c : cl.items)
    if (ray.tmin < c.hit.t && c.hit.t < ray.tmax) {
      first = &c;
      break;
    }
  Hit h;
  bool hit = shape.intersect(ray, h);
  const bool consistent = hit == (first != nullptr) && (!hit || sameT(h.t, first->hit.t));
  if (!consistent || !(got == expected)) {
    // A ray within rounding of touching may be answered either way, and the two searches
    // may then answer differently (a mesh drops a touching edge from its crossings, while
    // intersect() reports it).
    if (withinRounding(ref, ray, size, perturb, expected, solid)) {
      ++out.withinRounding;
    } else {
      ++out.wrong;
      if (out.firstProblem.empty())
        out.firstProblem = describe(
            ray,
            consistent
                ? fmt::format("{} crossings (starts inside: {}) where the reference has {} "
                              "(starts inside: {})",
                              got.count, got.startsInside, expected.count, expected.startsInside)
                : std::string("intersect() disagrees with crossings()"));
    }
    return;
  }

  const LVec dUnit = toL(glm::normalize(ray.d));
  for (size_t i = 0; i < cl.items.size(); ++i) {
    const Crossing& c = cl.items[i];
    const LRoot& r = refRoots[i];
    SurfaceInfo si = shape.surface(ray, c.hit);
    if (!std::isfinite(c.hit.t) || !isFinite(si.p) || !isFinite(si.ng)) {
      ++out.nonFinite;
      if (out.firstProblem.empty()) out.firstProblem = describe(ray, "a non-finite crossing");
      continue;
    }
    ++out.compared;
    const bool clear = std::abs(glm::dot(dUnit, r.n)) >= LD(kClearCos);
    if (r.t != 0) {
      double e = double(std::abs((LD(c.hit.t) - r.t) / r.t));
      out.relT.add(e);
      if (clear) out.relTClear.add(e);
    }
    if (r.normalDefined) {
      double a = double(angleBetween(toL(si.ng), r.n));
      out.angle.add(a);
      if (clear) out.angleClear.add(a);
    }
  }
}

namespace {

std::string sci(double x) {
  if (x == 0.0) return "0";
  return fmt::format("{:.1e}", x);
}

// Maximum and median of a measure, or dashes when nothing was measured.
std::string maxOf(const Samples& s) { return s.size() ? sci(s.max()) : "–"; }
std::string medianOf(const Samples& s) { return s.size() ? sci(s.median()) : "–"; }

}  // namespace

std::string markdownTable(const std::vector<CaseResult>& results) {
  std::string s;
  std::string group;
  for (const CaseResult& r : results) {
    if (r.group != group) {
      group = r.group;
      s += fmt::format("\n**{}**\n\n", group);
      s += "| case | rays | crossings | t: max | t: median | t: max, clear | t: bound "
           "| normal: max | normal: median | normal: max, clear | normal: bound "
           "| wrong | within rounding | non-finite |\n";
      s += "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    }
    s +=
        fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
                    r.name, r.rays, r.compared, maxOf(r.relT), medianOf(r.relT), maxOf(r.relTClear),
                    r.boundRelT > 0 ? sci(r.boundRelT) : "–", maxOf(r.angle), medianOf(r.angle),
                    maxOf(r.angleClear), r.boundAngle > 0 ? sci(r.boundAngle) : "–", r.wrong,
                    r.withinRounding, r.nonFinite);
  }
  return s;
}

}  // namespace lucent::accuracy
