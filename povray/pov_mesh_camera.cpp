#include "pov_mesh_camera.h"

#include <fmt/core.h>

#include <cmath>

namespace lucent {

namespace {

// One face, written a, c, b (see the header), with its uvs and, where the mesh has them, its
// vertex normals (a smooth_triangle).
void writeFace(const MeshData& d, const std::array<uint32_t, 3>& t, PovWriter& out) {
  const uint32_t order[3] = {t[0], t[2], t[1]};
  std::string corners;
  for (int k = 0; k < 3; ++k) {
    if (k > 0) corners += ", ";
    corners += povVector(d.positions[order[k]]);
    if (!d.normals.empty()) corners += ", " + povVector(d.normals[order[k]]);
  }
  std::string text = (d.normals.empty() ? "triangle { " : "smooth_triangle { ") + corners;
  if (!d.uvs.empty()) {
    text += " uv_vectors ";
    for (int k = 0; k < 3; ++k) {
      const Vec2& uv = d.uvs[order[k]];
      text += (k > 0 ? ", <" : "<") + povNumber(uv.x) + ", " + povNumber(uv.y) + ">";
    }
  }
  out.line(text + " }");
}

}  // namespace

void writeMeshCamera(const Camera& camera, PovWriter& out, PovIssues& issues) {
  if (camera.near > 0.0)
    issues.error(camera.loc,
                 "a mesh camera's near has no POV-Ray equivalent (its rays start "
                 "on the faces)");
  out.open("camera");
  out.open("mesh_camera");
  // Without commas, as POV-Ray reads them; its optional maximum distance (0 is none).
  out.line(fmt::format("{} {}{}", camera.raysPerPixel, camera.distribution,
                       std::isfinite(camera.far) ? " " + povNumber(camera.far) : ""));
  for (const Camera::FaceMesh& m : camera.meshes) {
    if (!m.data) continue;
    for (const auto& t : m.data->triangles) {
      const Vec3 &a = m.data->positions[t[0]], &b = m.data->positions[t[1]],
                 &c = m.data->positions[t[2]];
      if (!(glm::length(glm::cross(b - a, c - a)) > 0.0)) {
        issues.warning(m.loc,
                       "a mesh camera's face of no area: POV-Ray drops it, so the "
                       "faces after it take other pixels");
        break;
      }
    }
    out.open("mesh");
    for (const auto& t : m.data->triangles) writeFace(*m.data, t, out);
    const Mat4 placed = camera.transform * m.transform;
    if (placed != Mat4(1.0)) out.line(povMatrix(placed));
    out.close();
  }
  if (camera.smooth) out.line("smooth");
  out.close();
  out.line("location <0, 0, " + povNumber(camera.offset) + ">");
  out.line(std::string("direction <0, 0, ") + (camera.reverse ? "-1" : "1") + ">");
  out.close();
}

}  // namespace lucent
