// Every OBJ, PLY, OFF and STL file of Debian's assimp-testmodels package (a few dozen real
// and deliberately broken files) either loads as a well-formed mesh or is refused with a
// MeshError naming the reason; never a crash or a hang. The outcome of each file is pinned,
// so that a change in any of them fails this test and has to be looked at.
#include "mesh_test_support.h"

#include "meshes/mesh_files.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <iostream>
#include <map>
#include <set>
#include <variant>

using namespace lucent;
using namespace lucent::meshtest;

namespace {

const char* kModels = "/usr/share/assimp/models";

struct Loads {
  std::size_t positions, triangles;
  bool closed, normals, uvs;
};
struct Refused {
  std::string message;
};
using Outcome = std::variant<Loads, Refused>;

// Paths relative to kModels. Regenerate by hand only after checking why an outcome changed.
const std::map<std::string, Outcome> kPinned = {
    {"OBJ/WusonOBJ.obj", Loads{2126, 3732, false, true, true}},
    {"OBJ/box.obj", Loads{8, 12, true, false, false}},
    {"OBJ/box_UTF16BE.obj", Refused{"the OBJ file is UTF-16 text; save it as ASCII or UTF-8"}},
    {"OBJ/box_longline.obj", Loads{8, 12, true, false, false}},
    {"OBJ/box_mat_with_spaces.obj", Loads{8, 12, true, false, false}},
    {"OBJ/box_without_lineending.obj", Loads{8, 12, true, false, false}},
    {"OBJ/concave_polygon.obj", Loads{64, 60, false, true, false}},
    {"OBJ/cube_mtllib_after_g.obj", Loads{24, 12, true, true, false}},
    {"OBJ/cube_usemtl.obj", Loads{24, 12, true, true, false}},
    {"OBJ/cube_with_vertexcolors.obj", Loads{24, 12, true, true, false}},
    {"OBJ/cube_with_vertexcolors_uni.obj", Loads{24, 12, true, true, false}},
    {"OBJ/empty_mat.obj", Loads{450, 256, true, true, false}},
    {"OBJ/multiple_spaces.obj", Loads{3, 1, false, false, false}},
    {"OBJ/number_formats.obj", Refused{"OBJ line 11: '3.1+e2' is not a finite number"}},
    {"OBJ/point_cloud.obj",
     Refused{"the OBJ file has no faces ('f' statements); points and lines have no surface"}},
    {"OBJ/regr01.obj", Loads{1382, 2703, false, false, false}},
    // A quad plus the two triangles that cover it: duplicates merge into one flat open quad.
    {"OBJ/regr_3429812.obj", Loads{4, 2, false, false, false}},
    {"OBJ/space_in_material_name.obj", Loads{64, 60, false, true, false}},
    {"OBJ/spider.obj", Loads{894, 1312, false, false, true}},
    {"OBJ/testline.obj",
     Refused{"the OBJ file has no faces ('f' statements); points and lines have no surface"}},
    {"OBJ/testmixed.obj", Loads{8, 12, true, false, false}},
    {"OBJ/testpoints.obj",
     Refused{"the OBJ file has no faces ('f' statements); points and lines have no surface"}},
    {"OFF/Cube.off", Loads{8, 12, true, false, false}},
    {"OFF/Wuson.off", Loads{2126, 3732, false, false, false}},
    {"OFF/invalid.off", Refused{"OFF line 7: the face announces 2 vertices but lists 1"}},
    // Flat normals: the file repeats a position for each face around it.
    {"PLY/Wuson.ply", Loads{11184, 3732, false, true, true}},
    {"PLY/cube.ply", Loads{8, 12, true, false, false}},
    {"PLY/cube_binary.ply", Loads{8, 12, true, false, false}},
    {"PLY/cube_uv.ply", Loads{24, 12, true, true, true}},
    {"PLY/float-color.ply", Loads{3, 1, false, false, false}},
    {"PLY/issue623.ply",
     Refused{"the PLY header declares no 'face' element (a point cloud has no surface)"}},
    {"PLY/points.ply",
     Refused{"the PLY header declares no 'face' element (a point cloud has no surface)"}},
    {"PLY/pond.0.ply",
     Refused{"the PLY header declares no 'face' element (a point cloud has no surface)"}},
    {"STL/3DSMaxExport.STL", Loads{1074, 2000, false, false, false}},
    {"STL/Spider_ascii.stl", Loads{722, 1312, false, false, false}},
    {"STL/Spider_binary.stl", Loads{722, 1312, false, false, false}},
    {"STL/Wuson.stl", Loads{2126, 3732, false, false, false}},
    {"STL/sphereWithHole.stl", Loads{148, 285, false, false, false}},
    {"STL/triangle.stl", Loads{3, 1, false, false, false}},
    {"STL/triangle_with_empty_solid.stl", Loads{3, 1, false, false, false}},
    {"STL/triangle_with_two_solids.stl", Loads{6, 2, false, false, false}},
    {"invalid/OutOfMemory.off",
     Refused{"the OFF header count '353535235358' is not a number the reader can hold"}},
    {"invalid/empty.obj", Refused{"the file is empty"}},
    {"invalid/empty.off", Refused{"the file is empty"}},
    {"invalid/empty.ply", Refused{"the file is empty"}},
    {"invalid/malformed.obj",
     Refused{"OBJ line 28: vertex index 0 is invalid (OBJ counts from 1)"}},
    {"invalid/malformed2.obj", Loads{8, 10, false, false, false}},
};

std::set<std::string> meshFilesUnder(const std::filesystem::path& root) {
  std::set<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file()) continue;
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".obj" || ext == ".ply" || ext == ".off" || ext == ".stl")
      files.insert(std::filesystem::relative(entry.path(), root).generic_string());
  }
  return files;
}

}  // namespace

