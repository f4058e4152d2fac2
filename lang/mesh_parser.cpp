// <mesh src="file"> (OBJ, PLY, OFF or STL, relative to the scene file) or an inline mesh:
//   <mesh positions="x y z ..." indices="i j k ..." [normals="..."] [uvs="u v ..."] smooth="auto"/>
// positions: a multiple of 3 numbers; indices: a multiple of 3 whole numbers, each below
// the vertex count; normals: one per position (normalised); uvs: one pair per position.
// smooth = auto (the file's normals if any) | true (compute vertex normals) | false.
#include "element_parsers.h"

#include "primitives/mesh_io.h"

#include <fmt/format.h>

#include <cmath>

namespace lucent {

namespace {

// Loading keeps what orientation repaired (the mesh is usable, and a solid if closed), but
// says so: a face written backwards is usually a modelling mistake worth knowing of.
void warnRepairs(ElementReader& r, const MeshData& data, const std::string& what) {
  const MeshData::Repairs& repairs = data.repairs;
  if (repairs.flippedFaces == 0) return;
  const bool one = repairs.flippedFaces == 1;
  r.warning(fmt::format("{}: {} of {} {} {} flipped to agree with {} neighbours{}", what,
                        repairs.flippedFaces, repairs.faces,
                        repairs.onlyTriangles ? "triangles" : "faces", one ? "was" : "were",
                        one ? "its" : "their",
                        data.closed ? "; the mesh is closed and is used as a solid" : ""));
}

std::shared_ptr<const MeshData> loadFromFile(ElementReader& r, const std::string& src) {
  FileAccess::Resolved f = r.ctx().files.resolve(src, r.file().folder());
  if (f.path.empty()) {
    r.attrError("src", f.error);
    return nullptr;
  }
  auto& cache = r.ctx().meshCache;
  std::string key = f.path.string();
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  try {
    std::shared_ptr<const MeshData> data = loadMeshFile(key);
    cache.emplace(key, data);
    warnRepairs(r, *data, "<mesh src=\"" + src + "\">");  // once per file, where it is first read
    return data;
  } catch (const std::exception& e) {  // MeshError, and anything a reader library throws
    r.attrError("src", "cannot read the mesh '" + src + "': " + e.what());
    return nullptr;
  }
}

std::shared_ptr<const MeshData> buildInline(ElementReader& r) {
  auto data = std::make_shared<MeshData>();
  auto positions = r.text("positions");
  if (!positions) return nullptr;
  auto p = parseNumberList(*positions);
  if (!p) {
    r.attrError("positions", p.error);
    return nullptr;
  }
  if (p->size() % 3 != 0 || p->empty()) {
    r.attrError("positions", fmt::format("expected x y z for each vertex (a multiple of 3 numbers), got {}", p->size()));
    return nullptr;
  }
  size_t n = p->size() / 3;
  data->positions.reserve(n);
  for (size_t i = 0; i < n; ++i) data->positions.emplace_back((*p)[3 * i], (*p)[3 * i + 1], (*p)[3 * i + 2]);

  bool ok = true;
  if (!r.has("indices")) {
    r.error("<mesh> with 'positions' needs 'indices' (three vertex numbers per triangle)");
    ok = false;
  } else if (auto t = r.text("indices")) {
    auto idx = parseIntegerList(*t);
    if (!idx) {
      r.attrError("indices", idx.error);
      ok = false;
    } else if (idx->empty() || idx->size() % 3 != 0) {
      r.attrError("indices", fmt::format("expected three vertex numbers per triangle (a multiple of 3), got {}", idx->size()));
      ok = false;
    } else {
      data->triangles.reserve(idx->size() / 3);
      for (size_t i = 0; i < idx->size() && ok; i += 3) {
        std::array<uint32_t, 3> tri{};
        for (int k = 0; k < 3; ++k) {
          long long v = (*idx)[i + k];
          if (v < 0 || static_cast<size_t>(v) >= n) {
            r.attrError("indices", fmt::format("index {} (number {} of the list) is outside the {} vertices (0 to {})",
                                               v, i + k + 1, n, n - 1));
            ok = false;
            break;
          }
          tri[k] = static_cast<uint32_t>(v);
        }
        data->triangles.push_back(tri);
      }
    }
  } else {
    ok = false;
  }

  if (auto t = r.text("normals")) {
    auto nl = parseNumberList(*t);
    if (!nl) {
      r.attrError("normals", nl.error);
      ok = false;
    } else if (nl->size() != 3 * n) {
      r.attrError("normals", fmt::format("expected one normal per position ({} numbers), got {}", 3 * n, nl->size()));
      ok = false;
    } else {
      data->normals.reserve(n);
      for (size_t i = 0; i < n && ok; ++i) {
        Vec3 v((*nl)[3 * i], (*nl)[3 * i + 1], (*nl)[3 * i + 2]);
        double len = glm::length(v);
        if (!(len > 0.0) || !std::isfinite(len)) {
          r.attrError("normals", fmt::format("normal {} is the zero vector", i));
          ok = false;
        }
        data->normals.push_back(v / len);
      }
    }
  }
  if (auto t = r.text("uvs")) {
    auto uv = parseNumberList(*t);
    if (!uv) {
      r.attrError("uvs", uv.error);
      ok = false;
    } else if (uv->size() != 2 * n) {
      r.attrError("uvs", fmt::format("expected one u v pair per position ({} numbers), got {}", 2 * n, uv->size()));
      ok = false;
    } else {
      data->uvs.reserve(n);
      for (size_t i = 0; i < n; ++i) data->uvs.emplace_back((*uv)[2 * i], (*uv)[2 * i + 1]);
    }
  }
  if (!ok) return nullptr;
  try {
    finishMesh(*data);
  } catch (const std::exception& e) {
    r.error(std::string("<mesh>: ") + e.what());
    return nullptr;
  }
  warnRepairs(r, *data, "<mesh>");
  return data;
}

}  // namespace

ShapeSpec parseMesh(ElementReader& r) {
  MeshSpec m;
  m.smooth = r.choice("smooth", SmoothMode::Auto,
                      {{"auto", SmoothMode::Auto}, {"true", SmoothMode::True}, {"false", SmoothMode::False}});
  bool hasSrc = r.has("src"), hasInline = r.has("positions");
  if (hasSrc && hasInline) {
    r.error("<mesh> takes either 'src' (a file) or inline 'positions' and 'indices', not both");
  } else if (hasSrc) {
    for (const char* a : {"indices", "normals", "uvs"})
      if (r.has(a)) r.attrError(a, "only an inline mesh (with 'positions') takes this; the file holds its own");
    if (auto src = r.text("src")) {
      m.src = *src;
      m.data = loadFromFile(r, *src);
    }
  } else if (hasInline) {
    m.data = buildInline(r);
  } else {
    r.error("<mesh> needs 'src' (an OBJ, PLY, OFF or STL file) or inline 'positions' and 'indices'");
  }
  if (!m.data && !r.failed()) r.error("<mesh> holds no triangles");
  return m;
}

}  // namespace lucent
