// Orientation and closedness decided through CGAL: faces made consistent with their
// neighbours, closed shells turned outward, shells nested in others turned inward.
#include "mesh_test_support.h"

#include "meshes/mesh_files.h"

using namespace lucent;
using namespace lucent::meshtest;

TEST_CASE("a cube with one face written backwards comes out closed and outward", "[mesh]") {
  const auto mesh = loadMeshFile(dataFile("cube_one_face_flipped.obj"));
  requireWellFormed(*mesh);
  CHECK(mesh->closed);
  CHECK(mesh->triangles.size() == 12);
  CHECK(signedVolume(*mesh) == Approx(1.0).margin(1e-12));
}

TEST_CASE("a cube written inside-out is turned outward", "[mesh]") {
  for (const char* file : {"cube_inside_out.off", "cube_inside_out.stl"}) {
    INFO(file);
    const auto mesh = loadMeshFile(dataFile(file));
    requireWellFormed(*mesh);
    CHECK(mesh->closed);
    CHECK(mesh->positions.size() == 8);
    CHECK(signedVolume(*mesh) == Approx(1.0).margin(1e-12));
  }
}

TEST_CASE("the inner shell of a hollow cube faces into the cavity", "[mesh]") {
  // Outer [0,3]^3 and inner [1,2]^3, both written outward: the solid is the shell between
  // them, so the inner surface must face inward and the volume is 27 - 1.
  const auto mesh = loadMeshFile(dataFile("hollow_cube.obj"));
  requireWellFormed(*mesh);
  CHECK(mesh->closed);
  CHECK(mesh->positions.size() == 16);
  CHECK(mesh->triangles.size() == 24);
  CHECK(signedVolume(*mesh) == Approx(26.0).margin(1e-12));
}

TEST_CASE("each separate shell is turned outward on its own", "[mesh]") {
  // Two unit cubes apart, the second written inside-out.
  const auto mesh = loadMeshFile(dataFile("two_cubes_one_inverted.ply"));
  requireWellFormed(*mesh);
  CHECK(mesh->closed);
  CHECK(mesh->triangles.size() == 24);
  CHECK(signedVolume(*mesh) == Approx(2.0).margin(1e-12));
  double second = 0;  // the moved cube alone, [2,3]^3
  for (const auto& t : mesh->triangles)
    if (mesh->positions[t[0]].x >= 2)
      second += glm::dot(mesh->positions[t[0]],
                         glm::cross(mesh->positions[t[1]], mesh->positions[t[2]])) /
                6;
  CHECK(second == Approx(1.0).margin(1e-12));
}
