// The meshes' hard cases: the suite's one CGAL translation unit (CGAL compiles slowly).
// CGAL's exact predicates (Epick: interval filters with an exact fallback) decide whether
// a line really passes through the triangle Lucent reports, and convex_hull_3 builds a
// closed mesh whose vertices are on an exact grid, so rays can be aimed exactly through
// its edges and vertices. t is compared with the long-double intersection of the line
// with the reported triangle's plane, or with the exactly known entry parameter.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <fmt/format.h>

#include <cmath>

#include "accuracy_cases.h"
#include "primitives/box.h"
#include "primitives/offset.h"
#include "primitives/triangle.h"
#include "primitives/triangle_mesh.h"

namespace lucent::accuracy {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P3 = K::Point_3;

P3 cgal(const Vec3& v) { return P3(v.x, v.y, v.z); }

// Does the line through o and q (two exactly represented points) pass through the
// closed triangle (a, b, c)? Exact: the three orientations of the line against the
// triangle's edges agree in sign (zeros allowed: through an edge or a vertex).
bool lineThroughTriangle(const Vec3& o, const Vec3& q, const Vec3& a, const Vec3& b,
                         const Vec3& c) {
  P3 O = cgal(o), Q = cgal(q);
  CGAL::Orientation s0 = CGAL::orientation(O, Q, cgal(a), cgal(b));
  CGAL::Orientation s1 = CGAL::orientation(O, Q, cgal(b), cgal(c));
  CGAL::Orientation s2 = CGAL::orientation(O, Q, cgal(c), cgal(a));
  bool anyPos = s0 == CGAL::POSITIVE || s1 == CGAL::POSITIVE || s2 == CGAL::POSITIVE;
  bool anyNeg = s0 == CGAL::NEGATIVE || s1 == CGAL::NEGATIVE || s2 == CGAL::NEGATIVE;
  return anyPos != anyNeg;  // all zero: the line lies in the plane (not a crossing)
}

// The parameter where the line o + t·d meets the plane of (a, b, c), in long double.
LD planeT(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c) {
  LVec A = toL(a), n = glm::cross(toL(b) - A, toL(c) - A);
  return glm::dot(n, A - toL(o)) / glm::dot(n, toL(d));
}

LVec unitNormal(const Vec3& a, const Vec3& b, const Vec3& c) {
  LVec A = toL(a), n = glm::cross(toL(b) - A, toL(c) - A);
  return n / std::sqrt(glm::dot(n, n));
}

// A value on the dyadic grid of step 2^-bits (so sums of a few such values are exact).
double onGrid(double x, int bits) { return std::ldexp(std::round(std::ldexp(x, bits)), -bits); }
Vec3 onGrid(const Vec3& v, int bits) {
  return {onGrid(v.x, bits), onGrid(v.y, bits), onGrid(v.z, bits)};
}

// A latitude-longitude sphere of radius 1: a vertex at each pole, rings − 1 rings of
// `segments` vertices, counter-clockwise seen from outside, closed.
std::shared_ptr<MeshData> latLongSphere(int rings, int segments) {
  auto m = std::make_shared<MeshData>();
  m->positions.push_back({0, 1, 0});
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      double th = kPi * i / rings, ph = 2.0 * kPi * j / segments;
      m->positions.push_back(
          {std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph)});
    }
  m->positions.push_back({0, -1, 0});
  const uint32_t south = uint32_t(m->positions.size() - 1);
  auto id = [&](int i, int j) { return uint32_t(1 + (i - 1) * segments + (j % segments)); };
  for (int j = 0; j < segments; ++j) {
    m->triangles.push_back({0, id(1, j + 1), id(1, j)});
    m->triangles.push_back({south, id(rings - 1, j), id(rings - 1, j + 1)});
  }
  for (int i = 1; i + 1 < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      m->triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j)});
      m->triangles.push_back({id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)});
    }
  m->closed = true;
  return m;
}

