// Broken, hostile and unsupported mesh files: each is refused with a MeshError that names
// the reason (never a crash, a hang or a huge allocation), and the exact text is pinned.
#include "mesh_test_support.h"

#include "meshes/mesh_files.h"

#include <cstring>

using namespace lucent;
using namespace lucent::meshtest;

namespace {

std::string refusal(const std::string& file) {
  try {
    loadMeshFile(file);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "(loaded)";
}

template <class T>
void put(std::string& out, T value, bool bigEndian = false) {
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  if (bigEndian) std::reverse(b, b + sizeof(T));
  out.append(b, sizeof(T));
}

// A binary STL with `declared` in the header and the unit triangle repeated `actual` times.
std::string binaryStl(uint32_t declared, uint32_t actual, float poison = 0) {
  std::string s(80, ' ');
  put(s, declared);
  for (uint32_t t = 0; t < actual; ++t) {
    for (int k = 0; k < 3; ++k) put(s, 0.0f);
    const float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, t == actual - 1 ? poison : 0.0f};
    for (float x : v) put(s, x);
    put(s, uint16_t{0});
  }
  return s;
}

const char* kCubePlyHeader =
    "ply\nformat binary_little_endian 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
    "property float z\nelement face 6\nproperty list uchar int vertex_indices\nend_header\n";

std::string binaryCubePly(float poison = 0) {
  std::string s = kCubePlyHeader;
  const float v[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, poison}};
  for (const auto& p : v)
    for (float x : p) put(s, x);
  const int32_t q[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                           {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
  for (const auto& f : q) {
    put(s, uint8_t{4});
    for (int32_t i : f) put(s, i);
  }
  return s;
}

const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

}  // namespace

TEST_CASE("missing, empty, folder and unknown-format paths are refused", "[mesh]") {
  TempDir dir;
  CHECK(refusal(dir.file("nothing.obj")) == "the file does not exist");
  CHECK(refusal(dir.write("empty.ply", "")) == "the file is empty");
  std::filesystem::create_directory(dir.file("folder.obj"));
  CHECK(refusal(dir.file("folder.obj")) == "this is a folder, not a file");
  CHECK(refusal(dir.write("model.3ds", "x")) ==
        "unknown mesh format '.3ds'; expected .obj, .ply, .off or .stl");
  CHECK(refusal(dir.write("model", "x")) ==
        "the file name has no extension; expected .obj, .ply, .off or .stl");
}

TEST_CASE("malformed OBJ files are refused with the line", "[mesh]") {
  TempDir dir;
  auto obj = [&](const std::string& text) { return refusal(dir.write("m.obj", text)); };
  CHECK(obj(std::string(kTriangleObj) + "f 1 2 4\n") ==
        "OBJ line 4: a face uses vertex 4, but the file has 3 vertices");
  CHECK(obj("v 0 0 0\nv 1 x 0\n") == "OBJ line 2: 'x' is not a finite number");
  CHECK(obj("v 0 0 1e999\n") == "OBJ line 1: '1e999' is not a finite number");
  CHECK(obj("v 0 0 nan\n") == "OBJ line 1: 'nan' is not a finite number");
  CHECK(obj("v 0 0\n") == "OBJ line 1: 'v' needs 3 numbers");
  CHECK(obj(std::string(kTriangleObj) + "f 0 1 2\n") ==
        "OBJ line 4: vertex index 0 is invalid (OBJ counts from 1)");
  CHECK(obj(std::string(kTriangleObj) + "f -4 -2 -1\n") ==
        "OBJ line 4: relative vertex index -4 reaches before the first vertex");
  CHECK(obj(std::string(kTriangleObj) + "f 1 2 99999999999\n") ==
        "OBJ line 4: '99999999999' is not a face corner (v, v/vt, v//vn or v/vt/vn)");
  CHECK(obj(std::string(kTriangleObj) + "f 1/1 2/1 3/1\n") ==
        "OBJ line 4: a face uses texture coordinate 1, but the file has 0");
  CHECK(obj(std::string(kTriangleObj) + "f 1/2/3/4 2 3\n") ==
        "OBJ line 4: '1/2/3/4' is not a face corner (v, v/vt, v//vn or v/vt/vn)");
  CHECK(obj("foo 1 2\n") == "OBJ line 1: unknown OBJ statement 'foo'");
  CHECK(obj(kTriangleObj) ==
        "the OBJ file has no faces ('f' statements); points and lines have no surface");
  CHECK(obj("# nothing\n") == "the OBJ file has no vertices ('v' statements)");
  CHECK(obj(std::string("\xFE\xFF\0v", 4)) ==
        "the OBJ file is UTF-16 text; save it as ASCII or UTF-8");
  // Truncated in the middle of a face: what is left has two corners.
  CHECK(obj(std::string(kTriangleObj) + "f 1 2") ==
        "no usable face: none of the 1 faces has three distinct vertices");
  CHECK(obj("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n") ==
        "no usable triangle: all 1 faces are degenerate (zero area)");
}

TEST_CASE("malformed OFF files are refused with the reason", "[mesh]") {
  TempDir dir;
  auto off = [&](const std::string& text) { return refusal(dir.write("m.off", text)); };
  const std::string triangle = "0 0 0\n1 0 0\n0 1 0\n";
  CHECK(off("OFF\n1000000000 1 0\n0 0 0\n") ==
        "the OFF header declares 1000000000 vertices; the limit is 16777216");
  CHECK(off("OFF\n353535235358 6 0\n") ==
        "the OFF header count '353535235358' is not a number the reader can hold");
  CHECK(off("OFF\n1000000 1 0\n0 0 0\n") == "the OFF file ends after 1 of its 1000000 vertices");
  CHECK(off("OFF\n3 2 0\n" + triangle + "3 0 1 2\n") == "the OFF file ends after 1 of its 2 faces");
  CHECK(off("OFF\n3 1 0\n" + triangle + "3 0 1 7\n") ==
        "OFF line 6: vertex index '7' is not between 0 and 2");
  CHECK(off("OFF\n3 1 0\n0 0 zz\n1 0 0\n0 1 0\n3 0 1 2\n") == "OFF line 3: 'zz' is not a number");
  CHECK(off("OFF\n3 1 0\n" + triangle + "4000000000 0 1 2\n") ==
        "OFF line 6: '4000000000' is not a face vertex count between 0 and 65536");
  CHECK(off("OFF\n3 1 0\n" + triangle + "4 0 1 2\n") ==
        "OFF line 6: the face announces 4 vertices but lists 3");
  CHECK(off("OFF\n3 1 0\n0 0\n1 0 0\n0 1 0\n3 0 1 2\n") ==
        "OFF line 3: a vertex needs 3 numbers, found 2");
  CHECK(off("OFF\n3 -1 0\n") == "the OFF header has a negative count");
  CHECK(off("OFF\n3 1\n") ==
        "the OFF header must give three counts (vertices, faces, edges) after the keyword");
  CHECK(off("OFF BINARY\n") ==
        "binary OFF is not supported (CGAL 5.5 misreads its faces); use ASCII OFF, PLY or STL");
  CHECK(off("STOFF\n3 1 0\n") ==
        "OFF variant 'STOFF' is not supported (texture, homogeneous and n-dimensional OFF are not "
        "read "
        "reliably); use OFF, COFF, NOFF or CNOFF");
  CHECK(off("ply\n") == "not an OFF file: it starts with 'ply' instead of the keyword OFF");
  CHECK(off("SKEL\n1 0\n") == "SKEL files hold skeletons, not surfaces");
  // COFF: once a vertex had colours, CGAL reads three values from every later vertex.
  CHECK(off("COFF\n3 1 0\n0 0 0 255 0 0\n1 0 0 7 7\n0 1 0 1 2 3\n3 0 1 2\n") ==
        "OFF line 4: 2 colour values (expected 1, 3 or 4, as on the earlier lines)");
  CHECK(off("COFF\n3 1 0\n0 0 0 255 0 0\n1 0 0\n0 1 0 1 2 3\n3 0 1 2\n") ==
        "OFF line 4: 0 colour values (expected 1, 3 or 4, as on the earlier lines)");
}

TEST_CASE("a well-formed COFF with colours and comments loads", "[mesh]") {
  TempDir dir;
  const auto mesh =
      loadMeshFile(dir.write("c.off",
                             "# coloured\nCOFF\n# counts next\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0.5 "
                             "0.5 0.5\n0 1 0 3 # indexed\n3 0 1 2 1 2 3\n"));
  requireWellFormed(*mesh);
  CHECK(mesh->triangles.size() == 1);
}

TEST_CASE("malformed PLY files are refused with the reason", "[mesh]") {
  TempDir dir;
  auto ply = [&](const std::string& bytes) { return refusal(dir.write("m.ply", bytes)); };
  const std::string asciiHead = "ply\nformat ascii 1.0\n";
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  const std::string faces = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

  CHECK(ply(asciiHead + "element vertex 1000000000000\n" + xyz + faces) ==
        "the PLY header declares 1000000000000 'vertex' elements; the limit is 16777216");
  CHECK(ply(asciiHead + "element vertex 1000000\n" + xyz + faces + "0 0 0\n") ==
        "the PLY header declares 1000000 'vertex' elements, which need at least 6000000 bytes, but "
        "the "
        "data has 6 bytes");
  CHECK(ply(asciiHead + "element vertex 3\nproperty int x\nproperty float y\nproperty float z\n" +
            faces + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n") ==
        "PLY vertex property 'x' (line 4) must be float or double");
  CHECK(ply(asciiHead + "element vertex 3\nproperty int64 x\n") ==
        "PLY header line 4: unknown type 'int64'");
  CHECK(ply(asciiHead + "element vertex 3\n" + xyz + faces + "0 0 0\n1 0 abc\n0 1 0\n3 0 1 2\n") ==
        "PLY data ends or is malformed in vertex 1 (counting from 0), property 'z'");
  CHECK(ply(asciiHead + "element vertex 3\n" + xyz + faces + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n") ==
        "PLY face 0 refers to vertex 3, but there are 3 vertices");
  CHECK(ply(asciiHead + "element vertex 3\n" + xyz + faces + "0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n") ==
        "PLY data ends or is malformed in face 0 (counting from 0), property 'vertex_indices'");
  CHECK(ply(asciiHead + "element vertex 3\n" + xyz + "end_header\n0 0 0\n1 0 0\n0 1 0\n") ==
        "the PLY header declares no 'face' element (a point cloud has no surface)");
  CHECK(ply(asciiHead + "element vertex 3\n" + xyz) == "the PLY header has no end_header line");
  CHECK(ply(asciiHead + "property float x\n") == "PLY header line 3: property before any element");
  CHECK(ply("solid x\n") == "not a PLY file: the first line must be 'ply'");
  CHECK(ply("ply\nformat text 1.0\n") == "PLY line 2: unknown format 'text'");
  CHECK(ply(asciiHead + "element vertex 3\n" + xyz +
            "element face 1\nproperty list float int vertex_indices\n") ==
        "PLY header line 8: list count type 'float' is not an integer type");
  CHECK(ply(asciiHead + "element vertex 3\n" + xyz +
            "element face 1\nproperty list uchar short vertex_indices\nend_header\n") ==
        "PLY element 'face' (line 7) has no 'vertex_indices' (or 'vertex_index') list of int or "
        "uint");

  // Binary: truncated in the middle of the faces, a NaN coordinate, a list claiming 2e9 entries.
  const std::string cube = binaryCubePly();
  CHECK(ply(cube.substr(0, cube.size() - 30)) ==
        "PLY data ends or is malformed in face 4 (counting from 0), property 'vertex_indices'");
  CHECK(ply(binaryCubePly(std::nanf(""))) == "PLY vertex 7 has a non-finite coordinate");
  std::string huge =
      std::string(kCubePlyHeader).replace(std::string(kCubePlyHeader).find("uchar"), 5, "int");
  for (int i = 0; i < 24; ++i) put(huge, 0.0f);
  put(huge, int32_t{2000000000});
  huge.append(64, '\0');
  CHECK(ply(huge) ==
        "PLY face 0: list 'vertex_indices' claims 2000000000 entries (the limit is 65536)");
}

TEST_CASE("malformed STL files are refused with the reason", "[mesh]") {
  TempDir dir;
  auto stl = [&](const std::string& bytes) { return refusal(dir.write("m.stl", bytes)); };
  CHECK(stl(binaryStl(100, 12)) ==
        "the binary STL is truncated: its header announces 100 triangles (5084 bytes), but the "
        "file has 684 bytes");
  CHECK(stl(binaryStl(4000000000u, 1)) ==
        "the binary STL is truncated: its header announces 4000000000 triangles (200000000084 "
        "bytes), but the "
        "file has 134 bytes");
  CHECK(stl(binaryStl(3, 3, std::nanf(""))) ==
        "binary STL triangle 2 (counting from 0) has a non-finite vertex coordinate");
  CHECK(stl(binaryStl(3, 3, INFINITY)) ==
        "binary STL triangle 2 (counting from 0) has a non-finite vertex coordinate");
  CHECK(stl("abc") ==
        "the file is too short (3 bytes) for a binary STL, which has an 84-byte header, and does "
        "not start "
        "with 'solid' like an ASCII STL");
  CHECK(stl("solidcube\n") == "an ASCII STL must start with the word 'solid' followed by a space");
  const std::string facet =
      "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 "
      "0\nendloop\nendfacet\n";
  CHECK(stl("solid t\n" + facet + facet.substr(0, 40)) ==
        "CGAL's STL reader could not read the file (malformed or truncated data)");
  // So short that no facet is complete: CGAL then reports an empty file.
  CHECK(stl("solid t\n" + facet.substr(0, 40)) == "the file holds no faces");
  CHECK(stl("solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 x 0\nvertex 0 1 "
            "0\nendloop\nendfacet\nendsolid t\n") ==
        "CGAL's STL reader could not read the file (malformed or truncated data)");
  CHECK(stl("solid t\nendsolid t\n") == "the file holds no faces");
  CHECK(stl(binaryStl(0, 0)) == "the file holds no faces");
  // A tab after "solid" (seen in the wild) is still ASCII.
  const auto mesh =
      loadMeshFile(dir.write("tab.stl",
                             "solid\tt\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 "
                             "0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n"));
  requireWellFormed(*mesh);
  CHECK(mesh->triangles.size() == 1);
  CHECK(mesh->positions.size() == 3);
}
