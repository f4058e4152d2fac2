#include "clean_mesh.h"

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

// 12 bytes, not the 16 a 64-bit key would take with padding: three million of them for a
// million triangles are the largest allocation while a mesh file loads.
struct HalfEdge {
  uint32_t from, to;
  uint32_t third;  // the triangle's other vertex
  uint64_t key() const { return uint64_t(from) << 32 | to; }
};

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

}  // namespace

std::optional<MeshData> cleanClosedMesh(const std::vector<Vec3>& points,
                                        const std::vector<std::array<uint32_t, 3>>& triangles) {
  const size_t n = points.size(), m = triangles.size();
  if (m < 4 || n >= UINT32_MAX) return std::nullopt;  // a closed surface has 4 or more

  // Points with identical coordinates are one vertex (CGAL's repair merges them): each
  // takes the smallest index of its group.
  std::vector<uint32_t> canon(n);
  {
    std::vector<uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    auto less = [&](uint32_t i, uint32_t j) {
      const Vec3 &a = points[i], &b = points[j];
      return std::tie(a.x, a.y, a.z, i) < std::tie(b.x, b.y, b.z, j);
    };
    std::sort(order.begin(), order.end(), less);
    for (size_t k = 0; k < n; ++k)
      canon[order[k]] = k > 0 && points[order[k]] == points[order[k - 1]] ? canon[order[k - 1]]
                                                                           : order[k];
  }

  std::vector<std::array<uint32_t, 3>> tris(m);
  for (size_t f = 0; f < m; ++f) {
    const auto& t = triangles[f];
    const std::array<uint32_t, 3> c = {canon[t[0]], canon[t[1]], canon[t[2]]};
    if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0]) return std::nullopt;
    if (!certainlyNotCollinear(points[c[0]], points[c[1]], points[c[2]])) return std::nullopt;
    tris[f] = c;
  }
  canon = std::vector<uint32_t>();

  // Closed and consistently oriented: every directed edge once, and its reverse once.
  std::vector<HalfEdge> edges;
  edges.reserve(3 * m);
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k)
      edges.push_back({t[k], t[(k + 1) % 3], t[(k + 2) % 3]});
  std::sort(edges.begin(), edges.end(),
            [](const HalfEdge& a, const HalfEdge& b) { return a.key() < b.key(); });
  auto find = [&](size_t begin, size_t end, uint64_t key) -> const HalfEdge* {
    auto it = std::lower_bound(edges.begin() + begin, edges.begin() + end, key,
                               [](const HalfEdge& e, uint64_t k) { return e.key() < k; });
    return it != edges.begin() + end && it->key() == key ? &*it : nullptr;
  };
  for (size_t i = 0; i + 1 < edges.size(); ++i)
    if (edges[i + 1].key() == edges[i].key()) return std::nullopt;
  {
    // The keys are distinct, so every reverse is there exactly when the sorted reverses
    // are the sorted keys (two sequential passes, where a search per edge would miss
    // the cache on every step).
    std::vector<uint64_t> reversed(edges.size());
    for (size_t i = 0; i < edges.size(); ++i)
      reversed[i] = uint64_t(edges[i].to) << 32 | edges[i].from;
    std::sort(reversed.begin(), reversed.end());
    for (size_t i = 0; i < edges.size(); ++i)
      if (reversed[i] != edges[i].key()) return std::nullopt;
  }
  // Manifold at every vertex: its triangles form one fan. Around vertex v, the triangle
  // with edge v→w has third vertex x, and the next triangle of the fan has edge v→x; one
  // fan visits every edge leaving v before it returns to the first.
  for (size_t begin = 0; begin < edges.size();) {
    const uint64_t from = edges[begin].from;
    size_t end = begin;
    while (end < edges.size() && edges[end].from == from) ++end;
    const uint32_t first = edges[begin].to;
    uint32_t w = first;
    size_t steps = 0;
    do {
      const HalfEdge* e = find(begin, end, from << 32 | w);
      if (!e) return std::nullopt;
      w = e->third;
      ++steps;
    } while (w != first && steps <= end - begin);
    if (steps != end - begin) return std::nullopt;
    begin = end;
  }
  edges = std::vector<HalfEdge>();

  // One shell: several would need their nesting to decide which way each faces.
  {
    std::vector<uint32_t> parent(n);
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
  std::vector<uint32_t> newIndex(n, UINT32_MAX);
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
