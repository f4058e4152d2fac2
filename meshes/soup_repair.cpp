// Repairing soups (CGAL::Polygon_mesh_processing), for files and inline meshes alike:
//   repair_polygon_soup   merge coincident points, drop faces with < 3 distinct vertices
//                         and duplicate faces
//   orient_polygon_soup   make neighbouring faces agree (non-manifold spots are cut apart)
//   polygon_soup_to_polygon_mesh, triangulate_faces
//   drop zero-area triangles (exact CGAL::collinear); if any were dropped or polygons split,
//   repair and orient the triangle soup again so that closedness is decided on what is kept
//   is_closed             no border edge: the mesh encloses a volume
//   orient_to_bound_a_volume   for closed meshes: every shell outward, a shell nested in
//                         another inward (a hollow ball), so normals point out of the solid
// Normals and texture coordinates are carried over by matching each final triangle to
// the input face it came from by its corner coordinates (CGAL never moves a point); a
// position whose corners disagree (a seam) is split into one vertex per distinct (normal,
// uv). A face turned over by orientation keeps its corners' normals as they are: a vertex
// normal belongs to the vertex, which its unturned neighbours share, and shading turns an
// interpolated normal to the side of its face (triangle_geometry.h).
// triangulate_faces meets a self-intersecting polygon through CGAL's constrained Delaunay
// triangulation, which then prints a performance hint on stderr in builds without NDEBUG;
// the face is simply left untriangulated (and dropped below), so the hint is noise.
#include "mesh_repair.h"

#include "clean_mesh.h"
#include "soup.h"

#include "memory/system_memory.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <tuple>

namespace lucent {
namespace soup {

void checkSoup(const Soup& soup, const char* vertex, const char* vertices, const char* face) {
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const Point& p = soup.points[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw MeshError(
          fmt::format("{} {} (counting from 0) has a non-finite coordinate", vertex, i));
    if (std::max({std::abs(p.x()), std::abs(p.y()), std::abs(p.z())}) > kMaxMagnitude)
      throw MeshError(fmt::format(
          "{} {} (counting from 0) has a coordinate beyond 1e30 in magnitude", vertex, i));
  }
  for (std::size_t f = 0; f < soup.polygons.size(); ++f)
    for (std::size_t index : soup.polygons[f])
      if (index >= soup.points.size())
        throw MeshError(fmt::format("{} {} (counting from 0) uses {} {}, but there are {} {}", face,
                                    f, vertex, index, soup.points.size(), vertices));
}

void checkMemory(const Soup& soup) {
  std::uintmax_t corners = 0;
  for (const Polygon& p : soup.polygons) corners += p.size();
  const std::uintmax_t need =
      soup.points.size() * kPipelineBytesPerPoint + corners * kPipelineBytesPerCorner;
  const std::optional<std::uintmax_t> available = availableMemoryBytes();
  if (available && need > *available)
    throw MeshError(fmt::format(
        "the mesh ({} vertices, {} faces) needs about {} of memory, more than "
        "the {} available",
        soup.points.size(), soup.polygons.size(), formatBytes(need), formatBytes(*available)));
}

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using SurfaceMesh = CGAL::Surface_mesh<Point>;

// Is face f a simple polygon when seen along its Newell normal: no two corners on one
// point, no two edges crossing or touching except neighbours at their shared corner?
// CGAL's constrained Delaunay triangulation of a face works in that projection, and a
// non-simple one crashes it (a null handle in CGAL 5.5: fuzzed OBJ files with a corner
// moved far off the polygon's plane, tests/fuzz/crashes/mesh_obj). Decided in double with
// a relative tolerance, so near-touching edges count as touching: a polygon taken for
// non-simple is only triangulated by a slower method.
bool projectionIsSimple(const SurfaceMesh& mesh, SurfaceMesh::Face_index f) {
  std::vector<Vec3> p;
  for (SurfaceMesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
    const Point& q = mesh.point(v);
    p.emplace_back(q.x(), q.y(), q.z());
  }
  const std::size_t n = p.size();
  Vec3 normal(0.0);
  for (std::size_t i = 0; i < n; ++i) normal += glm::cross(p[i], p[(i + 1) % n]);
  if (!(glm::length(normal) > 0.0)) return false;
  normal = glm::normalize(normal);
  const Vec3 u = glm::normalize(std::abs(normal.x) < 0.9 ? glm::cross(normal, Vec3(1, 0, 0))
                                                         : glm::cross(normal, Vec3(0, 1, 0)));
  const Vec3 w = glm::cross(normal, u);
  std::vector<Vec2> q(n);
  double size = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    q[i] = Vec2(glm::dot(p[i], u), glm::dot(p[i], w));
    size = std::max(size, std::max(std::abs(q[i].x), std::abs(q[i].y)));
  }
  const double tol = 1e-9 * size * size;
  auto orient = [&](const Vec2& a, const Vec2& b, const Vec2& c) {
    const double d = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    return d > tol ? 1 : d < -tol ? -1 : 0;
  };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (glm::length(q[i] - q[j]) <= 1e-9 * size) return false;  // two corners on one point
      if (j == i + 1 || (i == 0 && j == n - 1)) continue;         // neighbouring edges
      const Vec2 &a = q[i], &b = q[(i + 1) % n], &c = q[j], &d = q[(j + 1) % n];
      const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a),
                o4 = orient(c, d, b);
      if (o1 * o2 <= 0 && o3 * o4 <= 0) return false;  // edges i and j cross or touch
    }
  return true;
}