// The convex hull of `count` points on the unit sphere rounded to the grid of 2^-10:
// closed, outward oriented (CGAL's hull faces are counter-clockwise from outside), and
// every vertex exact, so points on its edges are exact too.
std::shared_ptr<MeshData> gridHull(Rng& rng, int count) {
  std::vector<P3> pts;
  for (int i = 0; i < count; ++i) pts.push_back(cgal(onGrid(randomUnit(rng), 10)));
  CGAL::Surface_mesh<P3> hull;
  CGAL::convex_hull_3(pts.begin(), pts.end(), hull);
  auto m = std::make_shared<MeshData>();
  for (auto v : hull.vertices()) {
    const P3& p = hull.point(v);
    m->positions.push_back({p.x(), p.y(), p.z()});
  }
  for (auto f : hull.faces()) {
    std::array<uint32_t, 3> tri{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(hull.halfedge(f), hull))
      tri[size_t(k++)] = uint32_t(v.idx());
    m->triangles.push_back(tri);
  }
  m->closed = true;
  return m;
}

CaseResult newCase(const std::string& group, const std::string& name, double boundRelT,
                   double boundAngle) {
  CaseResult r;
  r.group = group;
  r.name = name;
  r.boundRelT = boundRelT;
  r.boundAngle = boundAngle;
  return r;
}

void problem(CaseResult& r, const Ray& ray, const std::string& what) {
  ++r.wrong;
  if (r.firstProblem.empty())
    r.firstProblem =
        fmt::format("{}: ray o=({:.17g}, {:.17g}, {:.17g}) d=({:.17g}, {:.17g}, {:.17g})", what,
                    ray.o.x, ray.o.y, ray.o.z, ray.d.x, ray.d.y, ray.d.z);
}

// Records the errors of a crossing on triangle `tri` of `m` against the exact line
// (o, o + d must be exact): the line must pass through the triangle; t is compared with
// tExact when given, else with the long-double plane intersection.
bool checkCrossing(CaseResult& r, const TriangleMesh& mesh, const Ray& ray, const Hit& hit,
                   const LD* tExact, bool normalDefined) {
  const MeshData& m = mesh.data();
  const auto& tri = m.triangles[hit.part];
  const Vec3 &a = m.positions[tri[0]], &b = m.positions[tri[1]], &c = m.positions[tri[2]];
  if (!lineThroughTriangle(ray.o, ray.o + ray.d, a, b, c)) {
    problem(r, ray, fmt::format("the line misses the reported triangle {}", hit.part));
    return false;
  }
  LD ref = tExact ? *tExact : planeT(ray.o, ray.d, a, b, c);
  if (!(ref > 0)) {
    problem(r, ray, fmt::format("triangle {} lies behind the origin", hit.part));
    return false;
  }
  SurfaceInfo si = mesh.surface(ray, hit);
  if (!std::isfinite(hit.t) || !isFinite(si.p) || !isFinite(si.ng)) {
    ++r.nonFinite;
    return false;
  }
  ++r.compared;
  LVec n = unitNormal(a, b, c);
  bool clear = std::abs(glm::dot(toL(glm::normalize(ray.d)), n)) >= LD(kClearCos);
  double e = double(std::abs((LD(hit.t) - ref) / ref));
  r.relT.add(e);
  if (clear) r.relTClear.add(e);
  if (normalDefined) {
    double ang = double(angleBetween(toL(si.ng), n));
    r.angle.add(ang);
    if (clear) r.angleClear.add(ang);
  }
  return true;
}

// t: as for the analytic shapes (a few ε·κ away from grazing, with room). Normal: the
// triangle's own (p1 − p0) × (p2 − p0), normalised, against the same in long double:
// a few ε, 2e-15 with room.
constexpr double kMeshT = 1e-14;
constexpr double kMeshN = 2e-15;

