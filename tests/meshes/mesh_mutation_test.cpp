// Seeded random damage to well-formed mesh files: whatever the damage, loading either gives a
// well-formed mesh or throws MeshError (nothing else, no crash, no hang).
#include "mesh_test_support.h"

#include "meshes/mesh_files.h"

#include <fstream>
#include <random>
#include <sstream>

using namespace lucent;
using namespace lucent::meshtest;

namespace {

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// One random change: cut, overwrite a byte, insert a hostile token, or repeat a slice.
std::string mutate(std::string bytes, std::mt19937& rng) {
  auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n)(rng); };
  const char* tokens[] = {
      " 99999999999 ", " -1 ", " 1e999 ", " nan ", " 0 ",   " 4294967295 ",     "\n",
      " -7 ",          "\t",   "#",       "/",     " 3.5 ", "\xff\xff\xff\x7f", "\0\0\0\0"};
  switch (pick(3)) {
    case 0:
      bytes.resize(pick(bytes.size()));
      break;
    case 1:
      if (!bytes.empty()) bytes[pick(bytes.size() - 1)] = static_cast<char>(pick(255));
      break;
    case 2: {
      const std::string tok = tokens[pick(std::size(tokens) - 1)];
      bytes.insert(pick(bytes.size()), tok.empty() ? std::string(4, '\0') : tok);
      break;
    }
    default: {
      const std::size_t from = pick(bytes.size()),
                        length = pick(std::min<std::size_t>(64, bytes.size() - from));
      bytes.insert(pick(bytes.size()), bytes.substr(from, length));
      break;
    }
  }
  return bytes;
}

}  // namespace

TEST_CASE("damaged mesh files load well-formed or are refused with MeshError", "[mesh]") {
  std::mt19937 rng(20261123);
  TempDir dir;
  const char* files[] = {
      "cube.obj",           "cube_normals_uvs.obj", "cube_tabs_polyline_relative.obj",
      "cube.off",           "cube_ascii.ply",       "cube_binary_le.ply",
      "cube_binary_be.ply", "cube_ascii.stl",       "cube_binary.stl",
      "hollow_cube.obj"};
  int loaded = 0, refused = 0;
  for (const char* file : files) {
    const std::string original = readAll(dataFile(file));
    REQUIRE(!original.empty());
    const std::string ext = std::filesystem::path(file).extension().string();
    for (int round = 0; round < 150; ++round) {
      std::string bytes = original;
      const int changes = 1 + static_cast<int>(rng() % 3);
      for (int c = 0; c < changes; ++c) bytes = mutate(bytes, rng);
      const std::string path = dir.write("damaged" + ext, bytes);
      INFO(file << " round " << round);
      try {
        const auto mesh = loadMeshFile(path);
        requireWellFormed(*mesh);
        ++loaded;
      } catch (const MeshError& e) {
        CHECK(std::string(e.what()).size() > 5);
        ++refused;
      }
    }
  }
  // Both outcomes occur, so the loop exercised the readers and the checks alike.
  CHECK(loaded > 100);
  CHECK(refused > 100);
}
