#include "triangle_mesh.h"

#include "test_counts.h"
#include "triangle_geometry.h"
#include "watertight.h"
#include "watertight_filter.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace lucent {

namespace {
// Subtrees of at most this many triangles are BVH leaves without a split search.
constexpr uint32_t kMinLeaf = 2;
// The SAH's cost of visiting a node, in triangle tests: high enough that a mesh's tree has
// few nodes and builds quickly at about the same ray speed (the choice of 3 and 4 is
// measured in docs/performance-history.md, "Figures behind comments in the code").
constexpr float kNodeCost = BvhNode::kWidth == 8 ? 4.0f : 3.0f;

// isDegenerateTriangle's decision (watertight.cpp: |e1 × e2| <= gamma(6)·|e1|·|e2|) with
// its three square roots spent only where it is close. Squared, the test reads
// C <= g²·A·B (C = |e1 × e2|², A = |e1|², B = |e2|², g = gamma(6)); where C exceeds
// 4·g²·A·B the lengths differ by a factor of 2, far more than the few roundings of either
// form (the cross product's cancellation included: its error is a few ulps of |e1|·|e2|,
// and g is 6 ulps), so the full test would find the triangle non-degenerate too. A and B
// are kept within [1e-100, 1e100] so that g²·A·B neither overflows nor underflows; every
// other triangle (NaN included: the comparisons fail) takes the full test. So the
// decisions are exactly those of isDegenerateTriangle.
bool isDegenerate(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  const Vec3 e1 = p1 - p0, e2 = p2 - p0;
  const double a = glm::dot(e1, e1), b = glm::dot(e2, e2);
  const Vec3 c = glm::cross(e1, e2);
  constexpr double kClear = 4.0 * gamma(6) * gamma(6);
  if (a > 1e-100 && a < 1e100 && b > 1e-100 && b < 1e100 && glm::dot(c, c) > kClear * a * b)
    return false;
  return isDegenerateTriangle(p0, p1, p2);
}
}  // namespace

std::vector<Vec3> computeVertexNormals(const MeshData& mesh) {
  std::vector<Vec3> n(mesh.positions.size(), Vec3(0.0));
  for (const auto& tri : mesh.triangles) {
    const Vec3& p0 = mesh.positions[tri[0]];
    Vec3 area2 = glm::cross(mesh.positions[tri[1]] - p0, mesh.positions[tri[2]] - p0);
    for (uint32_t v : tri) n[v] += area2;
  }
  for (Vec3& v : n) {
    double len = glm::length(v);
    v = len > 0.0 ? v / len : Vec3(0.0);
  }
  return n;
}

TriangleMesh::TriangleMesh(std::shared_ptr<const MeshData> mesh, bool useNormals)
    : mesh_(std::move(mesh)),
      useNormals_(useNormals && mesh_->normals.size() == mesh_->positions.size()) {
  const auto& P = mesh_->positions;
  for (uint32_t i = 0; i < mesh_->triangles.size(); ++i) {
    const auto& tri = mesh_->triangles[i];
    for (uint32_t v : tri)
      if (v >= P.size())
        throw std::invalid_argument("mesh: triangle " + std::to_string(i) + " uses vertex " +
                                    std::to_string(v) + ", but there are only " +
                                    std::to_string(P.size()));
    for (uint32_t v : tri) bounds_.expand(P[v]);
  }
  // Zero-area triangles are never hit: an empty box keeps them out of the BVH. Pairs of
  // triangles are leaves without a split search: splitting them saves few watertight
  // tests for more nodes and a slower build (docs/performance-history.md).
  BvhOptions options;
  options.minLeafSize = kMinLeaf;
  options.traversalCost = kNodeCost;
  bvh_ = Bvh(
      mesh_->triangles.size(),
      [&](uint32_t i) {
        const auto& tri = mesh_->triangles[i];
        if (isDegenerate(P[tri[0]], P[tri[1]], P[tri[2]])) return AABB();
        AABB box;
        for (uint32_t v : tri) box.expand(P[v]);
        return box;
      },
      options);
}

