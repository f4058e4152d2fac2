// Vertex normals and texture coordinates from PLY (ASCII and binary) and OFF files: small
// files written here with known values, and Debian's assimp PLY models compared with a
// reading of their text made here. Each loaded vertex is matched to the file's vertices by
// its position (the loader renumbers and splits positions, never moves them).
#include "mesh_test_support.h"

#include "meshes/mesh_files.h"

#include <fmt/format.h>

#include <cstring>
#include <sstream>
#include <vector>

using namespace lucent;
using namespace lucent::meshtest;

namespace {

struct FileVertex {
  Vec3 p, n;
  Vec2 uv;
};

// A tetrahedron, counter-clockwise seen from outside, with a distinct normal and uv per
// vertex (the normals are not unit length: the loader normalises them).
const std::vector<FileVertex> kTetra = {
    {{0, 0, 0}, {-1, -1, -1}, {0.0, 0.0}},
    {{1, 0, 0}, {2, 0, 0}, {1.0, 0.0}},
    {{0, 1, 0}, {0, 3, 0}, {0.0, 1.0}},
    {{0, 0, 1}, {0, 0, 0.5}, {0.25, 0.75}},
};
const std::vector<std::array<int, 3>> kTetraFaces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

// The file vertex at the loaded position i; fails if none or several.
const FileVertex& fileVertexAt(const MeshData& m, uint32_t i, const std::vector<FileVertex>& file) {
  const FileVertex* found = nullptr;
  for (const FileVertex& v : file)
    if (v.p == m.positions[i]) {
      REQUIRE(found == nullptr);
      found = &v;
    }
  REQUIRE(found != nullptr);
  return *found;
}

void requireAttributesOf(const MeshData& m, const std::vector<FileVertex>& file, bool normals,
                         bool uvs) {
  requireWellFormed(m);
  REQUIRE(m.normals.empty() == !normals);
  REQUIRE(m.uvs.empty() == !uvs);
  for (uint32_t i = 0; i < m.positions.size(); ++i) {
    const FileVertex& v = fileVertexAt(m, i, file);
    if (normals) CHECK(glm::length(m.normals[i] - glm::normalize(v.n)) < 1e-7);
    if (uvs) CHECK(glm::length(m.uvs[i] - v.uv) < 1e-7);
  }
}

std::string asciiPly(const std::vector<FileVertex>& vs,
                     const std::vector<std::array<int, 3>>& faces, const std::string& uvNames,
                     bool colours) {
  std::ostringstream out;
  out << "ply\nformat ascii 1.0\ncomment written by mesh_attributes_test\n"
      << "element vertex " << vs.size()
      << "\nproperty float x\nproperty float y\nproperty float z\n";
  if (colours) out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  out << "property float nx\nproperty float ny\nproperty float nz\n";
  std::istringstream names(uvNames);
  std::string u, v;
  names >> u >> v;
  out << "property float " << u << "\nproperty float " << v << "\n";
  out << "element face " << faces.size()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const FileVertex& x : vs) {
    out << x.p.x << ' ' << x.p.y << ' ' << x.p.z << ' ';
    if (colours) out << "255 128 0 ";
    out << x.n.x << ' ' << x.n.y << ' ' << x.n.z << ' ' << x.uv.x << ' ' << x.uv.y << '\n';
  }
  for (const auto& f : faces) out << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
  return out.str();
}

template <class T>
void put(std::string& bytes, T value) {  // little-endian on the machines Lucent runs on
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  bytes.append(b, sizeof(T));
}

// Binary little-endian, positions and normals as double, uvs as float named texture_u/v.
std::string binaryPly(const std::vector<FileVertex>& vs,
                      const std::vector<std::array<int, 3>>& faces) {
  std::string bytes = fmt::format(
      "ply\nformat binary_little_endian 1.0\nelement vertex {}\n"
      "property double x\nproperty double y\nproperty double z\n"
      "property double nx\nproperty double ny\nproperty double nz\n"
      "property float texture_u\nproperty float texture_v\nproperty uchar alpha\n"
      "element face {}\nproperty list uchar uint vertex_indices\nend_header\n",
      vs.size(), faces.size());
  for (const FileVertex& x : vs) {
    for (double c : {x.p.x, x.p.y, x.p.z, x.n.x, x.n.y, x.n.z}) put<double>(bytes, c);
    put<float>(bytes, static_cast<float>(x.uv.x));
    put<float>(bytes, static_cast<float>(x.uv.y));
    put<uint8_t>(bytes, 200);
  }
  for (const auto& f : faces) {
    put<uint8_t>(bytes, 3);
    for (int i : f) put<uint32_t>(bytes, static_cast<uint32_t>(i));
  }
  return bytes;
}

}  // namespace