// Splits every polygon into triangles: CGAL's constrained Delaunay triangulation for
// polygons that are simple in projection, its hole filling (cubic in the corners, so only
// up to kMaxHoleFilling corners) for the others. A polygon that is not split stays as it
// is and is dropped later.
void triangulatePolygons(SurfaceMesh& mesh) {
  constexpr std::size_t kMaxHoleFilling = 200;
  std::vector<SurfaceMesh::Face_index> simple, other;
  for (SurfaceMesh::Face_index f : mesh.faces()) {
    if (mesh.degree(f) <= 3) continue;
    (projectionIsSimple(mesh, f) ? simple : other).push_back(f);
  }
  for (SurfaceMesh::Face_index f : other)
    if (mesh.degree(f) <= kMaxHoleFilling)
      PMP::triangulate_face(f, mesh, CGAL::parameters::use_delaunay_triangulation(false));
  PMP::triangulate_faces(simple, mesh);
}

// Notes which polygons orient_polygon_soup turns over (toggled: a polygon turned twice is
// as it was). CGAL copies the visitor, hence the pointer.
struct FlipRecorder : PMP::Default_orientation_visitor {
  std::vector<char>* turned = nullptr;
  void polygon_orientation_reversed(std::size_t polygon) { (*turned)[polygon] ^= 1; }
};