template <class Visit>
void TriangleMesh::forEachCandidate(const Ray& ray, const double& tFar, Visit&& visit,
                                    Bvh::Order order) const {
  // Counted here, once per search, for --stats.
  uint64_t tested = 0;
  bvh_.candidates(
      ray, tFar,
      [&](uint32_t i) {
        ++tested;
        return visit(i);
      },
      Bvh::NoPrefetch(), order);
  threadTestCounts[kMeshTriangleSlot] += tested;
}

namespace {

struct TriangleHit {
  double t;
  uint32_t tri;
  double b1, b2;
  int facing;  // +1: the ray meets the outward side (entering a solid)
};

}  // namespace

template <class Exact>
bool TriangleMesh::forEachLeafCandidate(const Ray& ray, const ShearedRay& sr, const double& tFar,
                                        Exact&& exact, Bvh::Order order) const {
  // Counted here, once per search, for --stats: the triangles of the entered leaves up to
  // the one that ends the search, as when they were tested one by one.
  uint64_t tested = 0;
  const auto& P = mesh_->positions;
  const auto& T = mesh_->triangles;
  const auto& slotOrder = bvh_.order();
  bool ended = !bvh_.leaves(
      ray, tFar,
      [&](uint32_t first, uint32_t count) {
        tested += count;
        // Four at a time: the pre-test leaves only the triangles the exact test may hit,
        // which then run in slot order, as one by one.
        for (uint32_t s = first, e = first + count; s < e; s += 4) {
          const int n = int(std::min<uint32_t>(4, e - s));
          uint32_t items[4];
          const Vec3* corners[4][3];
          for (int i = 0; i < n; ++i) {
            items[i] = slotOrder.empty() ? s + i : slotOrder[s + i];
            const auto& tri = T[items[i]];
            for (int k = 0; k < 3; ++k) corners[i][k] = &P[tri[k]];
          }
          for (int m = watertightCandidates(sr, corners, n); m; m &= m - 1) {
            const int i = __builtin_ctz(m);
            if (!exact(items[i], corners[i])) {
              tested -= e - (s + i + 1);
              return false;
            }
          }
        }
        return true;
      },
      Bvh::NoPrefetch(), order);
  threadTestCounts[kMeshTriangleSlot] += tested;
  return ended;
}

bool TriangleMesh::intersect(const Ray& ray, Hit& hit) const {
  const ShearedRay sr(ray);
  double tFar = ray.tmax;
  bool found = false;
  forEachLeafCandidate(ray, sr, tFar, [&](uint32_t i, const Vec3* const* p) {
    TriangleIntersection ti;
    if (intersectTriangle(sr, *p[0], *p[1], *p[2], ti, ray.tmin) && ray.tmin < ti.t &&
        ti.t < tFar) {
      tFar = ti.t;
      hit.t = ti.t;
      hit.shape = this;
      hit.part = i;
      hit.b1 = ti.b1;
      hit.b2 = ti.b2;
      found = true;
    }
    return true;
  });
  return found;
}

bool TriangleMesh::occluded(const Ray& ray) const {
  const ShearedRay sr(ray);
  // Any hit will do: boxes in tree order, no sorting (Bvh::candidates).
  return forEachLeafCandidate(
      ray, sr, ray.tmax,
      [&](uint32_t, const Vec3* const* p) {
        TriangleIntersection ti;
        return !(intersectTriangle(sr, *p[0], *p[1], *p[2], ti, ray.tmin) && ray.tmin < ti.t &&
                 ti.t < ray.tmax);
      },
      Bvh::Order::Tree);
}