TEST_CASE("PLY vertex normals and texture coordinates are kept, ASCII and binary",
          "[mesh][attributes]") {
  TempDir dir;
  for (const char* names : {"s t", "u v", "texture_u texture_v", "texture_s texture_t"}) {
    INFO(names);
    const auto mesh =
        loadMeshFile(dir.write("tetra.ply", asciiPly(kTetra, kTetraFaces, names, false)));
    CHECK(mesh->closed);
    CHECK(mesh->positions.size() == 4);
    requireAttributesOf(*mesh, kTetra, true, true);
  }
  SECTION("colours are read and ignored") {
    const auto mesh =
        loadMeshFile(dir.write("tetra.ply", asciiPly(kTetra, kTetraFaces, "s t", true)));
    requireAttributesOf(*mesh, kTetra, true, true);
  }
  SECTION("binary little-endian") {
    const auto mesh = loadMeshFile(dir.write("tetra.ply", binaryPly(kTetra, kTetraFaces)));
    CHECK(mesh->closed);
    requireAttributesOf(*mesh, kTetra, true, true);
    // A uv written as float comes back as that float.
    for (uint32_t i = 0; i < mesh->positions.size(); ++i)
      if (mesh->positions[i] == Vec3(0, 0, 1)) CHECK(mesh->uvs[i] == Vec2(0.25, 0.75));
  }
  SECTION("a pair with one name missing is not a uv") {
    std::string text = asciiPly(kTetra, kTetraFaces, "s q", false);
    const auto mesh = loadMeshFile(dir.write("tetra.ply", text));
    requireAttributesOf(*mesh, kTetra, true, false);
  }
}

TEST_CASE("PLY: a zero normal a face uses drops the file's normals, not its uvs",
          "[mesh][attributes]") {
  TempDir dir;
  std::vector<FileVertex> vs = kTetra;
  vs[2].n = Vec3(0);
  const auto mesh = loadMeshFile(dir.write("tetra.ply", asciiPly(vs, kTetraFaces, "s t", false)));
  requireAttributesOf(*mesh, vs, false, true);
}

TEST_CASE("PLY: faces turned over by orientation keep the file's vertex normals",
          "[mesh][attributes]") {
  // The last face written backwards: orientation turns it over (and the warning counts it),
  // but the normals stay those of the file at every position.
  TempDir dir;
  std::vector<std::array<int, 3>> faces = kTetraFaces;
  std::swap(faces[3][1], faces[3][2]);
  const auto mesh = loadMeshFile(dir.write("tetra.ply", asciiPly(kTetra, faces, "s t", false)));
  CHECK(mesh->closed);
  CHECK(signedVolume(*mesh) == Approx(1.0 / 6).margin(1e-12));
  CHECK(mesh->repairs.flippedFaces == 1);
  CHECK(mesh->repairs.faces == 4);
  requireAttributesOf(*mesh, kTetra, true, true);
}

TEST_CASE("OFF: NOFF and CNOFF vertex normals are kept, plain and COFF have none",
          "[mesh][attributes]") {
  TempDir dir;
  auto off = [&](const std::string& keyword, bool normals, bool colours) {
    std::string text = keyword + "\n4 4 6\n";
    for (const FileVertex& v : kTetra) {
      text += fmt::format("{} {} {}", v.p.x, v.p.y, v.p.z);
      if (normals) text += fmt::format("  {} {} {}", v.n.x, v.n.y, v.n.z);
      if (colours) text += "  0.5 0.25 1 1";
      text += "\n";
    }
    for (const auto& f : kTetraFaces) text += fmt::format("3 {} {} {}\n", f[0], f[1], f[2]);
    return loadMeshFile(dir.write("tetra.off", text));
  };
  requireAttributesOf(*off("NOFF", true, false), kTetra, true, false);
  requireAttributesOf(*off("CNOFF", true, true), kTetra, true, false);
  requireAttributesOf(*off("OFF", false, false), kTetra, false, false);
  requireAttributesOf(*off("COFF", false, true), kTetra, false, false);
}

