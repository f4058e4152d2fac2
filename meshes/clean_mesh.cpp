#include "clean_mesh.h"

#include "memory/huge_page_allocator.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

namespace lucent {

namespace {

// Is one component of (b − a) × (c − a) certainly nonzero? Each component is a 2×2
// determinant of differences; its computed value is within gamma(4)·(|p| + |q|) of the
// exact one (p and q its two products: one rounding in each difference, the product and
// the subtraction; pbrt-v3 §3.9). gamma(6) leaves margin, and the floor keeps clear of
// subnormal products, where relative bounds no longer hold.
bool certainlyNotCollinear(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const double p[3] = {e1.y * e2.z, e1.z * e2.x, e1.x * e2.y};
  const double q[3] = {e1.z * e2.y, e1.x * e2.z, e1.y * e2.x};
  for (int k = 0; k < 3; ++k) {
    const double d = p[k] - q[k];
    const double bound = gamma(6) * (std::abs(p[k]) + std::abs(q[k]));
    if (std::abs(d) > bound && std::abs(d) > 1e-280) return true;
  }
  return false;
}

uint32_t findRoot(HugeVector<uint32_t>& parent, uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

}  // namespace

std::optional<MeshData> cleanClosedMesh(const std::vector<Vec3>& points,
                                        const std::vector<std::array<uint32_t, 3>>& triangles) {
  const size_t n = points.size(), m = triangles.size();
  if (m < 4 || n >= UINT32_MAX) return std::nullopt;  // a closed surface has 4 or more

  // The working arrays are HugeVectors (several times faster to fill than fresh 4 KB
  // pages, huge_page_allocator.h); their elements start uninitialised, and each is written
  // before it is read.
  // Points with identical coordinates are one vertex (CGAL's repair merges them): each
  // takes the smallest index of its group.
  HugeVector<uint32_t> canon(n);
  {
    HugeVector<uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    auto less = [&](uint32_t i, uint32_t j) {
      const Vec3 &a = points[i], &b = points[j];
      return std::tie(a.x, a.y, a.z, i) < std::tie(b.x, b.y, b.z, j);
    };
    std::sort(order.begin(), order.end(), less);
    for (size_t k = 0; k < n; ++k)
      canon[order[k]] =
          k > 0 && points[order[k]] == points[order[k - 1]] ? canon[order[k - 1]] : order[k];
  }

  HugeVector<std::array<uint32_t, 3>> tris(m);
  for (size_t f = 0; f < m; ++f) {
    const auto& t = triangles[f];
    const std::array<uint32_t, 3> c = {canon[t[0]], canon[t[1]], canon[t[2]]};
    if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0]) return std::nullopt;
    if (!certainlyNotCollinear(points[c[0]], points[c[1]], points[c[2]])) return std::nullopt;
    tris[f] = c;
  }
  canon = HugeVector<uint32_t>();

  // Closed, consistently oriented and manifold: checked on the half-edges leaving each
  // vertex. They are grouped by that vertex with a counting sort (linear, where a full
  // sort was a noticeable part of a mesh file's load), then sorted within each group
  // by the vertex they lead to.
  struct OutEdge {
    uint32_t to;
    uint32_t third;  // the triangle's other vertex
  };
  HugeVector<uint32_t> first(n + 1);  // the half-edges leaving v are [first[v], first[v + 1])
  HugeVector<OutEdge> leaving(3 * m);
  std::fill(first.begin(), first.end(), 0u);
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) ++first[t[k] + 1];
  for (size_t v = 0; v < n; ++v) first[v + 1] += first[v];
  for (const auto& t : tris)  // first[v] advances to the end of v's group ...
    for (int k = 0; k < 3; ++k) leaving[first[t[k]]++] = {t[(k + 1) % 3], t[(k + 2) % 3]};
  for (size_t v = n; v > 0; --v) first[v] = first[v - 1];  // ... and is moved back
  first[0] = 0;

  // Around vertex v: no directed edge twice, and the triangles form one fan. The
  // triangle with edge v→w has third vertex x, and the next triangle of the fan has edge
  // v→x; one fan visits every edge leaving v before it returns to the first. With every
  // directed edge unique, this also gives each edge its reverse exactly once (the
  // triangle of v→w holds x→v, whose reverse v→x the fan found): the surface is closed
  // and consistently oriented.
  for (size_t v = 0; v < n; ++v) {
    OutEdge* const begin = leaving.data() + first[v];
    OutEdge* const end = leaving.data() + first[v + 1];
    if (begin == end) continue;  // a point no triangle uses
    std::sort(begin, end, [](const OutEdge& a, const OutEdge& b) { return a.to < b.to; });
    for (const OutEdge* e = begin; e + 1 < end; ++e)
      if (e[1].to == e->to) return std::nullopt;
    auto find = [&](uint32_t to) -> const OutEdge* {
      const OutEdge* e = std::lower_bound(
          begin, end, to, [](const OutEdge& a, uint32_t key) { return a.to < key; });
      return e != end && e->to == to ? e : nullptr;
    };
    const size_t degree = size_t(end - begin);
    const uint32_t start = begin->to;
    uint32_t w = start;
    size_t steps = 0;
    do {
      const OutEdge* e = find(w);
      if (!e) return std::nullopt;
      w = e->third;
      ++steps;
    } while (w != start && steps <= degree);
    if (steps != degree) return std::nullopt;
  }
  leaving = HugeVector<OutEdge>();
  first = HugeVector<uint32_t>();

  // One shell: several would need their nesting to decide which way each faces.
  {
    HugeVector<uint32_t> parent(n);
    std::iota(parent.begin(), parent.end(), 0u);
    for (const auto& t : tris)
      for (int k = 1; k < 3; ++k) {
        uint32_t a = findRoot(parent, t[0]), b = findRoot(parent, t[k]);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
      }
    const uint32_t root = findRoot(parent, tris[0][0]);
    for (const auto& t : tris)
      if (findRoot(parent, t[0]) != root) return std::nullopt;
  }

  // Outward when the enclosed volume (sum of signed tetrahedra from the origin,
  // a · (b × c) / 6) is positive. Its rounding is below m·gamma(3) times the sum of the
  // terms' magnitudes; a volume not clearly above that is left to CGAL.
  double volume = 0.0, magnitude = 0.0;
  for (const auto& t : tris) {
    const double v = glm::dot(points[t[0]], glm::cross(points[t[1]], points[t[2]]));
    volume += v;
    magnitude += std::abs(v);
  }
  if (!std::isfinite(volume) || !(std::abs(volume) > 4.0 * double(m) * gamma(3) * magnitude))
    return std::nullopt;
  const bool flip = volume < 0.0;

  MeshData out;
  out.closed = true;
  out.triangles.reserve(m);
  out.positions.reserve(n);  // a closed mesh uses nearly every point
  HugeVector<uint32_t> newIndex(n, UINT32_MAX);
  for (auto t : tris) {
    if (flip) std::swap(t[1], t[2]);
    for (uint32_t& v : t) {
      if (newIndex[v] == UINT32_MAX) {
        newIndex[v] = uint32_t(out.positions.size());
        out.positions.push_back(points[v]);
      }
      v = newIndex[v];
    }
    out.triangles.push_back(t);
  }
  out.positions.shrink_to_fit();
  return out;
}

}  // namespace lucent