void TriangleMesh::crossings(const Ray& ray, CrossingList& out) const {
  out.startsInside = false;
  const ShearedRay sr(ray);
  const auto& P = mesh_->positions;
  const bool solid = mesh_->closed;
  // A solid needs the whole line (what lies before tmin says whether the ray starts
  // inside); a surface only [tmin, tmax].
  Ray search = ray;
  if (solid) {
    search.tmin = -kInf;
    search.tmax = kInf;
  }
  std::vector<TriangleHit> hits;
  forEachCandidate(search, search.tmax, [&](uint32_t i) {
    const auto& tri = mesh_->triangles[i];
    TriangleIntersection ti;
    if (intersectTriangle(sr, P[tri[0]], P[tri[1]], P[tri[2]], ti) && search.tmin <= ti.t &&
        ti.t <= search.tmax)
      hits.push_back({ti.t, i, ti.b1, ti.b2, ti.facing});
    return true;
  });

  auto push = [&](const TriangleHit& h, bool entering) {
    Crossing c;
    c.hit.t = h.t;
    c.hit.shape = this;
    c.hit.part = h.tri;
    c.hit.b1 = h.b1;
    c.hit.b2 = h.b2;
    c.entering = entering;
    out.items.push_back(c);
  };
  std::sort(hits.begin(), hits.end(),
            [](const TriangleHit& a, const TriangleHit& b) { return a.t < b.t; });
  if (!solid) {
    for (const TriangleHit& h : hits) push(h, true);
    return;
  }
  // Walk the line from −∞, where a closed mesh's winding number is 0, adding each hit's
  // facing; the line is inside where the winding number is positive. The watertight test
  // covers every point of the ray's plane exactly once around shared edges and vertices,
  // so the facings always sum to 0. Where the computed t of nearly edge-on triangles (a
  // ray along an edge) put a leaving hit before its entering one, the winding number
  // dips below 0 and back instead of flipping the state, and where a mesh overlaps itself
  // it rises above 1 without a crossing. Hits at one t are one event (a ray meeting a
  // silhouette vertex enters and leaves at once: nothing). Only real changes become
  // crossings, so the list alternates.
  int winding = 0;
  bool in = false;
  for (size_t i = 0; i < hits.size();) {
    size_t j = i;
    for (; j < hits.size() && hits[j].t == hits[i].t; ++j) winding += hits[j].facing;
    const bool next = winding > 0;
    if (next != in) {
      // The representative hit is one whose side agrees with the change.
      size_t k = i;
      while (k + 1 < j && (hits[k].facing > 0) != next) ++k;
      if (hits[k].t < ray.tmin) out.startsInside = next;
      else if (hits[k].t <= ray.tmax) push(hits[k], next);
      in = next;
    }
    i = j;
  }
}

bool TriangleMesh::inside(const Vec3& p) const {
  if (!mesh_->closed || !bounds_.contains(p)) return false;
  // Parity along a fixed direction chosen to be unlikely to run along any mesh edge.
  CrossingList cl;
  crossings(Ray(p, Vec3(0.5773502691896258, 0.5773529, 0.5773476), 0.0, 0.0), cl);
  return cl.startsInside;
}

SurfaceInfo TriangleMesh::surface(const Ray&, const Hit& hit) const {
  const auto& tri = mesh_->triangles[hit.part];
  const Vec3 p[3] = {mesh_->positions[tri[0]], mesh_->positions[tri[1]], mesh_->positions[tri[2]]};
  Vec3 n[3];
  Vec2 uv[3];
  if (useNormals_)
    for (int k = 0; k < 3; ++k) n[k] = mesh_->normals[tri[k]];
  bool hasUV = mesh_->uvs.size() == mesh_->positions.size();
  if (hasUV)
    for (int k = 0; k < 3; ++k) uv[k] = mesh_->uvs[tri[k]];
  return triangleSurface(p, useNormals_ ? n : nullptr, hasUV ? uv : nullptr, hit.b1, hit.b2,
                         /*normalFollowsShading=*/!mesh_->closed);
}

// POV-Ray's mesh: its uv_vectors interpolated, (0, 0) without them.
bool TriangleMesh::povUV(const SurfaceInfo& s, const Hit& /*hit*/, Vec2& uv) const {
  uv = s.hasUV ? s.uv : Vec2(0.0);
  return true;
}

}  // namespace lucent
