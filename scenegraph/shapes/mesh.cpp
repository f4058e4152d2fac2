// <mesh src="file"> (OBJ, PLY, OFF or STL, relative to the scene file) or an inline mesh:
//   <mesh positions="x y z ..." indices="i j k ..." [normals="..."] [uvs="u v ..."] smooth="auto"/>
// positions: a multiple of 3 numbers; indices: a multiple of 3 whole numbers, each below
// the vertex count; normals: one per position (normalised); uvs: one pair per position.
// smooth = auto (the file's normals if any) | true (compute vertex normals) | false.
// A solid when closed and consistently oriented (primitives/triangle_mesh.h).
#include "mesh_lists.h"

#include "scenegraph/shape_type.h"

#include "meshes/mesh_repair.h"
#include "primitives/triangle_mesh.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace lucent {

namespace {

// Loading keeps what orientation repaired (the mesh is usable, and a solid if closed), but
// says so: a face written backwards is usually a modelling mistake worth knowing of.
void warnRepairs(AttributeInput& in, const MeshData& data, const std::string& what) {
  const MeshData::Repairs& repairs = data.repairs;
  if (repairs.flippedFaces == 0) return;
  const bool one = repairs.flippedFaces == 1;
  in.warning(fmt::format(
      "{}: {} of {} {} {} flipped to agree with {} neighbours{}", what, repairs.flippedFaces,
      repairs.faces, repairs.onlyTriangles ? "triangles" : "faces", one ? "was" : "were",
      one ? "its" : "their", data.closed ? "; the mesh is closed and is used as a solid" : ""));
}

bool readIndices(AttributeInput& in, MeshData& data) {
  if (!in.has("indices")) {
    in.error("<mesh> with 'positions' needs 'indices' (three vertex numbers per triangle)");
    return false;
  }
  auto idx = in.integers("indices");
  if (!idx) return false;
  if (idx->empty() || idx->size() % 3 != 0) {
    in.attrError("indices",
                 fmt::format("expected three vertex numbers per triangle (a multiple of 3), got {}",
                             idx->size()));
    return false;
  }
  const size_t n = data.positions.size();
  data.triangles.reserve(idx->size() / 3);
  for (size_t i = 0; i < idx->size(); i += 3) {
    std::array<uint32_t, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      long long v = (*idx)[i + k];
      if (v < 0 || static_cast<size_t>(v) >= n) {
        in.attrError(
            "indices",
            fmt::format("index {} (number {} of the list) is outside the {} vertices (0 to {})", v,
                        i + k + 1, n, n - 1));
        return false;
      }
      tri[k] = static_cast<uint32_t>(v);
    }
    data.triangles.push_back(tri);
  }
  return true;
}

bool readNormals(AttributeInput& in, MeshData& data) {
  auto nl = in.numbers("normals");
  if (!nl) return !in.has("normals");
  const size_t n = data.positions.size();
  if (nl->size() != 3 * n) {
    in.attrError("normals", fmt::format("expected one normal per position ({} numbers), got {}",
                                        3 * n, nl->size()));
    return false;
  }
  data.normals.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    Vec3 v((*nl)[3 * i], (*nl)[3 * i + 1], (*nl)[3 * i + 2]);
    double len = glm::length(v);
    if (!(len > 0.0) || !std::isfinite(len)) {
      in.attrError("normals", fmt::format("normal {} is the zero vector", i));
      return false;
    }
    data.normals.push_back(v / len);
  }
  return true;
}

bool readUvs(AttributeInput& in, MeshData& data) {
  auto uv = in.numbers("uvs");
  if (!uv) return !in.has("uvs");
  const size_t n = data.positions.size();
  if (uv->size() != 2 * n) {
    in.attrError("uvs", fmt::format("expected one u v pair per position ({} numbers), got {}",
                                    2 * n, uv->size()));
    return false;
  }
  data.uvs.reserve(n);
  for (size_t i = 0; i < n; ++i) data.uvs.emplace_back((*uv)[2 * i], (*uv)[2 * i + 1]);
  return true;
}

// The inline lists as written: no repair, no finishing.
std::shared_ptr<MeshData> readLists(AttributeInput& in) {
  auto p = in.numbers("positions");
  if (!p) return nullptr;
  if (p->size() % 3 != 0 || p->empty()) {
    in.attrError(
        "positions",
        fmt::format("expected x y z for each vertex (a multiple of 3 numbers), got {}", p->size()));
    return nullptr;
  }
  auto data = std::make_shared<MeshData>();
  for (size_t i = 0; i < p->size(); i += 3)
    data->positions.emplace_back((*p)[i], (*p)[i + 1], (*p)[i + 2]);
  bool ok = readIndices(in, *data);
  ok = readNormals(in, *data) && ok;
  ok = readUvs(in, *data) && ok;
  if (!ok) return nullptr;
  return data;
}

std::shared_ptr<const MeshData> buildInline(AttributeInput& in) {
  std::shared_ptr<MeshData> data = readLists(in);
  if (!data) return nullptr;
  try {
    finishMesh(*data);
  } catch (const std::exception& e) {
    in.error(std::string("<mesh>: ") + e.what());
    return nullptr;
  }
  warnRepairs(in, *data, "<mesh>");
  return data;
}

}  // namespace

std::shared_ptr<const MeshData> readMeshLists(AttributeInput& in) {
  if (!in.has("positions")) {
    in.error(
        "a mesh camera's <mesh> needs inline 'positions' and 'indices' (its faces in "
        "order)");
    return nullptr;
  }
  return readLists(in);
}