TEST_CASE("every assimp test model loads or is refused with a reason, as pinned",
          "[mesh][assimp]") {
  if (!std::filesystem::is_directory(kModels))
    FAIL(
        fmt::format("{} is missing: run scripts/install-deps (it installs the Debian package "
                    "assimp-testmodels)",
                    kModels));
  const std::set<std::string> found = meshFilesUnder(kModels);
  for (const auto& [file, outcome] : kPinned) {
    (void)outcome;
    INFO(file);
    CHECK(found.count(file) == 1);  // a pinned file disappeared: the package changed
  }

  std::cout << "assimp test models (" << kModels << "):\n";
  for (const std::string& file : found) {
    INFO(file);
    const auto pinned = kPinned.find(file);
    CHECK(pinned != kPinned.end());  // a new file: look at its outcome and pin it
    std::shared_ptr<MeshData> mesh;
    std::string refusal;
    try {
      mesh = loadMeshFile(std::string(kModels) + "/" + file);
    } catch (const MeshError& e) {
      refusal = e.what();
    }
    if (mesh) {
      std::cout << fmt::format(
          "  loads    {:<38} {:>5} positions {:>5} triangles{}{}{}\n", file, mesh->positions.size(),
          mesh->triangles.size(), mesh->closed ? ", closed" : "",
          mesh->normals.empty() ? "" : ", normals", mesh->uvs.empty() ? "" : ", uvs");
      requireWellFormed(*mesh);
      if (mesh->closed) {  // outward: positive volume, or zero for a flat closed mesh
        Vec3 lo(kInf), hi(-kInf);
        for (const Vec3& p : mesh->positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
        const double scale = glm::length(hi - lo);
        CHECK(signedVolume(*mesh) > -1e-9 * scale * scale * scale);
      }
    } else {
      std::cout << fmt::format("  refused  {:<38} {}\n", file, refusal);
      CHECK(!refusal.empty());
    }
    if (pinned == kPinned.end()) continue;
    if (const auto* loads = std::get_if<Loads>(&pinned->second)) {
      CHECK(mesh);
      if (!mesh) continue;
      CHECK(mesh->positions.size() == loads->positions);
      CHECK(mesh->triangles.size() == loads->triangles);
      CHECK(mesh->closed == loads->closed);
      CHECK(!mesh->normals.empty() == loads->normals);
      CHECK(!mesh->uvs.empty() == loads->uvs);
    } else {
      CHECK(refusal == std::get<Refused>(pinned->second).message);
    }
  }
}
