// Loading well-formed mesh files in every supported format and layout. The files are written
// by tests/data/meshes/make_meshes.py; the unit cube [0,1]^3 has 8 corners, 6 faces, volume 1.
#include "mesh_test_support.h"

#include "meshes/mesh_file_check.h"
#include "meshes/mesh_files.h"

using namespace lucent;
using namespace lucent::meshtest;

namespace {

void requireUnitCube(const std::string& file) {
  INFO(file);
  const auto mesh = loadMeshFile(dataFile(file));
  requireWellFormed(*mesh);
  CHECK(mesh->positions.size() == 8);
  CHECK(mesh->triangles.size() == 12);
  CHECK(mesh->closed);
  CHECK(signedVolume(*mesh) == Approx(1.0).margin(1e-12));
  CHECK(mesh->normals.empty());
  CHECK(mesh->uvs.empty());
}

}  // namespace

TEST_CASE("a closed cube loads the same from OBJ, OFF, ASCII and binary PLY and STL", "[mesh]") {
  for (const char* file : {"cube.obj", "cube.off", "cube_ascii.ply", "cube_binary_le.ply",
                           "cube_binary_be.ply", "cube_ascii.stl", "cube_binary.stl"})
    requireUnitCube(file);
}

TEST_CASE("the PLY check counts the vertices and faces the reader will see", "[mesh]") {
  // loadMeshBytes sizes the reader's containers from these counts.
  for (const char* file : {"cube_ascii.ply", "cube_binary_le.ply", "cube_binary_be.ply"}) {
    INFO(file);
    const MeshCounts counts = checkPlyBytes(readMeshFile(dataFile(file)));
    CHECK(counts.vertices == 8);
    CHECK(counts.faces == 6);
  }
}

TEST_CASE("a binary STL whose header starts with 'solid' is read as binary", "[mesh]") {
  requireUnitCube("cube_binary_solid_header.stl");
}

TEST_CASE("the extension is recognised in any letter case", "[mesh]") {
  requireUnitCube("cube_upper.OBJ");
}

TEST_CASE("an OBJ with a byte-order mark, tabs, a polyline and relative indices loads", "[mesh]") {
  requireUnitCube("cube_tabs_polyline_relative.obj");
}

TEST_CASE("quads and a hexagon are triangulated", "[mesh]") {
  const auto grid = loadMeshFile(dataFile("grid_quads.obj"));
  requireWellFormed(*grid);
  CHECK(grid->positions.size() == 9);
  CHECK(grid->triangles.size() == 8);
  CHECK_FALSE(grid->closed);
  double area = 0;  // the 2x2 grid covers 4 square units
  for (const auto& t : grid->triangles)
    area += 0.5 * glm::length(glm::cross(grid->positions[t[1]] - grid->positions[t[0]],
                                         grid->positions[t[2]] - grid->positions[t[0]]));
  CHECK(area == Approx(4.0).margin(1e-12));

  const auto hexagon = loadMeshFile(dataFile("hexagon.off"));
  requireWellFormed(*hexagon);
  CHECK(hexagon->positions.size() == 6);
  CHECK(hexagon->triangles.size() == 4);
  CHECK_FALSE(hexagon->closed);
}

TEST_CASE("an open box is not closed and keeps the file's winding", "[mesh]") {
  const auto mesh = loadMeshFile(dataFile("open_box.obj"));
  requireWellFormed(*mesh);
  CHECK(mesh->positions.size() == 8);
  CHECK(mesh->triangles.size() == 10);
  CHECK_FALSE(mesh->closed);
  // The bottom face (z = 0) was written facing -z, and stays so.
  for (const auto& t : mesh->triangles) {
    const Vec3 a = mesh->positions[t[0]], b = mesh->positions[t[1]], c = mesh->positions[t[2]];
    if (a.z == 0 && b.z == 0 && c.z == 0) CHECK(glm::cross(b - a, c - a).z < 0);
  }
}