namespace {

void readMesh(MeshSpec& m, AttributeInput& in) {
  m.smooth = static_cast<SmoothMode>(in.choice("smooth", 0, {"auto", "true", "false"}));
  bool hasSrc = in.has("src"), hasInline = in.has("positions");
  if (hasSrc && hasInline) {
    in.error("<mesh> takes either 'src' (a file) or inline 'positions' and 'indices', not both");
  } else if (hasSrc) {
    for (const char* a : {"indices", "normals", "uvs"})
      if (in.has(a))
        in.attrError(a,
                     "only an inline mesh (with 'positions') takes this; the file holds its own");
    if (auto src = in.text("src")) {
      m.src = *src;
      bool firstRead = false;
      m.data = in.meshFile("src", &firstRead);
      if (m.data && firstRead)
        warnRepairs(in, *m.data, "<mesh src=\"" + *src + "\">");  // once per file
    }
  } else if (hasInline) {
    m.data = buildInline(in);
  } else {
    in.error(
        "<mesh> needs 'src' (an OBJ, PLY, OFF or STL file) or inline 'positions' and 'indices'");
  }
  if (!m.data && !in.failed()) in.error("<mesh> holds no triangles");
}

std::shared_ptr<const Shape> buildMesh(const MeshSpec& s) {
  if (!s.data) throw std::invalid_argument("makeShape: <mesh> has no data");
  switch (s.smooth) {
    case SmoothMode::Auto:  // the file's normals if it has them, else flat
      return std::make_shared<TriangleMesh>(s.data, !s.data->normals.empty());
    case SmoothMode::False:
      return std::make_shared<TriangleMesh>(s.data, false);
    case SmoothMode::True: {
      // Computed normals replace any the file had: a copy of the data owned by this shape
      // (a shape is built once per node, and every <use> shares it).
      auto smoothed = std::make_shared<MeshData>(*s.data);
      smoothed->normals = computeVertexNormals(*smoothed);
      return std::make_shared<TriangleMesh>(std::move(smoothed), true);
    }
  }
  throw std::invalid_argument("makeShape: unknown smooth mode");
}

// A unit octahedron, closed and outward oriented, with the axis directions as vertex
// normals and (u,v) = (x, y); and an open square of two triangles.
std::vector<std::pair<std::string, MeshSpec>> meshSamples() {
  auto oct = std::make_shared<MeshData>();
  oct->positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  oct->normals = oct->positions;
  for (const Vec3& p : oct->positions) oct->uvs.push_back({p.x, p.y});
  oct->triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                    {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  oct->closed = true;
  auto square = std::make_shared<MeshData>();
  square->positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  square->triangles = {{0, 1, 2}, {0, 2, 3}};
  return {{"octahedron mesh", {"", SmoothMode::Auto, oct}},
          {"flat octahedron mesh", {"", SmoothMode::False, oct}},
          {"open mesh", {"", SmoothMode::Auto, square}}};
}

}  // namespace

template <>
ShapeEntry<MeshSpec> shapeEntry<MeshSpec>() {
  ShapeEntry<MeshSpec> e("mesh", "meshes", buildMesh, [](const MeshSpec& s, PovShapeOut& out) {
    out.open("object");
    out.line(out.declaredMesh(s));
  });
  e.doc =
      "A triangle mesh from a file (src) or inline (positions, indices); solid if closed and "
      "consistently oriented.";
  e.fields = {readByEntry<MeshSpec>("src", AttrType::File)
                  .doc("An OBJ, PLY, OFF or STL file, relative to the scene file. Either src or "
                       "positions + indices."),
              readByEntry<MeshSpec>("positions", AttrType::NumberList, "", {}, 3)
                  .doc("Inline mesh: vertex positions, three numbers each."),
              readByEntry<MeshSpec>("indices", AttrType::IntegerList, "", {}, 3)
                  .doc("Inline mesh: triangles, three 0-based vertex indices each, "
                       "counter-clockwise seen from outside."),
              readByEntry<MeshSpec>("normals", AttrType::NumberList, "", {}, 3)
                  .doc("Inline mesh: one normal (three numbers) per position; normalised and "
                       "interpolated like a triangle's vertex normals. Optional."),
              readByEntry<MeshSpec>("uvs", AttrType::NumberList, "", {}, 2)
                  .doc("Inline mesh: one (u,v) pair per position, for image textures. Optional."),
              readByEntry<MeshSpec>("smooth", AttrType::Choice, "auto", {"auto", "true", "false"})
                  .doc("auto (use the file's or the inline normals if any) | true (compute vertex "
                       "normals) | false (flat).")};
  e.finish = readMesh;
  e.notSolid = [](const MeshSpec& s) {
    return s.data && s.data->closed
               ? std::string()
               : std::string("the mesh is not closed and consistently oriented");
  };
  e.triangles = [](const MeshSpec& s) {
    return s.data ? static_cast<long long>(s.data->triangles.size()) : 0LL;
  };
  // The mesh's own uv_vectors (uv_mapping), when it has one uv per position.
  e.povImageMapping = [](const MeshSpec& s) {
    ImageMapping m;
    if (s.data && !s.data->uvs.empty() && s.data->uvs.size() == s.data->positions.size())
      m.kind = ImageMapping::MeshUV;
    return m;
  };
  e.samples = meshSamples;
  return e;
}

}  // namespace lucent