// How many of the oriented soup's polygons disagreed with their neighbours in the input.
// CGAL orients each connected shell from a face of its choosing, and a closed shell may be
// turned over as a whole afterwards (orient_to_bound_a_volume): the faces that were wrong
// are the smaller part of each shell, the turned or the kept ones. Shells are told apart by
// shared points (orientation cuts non-manifold points apart).
std::size_t disagreeingFaces(const Soup& soup, const std::vector<char>& turned) {
  if (std::find(turned.begin(), turned.end(), 1) == turned.end()) return 0;
  std::vector<std::size_t> parent(soup.points.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
  auto root = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const Polygon& p : soup.polygons)
    for (std::size_t k = 1; k < p.size(); ++k) {
      const std::size_t a = root(p[0]), b = root(p[k]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  std::vector<std::size_t> total(soup.points.size(), 0), flipped(soup.points.size(), 0);
  for (std::size_t f = 0; f < soup.polygons.size(); ++f) {
    const std::size_t r = root(soup.polygons[f][0]);
    ++total[r];
    flipped[r] += turned[f] ? 1 : 0;
  }
  std::size_t wrong = 0;
  for (std::size_t r = 0; r < total.size(); ++r)
    wrong += std::min(flipped[r], total[r] - flipped[r]);
  return wrong;
}

// repair → orient → halfedge mesh. The soup is consumed. With `repairs`, the faces that
// orientation turned over are counted there.
SurfaceMesh orientedMesh(Soup& soup, std::size_t inputFaces, MeshData::Repairs* repairs = nullptr) {
  PMP::repair_polygon_soup(soup.points, soup.polygons);
  if (soup.polygons.empty())
    throw MeshError(fmt::format("no usable face: none of the {} faces has three distinct vertices",
                                inputFaces));
  if (repairs) {
    std::vector<char> turned(soup.polygons.size(), 0);
    FlipRecorder recorder;
    recorder.turned = &turned;
    PMP::orient_polygon_soup(soup.points, soup.polygons, CGAL::parameters::visitor(recorder));
    repairs->faces = soup.polygons.size();
    repairs->flippedFaces = disagreeingFaces(soup, turned);
    repairs->onlyTriangles = std::all_of(soup.polygons.begin(), soup.polygons.end(),
                                         [](const Polygon& p) { return p.size() == 3; });
  } else {
    PMP::orient_polygon_soup(soup.points, soup.polygons);
  }
  if (!PMP::is_polygon_soup_a_polygon_mesh(soup.polygons))
    throw MeshError("CGAL could not orient the faces into a consistent surface");
  SurfaceMesh mesh;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
  // A soup CGAL calls a polygon mesh can still come out with face cycles that never
  // close (a damaged PLY found by fuzzing), and every later walk around a face would
  // then run for ever: check the halfedge structure once.
  if (!mesh.is_valid(false))
    throw MeshError("the faces do not form a valid surface (CGAL built an inconsistent mesh)");
  return mesh;
}

// The triangles of `mesh` with nonzero area, as a soup over the mesh's vertices.
Soup usableTriangles(const SurfaceMesh& mesh, std::size_t& dropped) {
  Soup tri;
  tri.points.assign(mesh.points().begin(), mesh.points().end());
  dropped = 0;
  for (SurfaceMesh::Face_index f : mesh.faces()) {
    if (mesh.degree(f) != 3) {  // triangulate_faces gave up: degenerate or self-intersecting
      ++dropped;
      continue;
    }
    Polygon t;
    for (SurfaceMesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      t.push_back(v);
    if (CGAL::collinear(tri.points[t[0]], tri.points[t[1]], tri.points[t[2]])) {
      ++dropped;
      continue;
    }
    tri.polygons.push_back(std::move(t));
  }
  return tri;
}

// A clean closed triangle soup needs none of CGAL's repairs (clean_mesh.h). The check
// runs on a compact copy, and the soup's per-polygon vectors are released meanwhile; when
// it fails the soup is put back exactly as it was.
std::optional<MeshData> cleanClosed(Soup& soup) {
  if (soup.points.size() >= UINT32_MAX) return std::nullopt;
  for (const Polygon& p : soup.polygons)
    if (p.size() != 3) return std::nullopt;
  std::vector<std::array<uint32_t, 3>> triangles;
  triangles.reserve(soup.polygons.size());
  for (const Polygon& p : soup.polygons)
    triangles.push_back({uint32_t(p[0]), uint32_t(p[1]), uint32_t(p[2])});
  std::vector<Vec3> points;
  points.reserve(soup.points.size());
  for (const Point& p : soup.points) points.emplace_back(p.x(), p.y(), p.z());
  soup = Soup();
  std::optional<MeshData> mesh = cleanClosedMesh(points, triangles);
  if (!mesh) {
    soup.points.reserve(points.size());
    for (const Vec3& p : points) soup.points.emplace_back(p.x, p.y, p.z);
    soup.polygons.reserve(triangles.size());
    for (const auto& t : triangles) soup.polygons.push_back({t[0], t[1], t[2]});
  }
  return mesh;
}

// The closed/oriented triangle mesh of `soup`: positions and triangles of the result.
MeshData solidOrSurface(Soup soup) {
  // CGAL's soup functions trust the indices: one past the points (a PLY whose header was
  // damaged, found by fuzzing) builds a halfedge mesh whose face cycles never end.
  for (std::size_t f = 0; f < soup.polygons.size(); ++f)
    for (std::size_t v : soup.polygons[f])
      if (v >= soup.points.size())
        throw MeshError(fmt::format("face {} uses vertex {}, but there are only {} vertices", f + 1,
                                    v, soup.points.size()));
  if (std::optional<MeshData> clean = cleanClosed(soup)) {
    clean->repairs.faces = clean->triangles.size();
    return std::move(*clean);
  }
  const std::size_t inputFaces = soup.polygons.size();
  MeshData::Repairs repairs;
  SurfaceMesh mesh = orientedMesh(soup, inputFaces, &repairs);
  bool split = false;
  for (SurfaceMesh::Face_index f : mesh.faces()) split |= mesh.degree(f) > 3;
  triangulatePolygons(mesh);
  // On some damaged polygons CGAL 5.5's triangulation leaves broken face cycles, and
  // walking around such a face never ends (PLY files found by fuzzing,
  // tests/fuzz/crashes/mesh_ply): check the halfedge structure before anything walks it.
  if (!mesh.is_valid(false))
    throw MeshError(
        "its polygons could not be split into triangles (a damaged or self-overlapping polygon)");
  std::size_t dropped = 0;
  Soup triangles = usableTriangles(mesh, dropped);
  if (triangles.polygons.empty())
    throw MeshError(
        fmt::format("no usable triangle: all {} faces are degenerate (zero area)", inputFaces));
  // Splitting a polygon can add an edge between two vertices that are already joined (a
  // polygon and triangles covering it: a flat "pillow"); the halfedge mesh allows such a
  // double edge, but then an edge is shared by more than two triangles. Going through the
  // soup again merges duplicate triangles and cuts what is not manifold.
  if (dropped > 0 || split) mesh = orientedMesh(triangles, inputFaces);

  MeshData out;
  out.repairs = repairs;
  out.closed = CGAL::is_closed(mesh);
  if (out.closed) PMP::orient_to_bound_a_volume(mesh);

  std::vector<uint32_t> newIndex(mesh.number_of_vertices(), UINT32_MAX);
  for (SurfaceMesh::Face_index f : mesh.faces()) {
    std::array<uint32_t, 3> t{};
    int k = 0;
    for (SurfaceMesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      if (newIndex[v] == UINT32_MAX) {
        newIndex[v] = static_cast<uint32_t>(out.positions.size());
        const Point& p = mesh.point(v);
        out.positions.emplace_back(p.x(), p.y(), p.z());
      }
      t[k++] = newIndex[v];
    }
    out.triangles.push_back(t);
  }
  return out;
}

bool lexLess(const Vec3& a, const Vec3& b) {
  return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
}

// Gives `out` the normals/uvs of the input corners each of its triangle corners came from,
// splitting positions where those differ. Returns false (attributes left empty) if some
// triangle cannot be traced back, which CGAL's operations should never cause.
bool carryAttributes(const Soup& input, const CornerAttributes& attrs, MeshData& out) {
  struct Entry {
    Vec3 p;
    uint32_t polygon, corner;
  };
  std::vector<Entry> entries;
  for (std::size_t f = 0; f < input.polygons.size(); ++f)
    for (std::size_t j = 0; j < input.polygons[f].size(); ++j) {
      const Point& q = input.points[input.polygons[f][j]];
      entries.push_back(
          {Vec3(q.x(), q.y(), q.z()), static_cast<uint32_t>(f), static_cast<uint32_t>(j)});
    }
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return lexLess(a.p, b.p); });
  auto cornerAt = [&](uint32_t f, const Vec3& p) -> int {
    const Polygon& poly = input.polygons[f];
    for (std::size_t j = 0; j < poly.size(); ++j) {
      const Point& q = input.points[poly[j]];
      if (q.x() == p.x && q.y() == p.y && q.z() == p.z) return static_cast<int>(j);
    }
    return -1;
  };

  const bool withNormals = !attrs.normals.empty(), withUVs = !attrs.uvs.empty();
  struct Variant {
    int32_t normal, uv;
    uint32_t index;
  };
  std::vector<std::vector<Variant>> variants(out.positions.size());
  MeshData result;
  result.closed = out.closed;
  result.repairs = out.repairs;
  for (const auto& t : out.triangles) {
    const Vec3 p[3] = {out.positions[t[0]], out.positions[t[1]], out.positions[t[2]]};
    auto range = std::equal_range(entries.begin(), entries.end(), Entry{p[0], 0, 0},
                                  [](const Entry& a, const Entry& b) { return lexLess(a.p, b.p); });
    int corners[3] = {-1, -1, -1};
    uint32_t face = 0;
    for (auto e = range.first; e != range.second && corners[0] < 0; ++e) {
      const int c1 = cornerAt(e->polygon, p[1]), c2 = cornerAt(e->polygon, p[2]);
      if (c1 >= 0 && c2 >= 0) {
        corners[0] = static_cast<int>(e->corner), corners[1] = c1, corners[2] = c2;
        face = e->polygon;
      }
    }
    if (corners[0] < 0) return false;
    std::array<uint32_t, 3> newTriangle{};
    for (int k = 0; k < 3; ++k) {
      const std::size_t corner = attrs.polygonStart[face] + static_cast<std::size_t>(corners[k]);
      const int32_t n = withNormals ? attrs.normalOf[corner] : -1;
      const int32_t uv = withUVs ? attrs.uvOf[corner] : -1;
      auto& list = variants[t[k]];
      auto it = std::find_if(list.begin(), list.end(),
                             [&](const Variant& v) { return v.normal == n && v.uv == uv; });
      if (it == list.end()) {
        list.push_back({n, uv, static_cast<uint32_t>(result.positions.size())});
        result.positions.push_back(p[k]);
        if (withNormals) result.normals.push_back(attrs.normals[static_cast<std::size_t>(n)]);
        if (withUVs) result.uvs.push_back(attrs.uvs[static_cast<std::size_t>(uv)]);
        it = list.end() - 1;
      }
      newTriangle[k] = it->index;
    }
    result.triangles.push_back(newTriangle);
  }
  out = std::move(result);
  return true;
}

}  // namespace