namespace {

// The vertices of an ASCII PLY whose vertex element is x y z nx ny nz s t, all float, read
// with nothing but the header's layout.
std::vector<FileVertex> readXyzNxyzSt(const std::string& path) {
  std::istringstream in(readMeshFile(path));
  std::string line;
  std::size_t count = 0;
  std::vector<std::string> properties;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string word, type, name;
    words >> word;
    if (word == "element") {
      words >> name;
      if (name == "vertex") words >> count;
    } else if (word == "property" && properties.size() < 8 && count > 0) {
      words >> type >> name;
      properties.push_back(name);
    } else if (word == "end_header") {
      break;
    }
  }
  REQUIRE(properties == std::vector<std::string>{"x", "y", "z", "nx", "ny", "nz", "s", "t"});
  std::vector<FileVertex> vs(count);
  for (FileVertex& v : vs) {
    float f[8];
    for (float& x : f) REQUIRE(in >> x);
    v = {Vec3(f[0], f[1], f[2]), Vec3(f[3], f[4], f[5]), Vec2(f[6], f[7])};
  }
  return vs;
}

}  // namespace

TEST_CASE("assimp's PLY models with nx and s t load their normals and uvs",
          "[mesh][attributes][assimp]") {
  const std::string models = "/usr/share/assimp/models/PLY/";
  if (!std::filesystem::is_directory(models))
    FAIL(models + " is missing: run scripts/install-deps (it installs assimp-testmodels)");

  SECTION(
      "cube_uv.ply: each face's normals are the face's own, its uvs the unit square's corners") {
    const auto mesh = loadMeshFile(models + "cube_uv.ply");
    CHECK(mesh->closed);
    CHECK(mesh->positions.size() == 24);  // four corners per face: normals and uvs differ
    const auto file = readXyzNxyzSt(models + "cube_uv.ply");
    for (const auto& t : mesh->triangles) {
      const Vec3 face = glm::normalize(glm::cross(mesh->positions[t[1]] - mesh->positions[t[0]],
                                                  mesh->positions[t[2]] - mesh->positions[t[0]]));
      for (uint32_t i : t) {
        CHECK(glm::dot(mesh->normals[i], face) > 0.999999);
        const Vec2 uv = mesh->uvs[i];
        CHECK(((uv.x == 0 || uv.x == 1) && (uv.y == 0 || uv.y == 1)));
        // The file's vertex with this position and normal has this uv.
        bool found = false;
        for (const FileVertex& v : file)
          found |= v.p == mesh->positions[i] &&
                   glm::length(glm::normalize(v.n) - mesh->normals[i]) < 1e-7 && v.uv == uv;
        CHECK(found);
      }
    }
  }
  SECTION("Wuson.ply: every loaded vertex is a vertex of the file, with its normal and uv") {
    const auto mesh = loadMeshFile(models + "Wuson.ply");
    const auto file = readXyzNxyzSt(models + "Wuson.ply");
    REQUIRE(mesh->normals.size() == mesh->positions.size());
    REQUIRE(mesh->uvs.size() == mesh->positions.size());
    // The file repeats each position with the normal of each face around it (flat normals),
    // so positions, normals and uvs come back as the file's 11184 distinct vertices.
    CHECK(mesh->positions.size() == file.size());
    std::map<std::tuple<double, double, double>, std::vector<const FileVertex*>> byPosition;
    for (const FileVertex& v : file) byPosition[{v.p.x, v.p.y, v.p.z}].push_back(&v);
    std::size_t matched = 0;
    for (uint32_t i = 0; i < mesh->positions.size(); ++i) {
      const Vec3& p = mesh->positions[i];
      for (const FileVertex* v : byPosition[{p.x, p.y, p.z}])
        if (glm::length(glm::normalize(v->n) - mesh->normals[i]) < 1e-7 && v->uv == mesh->uvs[i]) {
          ++matched;
          break;
        }
    }
    CHECK(matched == mesh->positions.size());
  }
}
