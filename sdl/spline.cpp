// POV-Ray 3.7's spline interpolation (spline.h), component by component.
#include "spline.h"

#include <algorithm>
#include <iterator>

namespace lucent::sdl {

namespace {

using Entries = std::vector<Spline::Entry>;

// The first entry whose parameter is at least t, with POV-Ray's ends: 0 at or before the
// first parameter, the number of entries at or after the last.
size_t segmentEnd(const Entries& e, double t) {
  if (e.empty() || t <= e.front().par) return 0;
  if (t >= e.back().par) return e.size();
  return static_cast<size_t>(
      std::lower_bound(e.begin(), e.end(), t,
                       [](const Spline::Entry& a, double p) { return a.par < p; }) -
      e.begin());
}

double linear(const Entries& e, size_t i, int k, double p) {
  const double p1 = e[i].par, p2 = e[i + 1].par, v1 = e[i].v[k], v2 = e[i + 1].v[k];
  return (p - p1) * (v2 - v1) / (p2 - p1) + v1;
}

// The parabola through entries i-1, i and i+1.
double quadratic(const Entries& e, size_t i, int k, double p) {
  const double p1 = e[i - 1].par, p2 = e[i].par, p3 = e[i + 1].par;
  const double v1 = e[i - 1].v[k], v2 = e[i].v[k], v3 = e[i + 1].v[k];
  const double n = (p2 - p1) * (p3 - p1) * (p3 - p2);
  const double a = (-p2 * v1 + p3 * v1 + p1 * v2 - p3 * v2 - p1 * v3 + p2 * v3) / n;
  const double b =
      (p2 * p2 * v1 - p3 * p3 * v1 - p1 * p1 * v2 + p3 * p3 * v2 + p1 * p1 * v3 - p2 * p2 * v3) / n;
  const double c = (-p2 * p2 * p3 * v1 + p2 * p3 * p3 * v1 + p1 * p1 * p3 * v2 - p1 * p3 * p3 * v2 -
                    p1 * p1 * p2 * v3 + p1 * p2 * p2 * v3) /
                   n;
  return (a * p + b) * p + c;
}

// Catmull-Rom on the segment from entry i to i+1, its tangents from the neighbours.
double catmullRom(const Entries& e, size_t i, int k, double p) {
  const double dt = e[i + 1].par - e[i].par;
  const double u = (p - e[i].par) / dt;
  const double slope = (e[i + 1].v[k] - e[i].v[k]) / dt;
  const double dp0 = ((e[i].v[k] - e[i - 1].v[k]) / (e[i].par - e[i - 1].par) + slope) / 2.0 * dt;
  const double dp1 =
      ((e[i + 2].v[k] - e[i + 1].v[k]) / (e[i + 2].par - e[i + 1].par) + slope) / 2.0 * dt;
  return e[i].v[k] * (2 * u * u * u - 3 * u * u + 1) + e[i + 1].v[k] * (3 * u * u - 2 * u * u * u) +
         dp0 * (u * u * u - 2 * u * u + u) + dp1 * (u * u * u - u * u);
}

// The natural cubic spline's second derivatives at the entries (0 at both ends), for
// component k: the tridiagonal system solved forwards and back.
std::vector<double> secondDerivatives(const Entries& e, int k) {
  const size_t n = e.size();
  std::vector<double> m(n, 0.0);
  if (n < 3) return m;
  std::vector<double> h(n - 1), b(n - 1), u(n - 1), v(n - 1);
  for (size_t i = 0; i + 1 < n; ++i) {
    h[i] = e[i + 1].par - e[i].par;
    b[i] = (e[i + 1].v[k] - e[i].v[k]) / h[i];
  }
  u[1] = 2 * (h[0] + h[1]);
  v[1] = 6 * (b[1] - b[0]);
  for (size_t i = 2; i + 1 < n; ++i) {
    u[i] = 2 * (h[i] + h[i - 1]) - (h[i - 1] * h[i - 1]) / u[i - 1];
    v[i] = 6 * (b[i] - b[i - 1]) - (h[i - 1] * v[i - 1]) / u[i - 1];
  }
  for (size_t i = n - 2; i > 0; --i) m[i] = (v[i] - h[i] * m[i + 1]) / u[i];
  return m;
}

double natural(const Entries& e, const std::vector<double>& m, size_t i, int k, double p) {
  const double h = e[i + 1].par - e[i].par, d = p - e[i].par;
  double tmp = m[i] / 2.0 + (d * (m[i + 1] - m[i])) / (6.0 * h);
  tmp = -(h / 6.0) * (m[i + 1] + 2.0 * m[i]) + (e[i + 1].v[k] - e[i].v[k]) / h + d * tmp;
  return e[i].v[k] + d * tmp;
}

}  // namespace

SplineEntries::SplineEntries(const Spline& from) {
  for (const Spline::Entry& e : from.entries) byPar_.emplace(e.par, e.v);
}

void SplineEntries::insert(double par, const std::array<double, 5>& v) {
  auto it = byPar_.find(par);
  if (it == byPar_.end()) {
    byPar_.emplace(par, v);
    return;
  }
  if (byPar_.size() >= 2 && std::next(it) == byPar_.end()) return;  // POV-Ray's quirk
  it->second = v;
}

Spline SplineEntries::make(SplineKind kind, int terms) const {
  Spline s;
  s.kind = kind;
  s.terms = terms;
  s.entries.reserve(byPar_.size());
  for (const auto& [par, v] : byPar_) s.entries.push_back(Spline::Entry{par, v});
  s.finish();
  return s;
}

void Spline::finish() {
  for (int k = 0; k < 5; ++k) curvature[static_cast<size_t>(k)] = secondDerivatives(entries, k);
}

std::array<double, 5> Spline::at(double t, SplineKind how) const {
  std::array<double, 5> out{};
  const Entries& e = entries;
  if (e.empty()) return out;
  const size_t last = e.size() - 1;
  if (last == 0) return e[0].v;
  const size_t i = segmentEnd(e, t);
  for (int k = 0; k < 5; ++k) {
    double& r = out[static_cast<size_t>(k)];
    switch (how) {
      case SplineKind::Linear:
        r = i == 0 ? e[0].v[k] : i > last ? e[last].v[k] : linear(e, i - 1, k, t);
        break;
      case SplineKind::Quadratic:
        if (i == 0) r = e[0].v[k];
        else if (i > last) r = e[last].v[k];
        else if (last == 1) r = linear(e, i - 1, k, t);
        else r = quadratic(e, i > 1 ? i - 1 : i, k, t);
        break;
      case SplineKind::Natural:
        if (i == 0) r = e[0].v[k];
        else if (i > last) r = e[last].v[k];
        else r = natural(e, curvature[static_cast<size_t>(k)], i - 1, k, t);
        break;
      case SplineKind::Cubic:
        if (last == 1) r = (e[0].v[k] + e[1].v[k]) / 2.0;
        else if (i < 2) r = e[1].v[k];
        else if (i >= last) r = e[last - 1].v[k];
        else r = catmullRom(e, i - 1, k, t);
        break;
    }
  }
  return out;
}

}  // namespace lucent::sdl