MeshData repairSoup(Soup soup, const CornerAttributes& attrs) {
  std::optional<Soup> input;
  if (attrs.any()) input = soup;  // the pipeline consumes the soup; tracing needs the original
  MeshData mesh = solidOrSurface(std::move(soup));
  if (input) carryAttributes(*input, attrs, mesh);
  return mesh;
}

}  // namespace soup

using namespace soup;

void finishMesh(MeshData& mesh) {
  const std::size_t n = mesh.positions.size();
  if (mesh.triangles.empty()) throw MeshError("the mesh has no triangles");
  if (!mesh.normals.empty() && mesh.normals.size() != n)
    throw MeshError(fmt::format("{} normals for {} positions: give one normal per position",
                                mesh.normals.size(), n));
  if (!mesh.uvs.empty() && mesh.uvs.size() != n)
    throw MeshError(
        fmt::format("{} uvs for {} positions: give one uv per position", mesh.uvs.size(), n));

  CornerAttributes attrs;
  for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
    const double length = glm::length(mesh.normals[i]);
    if (!(length > 0) || !std::isfinite(length))
      throw MeshError(fmt::format("normal {} (counting from 0) is zero or not finite", i));
    attrs.normals.push_back(mesh.normals[i] / length);
  }
  for (std::size_t i = 0; i < mesh.uvs.size(); ++i) {
    if (!std::isfinite(mesh.uvs[i].x) || !std::isfinite(mesh.uvs[i].y))
      throw MeshError(fmt::format("uv {} (counting from 0) is not finite", i));
  }
  attrs.uvs = mesh.uvs;

  Soup soup;
  soup.points.reserve(n);
  for (const Vec3& p : mesh.positions) soup.points.emplace_back(p.x, p.y, p.z);
  soup.polygons.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    soup.polygons.push_back({t[0], t[1], t[2]});
    if (attrs.any()) {
      attrs.polygonStart.push_back(attrs.normalOf.size());
      for (uint32_t v : t) {
        attrs.normalOf.push_back(static_cast<int32_t>(v));
        attrs.uvOf.push_back(static_cast<int32_t>(v));
      }
    }
  }
  checkSoup(soup, "position", "positions", "triangle");
  checkMemory(soup);
  mesh = guarded([&] { return repairSoup(std::move(soup), attrs); });
}

}  // namespace lucent
