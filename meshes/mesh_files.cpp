// Reading mesh files (OBJ, PLY, OFF, STL) with CGAL 5.5's readers. Files are first walked
// by the checks in mesh_file_check.h / obj_scan.h (CGAL's readers trust the counts they
// find, and drop normals and texture coordinates, which the checks keep), then read by
// CGAL from the same bytes into a soup that soup_repair.cpp turns into a mesh.
#include "mesh_files.h"

#include "obj_scan.h"
#include "soup.h"

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>
#include <malloc.h>
#include <boost/iostreams/device/array.hpp>
#include <boost/iostreams/stream.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace lucent {
namespace {

using namespace soup;

// `expected`: the counts the checks found, if they know them. Reserving them spares the
// reader's containers their doublings (each a copy, and fresh pages to fault in).
Soup readSoup(const std::string& bytes, MeshFormat format, MeshCounts expected) {
  boost::iostreams::stream<boost::iostreams::array_source> in(bytes.data(), bytes.size());
  Capped<std::vector<Point>, Cap::Vertices> points;
  Capped<HugeVector<Polygon>, Cap::Faces> polygons;
  points.reserve(std::min(expected.vertices, kMaxMeshVertices));
  polygons.reserve(std::min(expected.faces, kMaxMeshFaces));
  const auto quiet = CGAL::parameters::verbose(false);
  bool ok = false;
  switch (format) {
    case MeshFormat::Obj:
      ok = CGAL::IO::read_OBJ(in, points, polygons, quiet);
      break;
    case MeshFormat::Off:
      ok = CGAL::IO::read_OFF(in, points, polygons, quiet);
      break;
    case MeshFormat::Ply:
      ok = CGAL::IO::read_PLY(in, points, polygons, quiet);
      break;
    case MeshFormat::Stl:
      ok = CGAL::IO::read_STL(in, points, polygons, quiet);
      break;
  }
  if (!ok)
    throw MeshError(
        fmt::format("CGAL's {} reader could not read the file (malformed or truncated data)",
                    meshFormatName(format)));
  // Moved, not copied: the polygons are most of a large mesh's memory.
  Soup soup;
  soup.points = std::move(static_cast<std::vector<Point>&>(points));
  soup.polygons = std::move(static_cast<HugeVector<Polygon>&>(polygons));
  return soup;
}

// OBJ corners → attributes, when every corner has one (MeshData holds all or nothing).
CornerAttributes objAttributes(const ObjScan& scan, const Soup& soup) {
  CornerAttributes attrs;
  if (scan.faceCount() != soup.polygons.size()) return attrs;  // CGAL read it differently
  for (std::size_t f = 0; f < scan.faceCount(); ++f)
    if (scan.faceStart[f + 1] - scan.faceStart[f] != soup.polygons[f].size()) return attrs;
  const bool normals = !scan.normals.empty() && scan.everyCornerHasNormal;
  const bool uvs = !scan.texcoords.empty() && scan.everyCornerHasTexcoord;
  if (normals) attrs.normals = scan.normals;
  if (uvs) attrs.uvs = scan.texcoords;
  attrs.polygonStart.assign(scan.faceStart.begin(), scan.faceStart.end());
  for (const ObjScan::Corner& c : scan.corners) {
    attrs.normalOf.push_back(c.normal);
    attrs.uvOf.push_back(c.texcoord);
  }
  return attrs;
}

// Per-vertex attributes of a PLY or OFF file → corner attributes (each corner takes its
// vertex's). All or nothing, as for OBJ: normals only if every vertex a face uses has a
// nonzero finite one, uvs only if every such vertex has finite ones. Vertex i of the file
// is point i of CGAL's soup, which both readers fill in file order; a count that differs
// (CGAL read the file otherwise) keeps nothing.
CornerAttributes vertexAttributes(const VertexAttributes& file, const Soup& soup) {
  CornerAttributes attrs;
  const std::size_t n = soup.points.size();
  bool normals = file.normals.size() == n && n > 0, uvs = file.uvs.size() == n && n > 0;
  for (const Polygon& p : soup.polygons)
    for (std::size_t v : p) {
      if (normals) {
        const double length = glm::length(file.normals[v]);
        normals = length > 0 && std::isfinite(length);
      }
      if (uvs) uvs = std::isfinite(file.uvs[v].x) && std::isfinite(file.uvs[v].y);
    }
  if (normals) {
    attrs.normals.reserve(n);
    for (const Vec3& normal : file.normals) {
      const double length = glm::length(normal);
      attrs.normals.push_back(length > 0 && std::isfinite(length) ? normal / length
                                                                  : Vec3(0, 0, 1));
    }
  }
  if (uvs) attrs.uvs = file.uvs;
  if (!attrs.any()) return attrs;
  attrs.polygonStart.reserve(soup.polygons.size());
  for (const Polygon& p : soup.polygons) {
    attrs.polygonStart.push_back(attrs.normalOf.size());
    for (std::size_t v : p) {
      attrs.normalOf.push_back(static_cast<int32_t>(v));
      attrs.uvOf.push_back(static_cast<int32_t>(v));
    }
  }
  return attrs;
}

}  // namespace

std::shared_ptr<MeshData> loadMeshFile(const std::string& path) {
  const MeshFormat format = meshFormatOf(path);
  return loadMeshBytes(readMeshFile(path), format);
}

std::shared_ptr<MeshData> loadMeshBytes(std::string bytes, MeshFormat format) {
  std::optional<ObjScan> obj;
  VertexAttributes vertex;  // PLY and OFF
  MeshCounts counts;
  switch (format) {
    case MeshFormat::Obj:
      obj = scanObj(bytes);
      counts = {obj->vertexCount, obj->faceCount()};
      break;
    case MeshFormat::Ply:
      counts = checkPlyBytes(bytes, &vertex);
      break;
    case MeshFormat::Off:
      checkOffBytes(bytes, &vertex);
      break;
    case MeshFormat::Stl:
      checkStlBytes(bytes);
      break;
  }
  return guarded([&] {
    Soup soup = readSoup(bytes, format, counts);
    // Releases the text before the mesh is built (assigning an empty string would keep
    // the buffer: libstdc++ copies a short string into the existing capacity).
    std::string().swap(bytes);
    checkSoup(soup, "vertex", "vertices", "face");
    if (soup.polygons.empty()) throw MeshError("the file holds no faces");
    checkMemory(soup);
    CornerAttributes attrs;
    if (obj) attrs = objAttributes(*obj, soup);
    else attrs = vertexAttributes(vertex, soup);
    obj.reset();
    vertex = VertexAttributes();
    auto mesh = std::make_shared<MeshData>(repairSoup(std::move(soup), attrs));
    // The soup and the repair's working arrays are freed by now, but glibc keeps such
    // blocks for reuse, and the BVH build that comes next takes its memory in huge pages
    // of its own: hand them back, or a large mesh's peak counts them twice
    // (docs/performance-history.md, "Mesh loading").
    ::malloc_trim(0);
    return mesh;
  });
}

}  // namespace lucent