TEST_CASE("OBJ vertex normals and texture coordinates are kept per corner", "[mesh]") {
  // Each face uses its own normal (written with length 2) and the four corners of the unit
  // texture square in the order of the face's corners.
  const auto mesh = loadMeshFile(dataFile("cube_normals_uvs.obj"));
  requireWellFormed(*mesh);
  CHECK(mesh->closed);
  CHECK(mesh->positions.size() == 24);  // 6 faces x 4 corners: every corner differs in normal
  REQUIRE(mesh->normals.size() == 24);
  REQUIRE(mesh->uvs.size() == 24);
  CHECK(mesh->triangles.size() == 12);
  CHECK(signedVolume(*mesh) == Approx(1.0).margin(1e-12));

  const Vec3 cube[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                        {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                           {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
  const Vec3 faceNormal[6] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}};
  const Vec2 square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const auto& t : mesh->triangles) {
    const Vec3 a = mesh->positions[t[0]], b = mesh->positions[t[1]], c = mesh->positions[t[2]];
    const Vec3 ng = glm::normalize(glm::cross(b - a, c - a));
    int face = -1;
    for (int f = 0; f < 6; ++f)
      if (glm::length(ng - faceNormal[f]) < 1e-12) face = f;
    REQUIRE(face >= 0);  // geometric normal is one of the outward face normals
    for (uint32_t i : t) {
      CHECK(glm::length(mesh->normals[i] - faceNormal[face]) < 1e-12);
      int corner = -1;
      for (int j = 0; j < 4; ++j)
        if (mesh->positions[i] == cube[quads[face][j]]) corner = j;
      REQUIRE(corner >= 0);
      CHECK(mesh->uvs[i] == square[corner]);
    }
  }
}

TEST_CASE("OBJ normals given for only some corners are not used", "[mesh]") {
  const auto mesh = loadMeshFile(dataFile("cube_partial_normals.obj"));
  requireWellFormed(*mesh);
  CHECK(mesh->normals.empty());
  CHECK(mesh->positions.size() == 8);
  CHECK(mesh->closed);
}

TEST_CASE("a zero-area triangle in a file is dropped and the cube stays closed", "[mesh]") {
  const auto mesh = loadMeshFile(dataFile("cube_with_degenerate.obj"));
  requireWellFormed(*mesh);
  CHECK(mesh->positions.size() == 8);
  CHECK(mesh->triangles.size() == 12);
  CHECK(mesh->closed);
  CHECK(signedVolume(*mesh) == Approx(1.0).margin(1e-12));
}

TEST_CASE("a non-planar quad is split in two, a self-intersecting one is dropped", "[mesh]") {
  TempDir dir;
  const auto warped =
      loadMeshFile(dir.write("warped.obj", "v 0 0 0\nv 1 0 0.2\nv 1 1 0\nv 0 1 0.3\nf 1 2 3 4\n"));
  requireWellFormed(*warped);
  CHECK(warped->positions.size() == 4);
  CHECK(warped->triangles.size() == 2);

  // A bow-tie has no triangulation on its own corners: CGAL leaves it, and only the separate
  // triangle remains.
  const auto bowtie = loadMeshFile(dir.write(
      "bowtie.obj",
      "v 0 0 0\nv 1 1 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nv 6 5 5\nv 5 6 5\nf 1 2 3 4\nf 5 6 7\n"));
  requireWellFormed(*bowtie);
  CHECK(bowtie->triangles.size() == 1);
  CHECK(bowtie->positions.size() == 3);
  for (const Vec3& p : bowtie->positions) CHECK(p.z == 5);
}

TEST_CASE("coordinates that underflow are read as tiny numbers", "[mesh]") {
  TempDir dir;
  const auto mesh =
      loadMeshFile(dir.write("tiny.obj", "v 0 0 0\nv 1 0 1e-400\nv 0 1 4.9e-324\nf 1 2 3\n"));
  requireWellFormed(*mesh);
  REQUIRE(mesh->positions.size() == 3);
  double zs = 0;
  for (const Vec3& p : mesh->positions) zs += p.z;
  CHECK(zs == 4.9e-324);  // 1e-400 becomes 0, the smallest denormal stays
}