// A ray through the interior of a convex closed mesh: exactly two crossings, entering
// then leaving, the first at tEnter when known, and intersect() agreeing.
void convexThrough(CaseResult& r, const TriangleMesh& mesh, const Ray& ray, const LD* tEnter,
                   bool entryNormalDefined) {
  ++r.rays;
  CrossingList cl;
  mesh.crossings(ray, cl);
  if (cl.startsInside || cl.items.size() != 2 || !cl.items[0].entering || cl.items[1].entering) {
    problem(r, ray, fmt::format("{} crossings through a convex mesh", cl.items.size()));
    return;
  }
  Hit h;
  if (!mesh.intersect(ray, h) || !sameT(h.t, cl.items[0].hit.t) || !mesh.occluded(ray)) {
    problem(r, ray, "intersect() or occluded() disagrees with crossings()");
    return;
  }
  checkCrossing(r, mesh, ray, cl.items[0].hit, tEnter, entryNormalDefined);
  checkCrossing(r, mesh, ray, cl.items[1].hit, nullptr, true);
}

}  // namespace

std::vector<CaseResult> meshCases(double effort) {
  const std::string group = "Triangle meshes (exact predicates)";
  std::vector<CaseResult> out;

  {  // 10^6 rays from inside a closed tessellated sphere: every one must hit. Origins and
     // directions are on the grid of 2^-20, so o + d is exact and CGAL decides exactly
     // whether the line passes through the triangle Lucent reports.
    const int rings = 16, segments = 32;
    TriangleMesh mesh(latLongSphere(rings, segments), false);
    Rng rng(1601);
    CaseResult r = newCase(group,
                           fmt::format("10^6 rays from inside a closed tessellated sphere ({} "
                                       "triangles)",
                                       mesh.triangleCount()),
                           kMeshT, kMeshN);
    for (int i = 0; i < 1000000; ++i) {
      Vec3 o = i == 0 ? Vec3(0.0)
                      : onGrid(0.9 * std::cbrt(uniform(rng, 0.0, 1.0)) * randomUnit(rng), 20);
      Vec3 d = onGrid(randomUnit(rng) * uniform(rng, 0.5, 2.0), 20);
      if (i % 10 == 1) {  // along an axis
        d = Vec3(0.0);
        d[i % 3] = i % 20 == 1 ? 1.0 : -0.75;
      }
      Ray ray(o, d);
      ++r.rays;
      Hit h;
      if (!mesh.intersect(ray, h) || !mesh.occluded(ray)) {
        problem(r, ray, "a ray from inside missed the closed mesh");
        continue;
      }
      // From inside a convex solid the crossing is ahead, at a healthy angle: the plane's
      // long-double t is positive by a wide margin whenever the line meets the triangle.
      checkCrossing(r, mesh, ray, h, nullptr, true);
    }
    out.push_back(std::move(r));
  }

  Rng rng(1602);
  auto hullData = gridHull(rng, 300);
  TriangleMesh hull(hullData, false);
  const auto& P = hullData->positions;
  const auto& T = hullData->triangles;
  const int n = rayCount(20000, effort);
  // A point inside the hull, on the grid (the hull of 300 points on the unit sphere
  // contains the ball of radius 0.3 by a wide margin).
  auto inner = [&] { return onGrid(0.3 * uniform(rng, 0.0, 1.0) * randomUnit(rng), 10); };
  const double spans[] = {0.5, 1.0, 2.0, 4.0};

  {  // Through exact points of edges (p + k/8·(q − p)), from outside, towards the inside.
    CaseResult r = newCase(group,
                           fmt::format("convex grid mesh ({} triangles): rays through shared edges",
                                       hull.triangleCount()),
                           kMeshT, kMeshN);
    for (int i = 0; i < n; ++i) {
      const auto& tri = T[rng() % T.size()];
      int e = int(rng() % 3);
      Vec3 p = P[tri[size_t(e)]], q = P[tri[size_t((e + 1) % 3)]];
      Vec3 onEdge = p + (double(1 + rng() % 7) / 8.0) * (q - p);
      Vec3 d = inner() - onEdge;
      double j = spans[rng() % 4];
      LD tEnter = j;
      convexThrough(r, hull, Ray(onEdge - j * d, d), &tEnter, false);
    }
    out.push_back(std::move(r));
  }
  {  // Through shared vertices.
    CaseResult r = newCase(group, "convex grid mesh: rays through shared vertices", kMeshT, kMeshN);
    for (int i = 0; i < n; ++i) {
      Vec3 v = P[rng() % P.size()];
      Vec3 d = inner() - v;
      double j = spans[rng() % 4];
      LD tEnter = j;
      convexThrough(r, hull, Ray(v - j * d, d), &tEnter, false);
    }
    out.push_back(std::move(r));
  }
  {  // Zero direction components: axis-aligned and in-plane rays through inner points.
    CaseResult r =
        newCase(group, "convex grid mesh: rays with zero direction components", kMeshT, kMeshN);
    for (int i = 0; i < n; ++i) {
      Vec3 d(0.0);
      int axis = int(rng() % 3);
      d[axis] = rng() % 2 ? 1.0 : -1.0;
      if (i % 2) d[(axis + 1) % 3] = onGrid(uniform(rng, -1.0, 1.0), 10);
      convexThrough(r, hull, Ray(inner() - 4.0 * d, d), nullptr, true);
    }
    out.push_back(std::move(r));
  }
  {  // Secondary rays leaving the hull and the tessellated sphere (offsetRayOrigin):
     // out of a convex solid nothing may be found; into it exactly one crossing, leaving.
    CaseResult r = newCase(group, "closed meshes: secondary rays leaving the surface", 0.0, 0.0);
    TriangleMesh sphere(latLongSphere(16, 32), false);
    for (const TriangleMesh* mesh : {&hull, &sphere}) {
      for (int i = 0; i < n / 4; ++i) {
        Vec3 target = 0.9 * randomUnit(rng);
        Vec3 o = 3.0 * randomUnit(rng);
        Ray primary(o, (target - o) * uniform(rng, 0.5, 2.0));
        Hit h;
        if (!mesh->intersect(primary, h)) continue;
        SurfaceInfo si = mesh->surface(primary, h);
        for (int k = 0; k < 4; ++k) {
          double side = k % 2 ? 1.0 : -1.0;
          double c = k < 2 ? uniform(rng, 0.05, 1.0) : uniform(rng, 1e-4, 0.05);
          Vec3 w = side * c * si.ng + std::sqrt(1.0 - c * c) * randomPerpendicular(rng, si.ng);
          Ray ray(offsetRayOrigin(si.p, si.pError, si.ng, w), w);
          ++r.rays;
          CrossingList cl;
          mesh->crossings(ray, cl);
          Hit again;
          bool hit = mesh->intersect(ray, again);
          if (side > 0) {
            if (hit || !cl.items.empty() || cl.startsInside)
              problem(r, ray, "re-hit leaving outwards");
            continue;
          }
          if (!hit || !cl.startsInside || cl.items.size() != 1 || cl.items[0].entering ||
              !sameT(again.t, cl.items[0].hit.t)) {
            problem(r, ray, fmt::format("{} crossings leaving inwards", cl.items.size()));
            continue;
          }
          // The origin is not on the grid here: compare with the plane's t only.
          const auto& tri = mesh->data().triangles[again.part];
          const Vec3* q = &mesh->data().positions[0];
          LD ref = planeT(ray.o, ray.d, q[tri[0]], q[tri[1]], q[tri[2]]);
          double e = double(std::abs((LD(again.t) - ref) / ref));
          ++r.compared;
          r.relT.add(e);
          if (glm::dot(glm::normalize(ray.d), si.ng) < -kClearCos || c >= kClearCos)
            r.relTClear.add(e);
        }
      }
    }
    out.push_back(std::move(r));
  }
  {  // Degenerate triangles: loose ones never hit, and slivers inside a closed box mesh
     // change none of its crossings (compared with the analytic box).
    CaseResult r =
        newCase(group, "degenerate triangles (zero area, collinear): loose and in a closed mesh",
                kMeshT, kMeshN);
    const Vec3 p(0.25, -0.5, 0.125), v(0.375, 0.25, -0.5);
    const Triangle loose[] = {
        Triangle(p, p + v, p + 2.0 * v),          // collinear, exact
        Triangle(p, p, p + v),                    // two corners equal
        Triangle(p, p, p),                        // a point
        Triangle(p, p + 1e-3 * v, p + 3e-3 * v),  // collinear, tiny
        // Area below the rounding of its own cross product: degenerate by definition
        // (watertight.h, isDegenerateTriangle), so never hit either.
        Triangle(p, p + v, p + 2.0 * v + Vec3(0, 1e-17, 0)),
    };
    for (int i = 0; i < n; ++i) {
      const Triangle& t = loose[size_t(i) % 5];
      // Half aimed exactly through a point of the segment (p + v), half random.
      Vec3 o = onGrid(uniform(rng, 1.0, 3.0) * randomUnit(rng), 10);
      Vec3 d = i % 2 ? (p + v) - o : randomUnit(rng);
      if (i % 7 == 0) d = Vec3(0, 0, (p + v).z - o.z);  // zero components
      Ray ray(o, d);
      ++r.rays;
      Hit h;
      CrossingList cl;
      t.crossings(ray, cl);
      if (t.intersect(ray, h) || !cl.items.empty())
        problem(r, ray, "a degenerate triangle was hit");
    }
    auto data = std::make_shared<MeshData>();
    {
      // The box [-1, 1]³ (12 triangles) plus a collinear sliver across the top face and a
      // triangle collapsed to a point.
      for (int k = 0; k < 8; ++k)
        data->positions.push_back({k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0});
      const uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                    {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
      for (const auto& q : quads) {
        data->triangles.push_back({q[0], q[1], q[2]});
        data->triangles.push_back({q[0], q[2], q[3]});
      }
      data->positions.push_back({0, 1, 0});
      data->triangles.push_back({2, 8, 7});
      data->triangles.push_back({8, 8, 8});
      data->closed = true;
    }
    TriangleMesh slivers(data, false);
    auto box = refBox(Vec3(-1.0), Vec3(1.0));
    for (int i = 0; i < n; ++i) {
      Vec3 o = onGrid(3.0 * randomUnit(rng), 10);
      Vec3 target =
          i % 2 ? Vec3(onGrid(uniform(rng, -1, 1), 10), 1.0, onGrid(uniform(rng, -1, 1), 10))
                : onGrid(Vec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)), 10);
      measureRay(r, slivers, *box, Ray(o, target - o), 3.5);
    }
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<CaseResult> meshAlongEdgeCases(double effort) {
  // Rays lying along the line of an edge of the convex grid mesh: they only touch it, so
  // whatever crossings are listed must pair up and leave the ray outside. The triangles
  // beside the edge are seen almost edge-on: their t error bounds (which grow as 1/det)
  // exceed t, and their computed t may misorder entering and leaving hits; watertight.cpp
  // then decides t's sign from the origin's exact side of the plane, and the mesh's walk
  // counts a winding number (docs/accuracy.md).
  Rng rng(1602);
  auto hullData = gridHull(rng, 300);
  TriangleMesh hull(hullData, false);
  const auto& P = hullData->positions;
  const auto& T = hullData->triangles;
  const double spans[] = {0.5, 1.0, 2.0, 4.0};
  CaseResult r = newCase("Triangle meshes (exact predicates)",
                         "convex grid mesh: rays along edges (touching only)", 0.0, 0.0);
  for (int i = 0; i < rayCount(20000, effort); ++i) {
    const auto& tri = T[rng() % T.size()];
    int e = int(rng() % 3);
    Vec3 p = P[tri[size_t(e)]], q = P[tri[size_t((e + 1) % 3)]];
    Vec3 d = q - p;
    Ray ray(p - spans[rng() % 4] * d, d);
    ++r.rays;
    CrossingList cl;
    hull.crossings(ray, cl);
    bool in = cl.startsInside;
    bool ok = !in;
    for (const Crossing& c : cl.items) {
      ok = ok && c.entering != in;
      in = c.entering;
    }
    if (!ok || in) problem(r, ray, "crossings along an edge break parity");
  }
  return {r};
}

}  // namespace lucent::accuracy
