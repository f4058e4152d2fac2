// The scene files the whole-process benchmarks render (peak_memory, vs_povray): written by
// the programs from data they make, never downloaded.
#pragma once

#include "bench_util.h"

#include <cstdint>
#include <fstream>
#include <string>

namespace lucent::bench {

// Binary little-endian PLY (float positions, int indices), as scanners and Blender write.
inline void writePly(const std::string& path, const MeshData& m) {
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\n"
      << "element vertex " << m.positions.size() << "\n"
      << "property float x\nproperty float y\nproperty float z\n"
      << "element face " << m.triangles.size() << "\n"
      << "property list uchar int vertex_indices\nend_header\n";
  for (const Vec3& p : m.positions) {
    float f[3] = {float(p.x), float(p.y), float(p.z)};
    out.write(reinterpret_cast<const char*>(f), sizeof f);
  }
  for (const auto& t : m.triangles) {
    unsigned char three = 3;
    int32_t idx[3] = {int32_t(t[0]), int32_t(t[1]), int32_t(t[2])};
    out.write(reinterpret_cast<const char*>(&three), 1);
    out.write(reinterpret_cast<const char*>(idx), sizeof idx);
  }
}

// `dir`/bumpy.xml: the displaced sphere of about `triangles` triangles (dir/bumpy.ply),
// flat shaded, one point light, size×size pixels, one sample. Returns the triangle count.
inline size_t writeMeshScene(const std::string& dir, size_t triangles, int size) {
  MeshData mesh = displacedSphereOf(triangles);
  writePly(dir + "/bumpy.ply", mesh);
  std::ofstream(dir + "/bumpy.xml")
      << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<scene version=\"1\">\n"
      << "  <render width=\"" << size << "\" height=\"" << size << "\" samples=\"1\"/>\n"
      << "  <camera position=\"0.6 0.9 3.2\" look-at=\"0 0 0\" fov=\"40\"/>\n"
      << "  <light type=\"point\" position=\"4 6 5\"/>\n"
      << "  <mesh src=\"bumpy.ply\" smooth=\"false\"/>\n"
      << "</scene>\n";
  return mesh.triangles.size();
}

// `dir`/spheres.xml: a field of `count` spheres of three materials (one of them a
// mirror) standing on a checkered ground, lit by two point lights: the classic
// Whitted test scene, with shadows and reflections. Positions are a jittered grid from a
// fixed linear congruential sequence, so the file is the same on every run.
inline void writeSphereField(const std::string& dir, int count, int width, int height) {
  std::ofstream out(dir + "/spheres.xml");
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<scene version=\"1\">\n"
      << "  <render width=\"" << width << "\" height=\"" << height << "\" samples=\"1\"/>\n"
      << "  <camera position=\"0 9 -26\" look-at=\"0 0 2\" fov=\"45\"/>\n"
      << "  <light type=\"point\" position=\"-10 20 -10\" color=\"0.7 0.7 0.7\"/>\n"
      << "  <light type=\"point\" position=\"12 15 -6\" color=\"0.5 0.5 0.5\"/>\n"
      << "  <material id=\"red\" diffuse=\"0.8 0.2 0.15\" specular=\"0.4\" shininess=\"40\"/>\n"
      << "  <material id=\"blue\" diffuse=\"0.15 0.3 0.8\" specular=\"0.4\" shininess=\"40\"/>\n"
      << "  <material id=\"mirror\" diffuse=\"0.1\" specular=\"0.8\" shininess=\"200\" "
         "reflective=\"0.6\"/>\n"
      << "  <plane normal=\"0 1 0\" offset=\"0\">\n"
      << "    <material diffuse=\"0.9\"><checker color1=\"1\" color2=\"0.3\"/></material>\n"
      << "  </plane>\n";
  const char* materials[3] = {"red", "blue", "mirror"};
  int side = int(std::ceil(std::sqrt(double(count))));
  uint32_t state = 12345;
  auto next = [&] {  // Numerical Recipes' LCG, in [0, 1)
    state = state * 1664525u + 1013904223u;
    return double(state >> 8) / double(1u << 24);
  };
  const double spacing = 40.0 / side;
  for (int i = 0; i < count; ++i) {
    double x = -20.0 + spacing * ((i % side) + 0.2 + 0.6 * next());
    double z = -10.0 + spacing * ((i / side) + 0.2 + 0.6 * next());
    double r = spacing * (0.2 + 0.15 * next());
    out << fmt::format(
        "  <sphere center=\"{:.4f} {:.4f} {:.4f}\" radius=\"{:.4f}\" material=\"{}\"/>\n", x, r, z,
        r, materials[i % 3]);
  }
  out << "</scene>\n";
}

}  // namespace lucent::bench
