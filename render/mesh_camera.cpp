#include "mesh_camera.h"

#include <algorithm>
#include <cmath>

namespace lucent {

MeshCameraProjection::MeshCameraProjection(const CameraFrame& frame, const Camera& camera,
                                           int width, int height)
    : Projection(frame, camera, width, height),
      rays_(std::max(1, camera.raysPerPixel)),
      distribution_(camera.distribution),
      offset_(camera.offset),
      reverse_(camera.reverse),
      smooth_(camera.smooth) {
  size_t faces = 0;
  for (const Camera::FaceMesh& m : camera.meshes) {
    const Mat4 world = camera.transform * m.transform;
    meshes_.push_back({m.data.get(), world, glm::transpose(glm::inverse(Mat3(world)))});
    firstFace_.push_back(faces);
    faces += m.data->triangles.size();
  }
  firstFace_.push_back(faces);
}

bool MeshCameraProjection::faceRay(const Mesh& m, size_t face, const Vec3& w, bool interpolate,
                                   Ray& ray) const {
  const auto& t = m.data->triangles[face];
  const Vec3& a = m.data->positions[t[0]];
  const Vec3& b = m.data->positions[t[1]];
  const Vec3& c = m.data->positions[t[2]];
  Vec3 n = glm::cross(b - a, c - a);
  const double length = glm::length(n);
  if (!(length > 0.0)) return false;  // a face without a normal casts no ray
  n /= length;
  if (interpolate && !m.data->normals.empty()) {
    const Vec3 s =
        w.x * m.data->normals[t[0]] + w.y * m.data->normals[t[1]] + w.z * m.data->normals[t[2]];
    if (glm::length(s) > 0.0) n = glm::normalize(s);
  }
  Vec3 origin = w.x * a + w.y * b + w.z * c + offset_ * n;
  if (reverse_) n = -n;
  origin = Vec3(m.worldFromMesh * Vec4(origin, 1.0));
  const Vec3 d = m.normalToWorld * n;
  const double dl = glm::length(d);
  if (!(dl > 0.0) || !std::isfinite(dl)) return false;
  if (!std::isfinite(origin.x) || !std::isfinite(origin.y) || !std::isfinite(origin.z))
    return false;  // a start beyond the numbers: no ray
  ray = primaryRay(origin, d / dl);
  return true;
}

bool MeshCameraProjection::generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const {
  return generateRayNumber(film, lens, 0, ray);
}

bool MeshCameraProjection::generateRayNumber(const Vec2& film, const Vec2&, int index,
                                             Ray& ray) const {
  // POV-Ray's pixel position: a row lower, held within the image.
  const double x = std::clamp(film.x, 0.0, width_ - 1.0);
  const double y = std::clamp(film.y - 1.0, 0.0, height_ - 1.0);
  const auto column = static_cast<size_t>(x), row = static_cast<size_t>(y);
  const Vec3 centroid(1.0 / 3.0);
  switch (distribution_) {
    case 0: {
      if (static_cast<size_t>(index) >= meshes_.size()) return false;
      const Mesh& m = meshes_[static_cast<size_t>(index)];
      const size_t face = row * static_cast<size_t>(width_) + column;
      return face < m.data->triangles.size() && faceRay(m, face, centroid, false, ray);
    }
    case 1: {
      // POV-Ray 3.7 adds index times the faces' count: only ray 0 finds a face.
      const size_t face = row * static_cast<size_t>(width_) + column +
                          static_cast<size_t>(index) * firstFace_.back();
      if (face >= firstFace_.back()) return false;
      const size_t m = static_cast<size_t>(
          std::upper_bound(firstFace_.begin(), firstFace_.end(), face) - firstFace_.begin() - 1);
      return faceRay(meshes_[m], face - firstFace_[m], centroid, false, ray);
    }
    case 2: {
      const double across = static_cast<double>(width_) / static_cast<double>(meshes_.size());
      const auto m = std::min(static_cast<size_t>(x / across), meshes_.size() - 1);
      const size_t face =
          row * (static_cast<size_t>(width_) / meshes_.size()) + column;  // x as POV-Ray's
      return face < meshes_[m].data->triangles.size() &&
             faceRay(meshes_[m], face, centroid, false, ray);
    }
    default: {
      const double u = (x - 0.5) / width_, v = 1.0 - (y + 0.5) / height_;
      const Mesh& m = meshes_.front();
      if (m.data->uvs.empty()) return false;
      for (size_t f = 0; f < m.data->triangles.size(); ++f) {
        const auto& t = m.data->triangles[f];
        const Vec2& p1 = m.data->uvs[t[0]];
        const Vec2& p2 = m.data->uvs[t[1]];
        const Vec2& p3 = m.data->uvs[t[2]];
        const double scale = (p2.x - p1.x) * (p3.y - p1.y) - (p3.x - p1.x) * (p2.y - p1.y);
        if (scale == 0.0) continue;
        const double b1 = ((p2.x - u) * (p3.y - v) - (p3.x - u) * (p2.y - v)) / scale;
        const double b2 = ((p3.x - u) * (p1.y - v) - (p1.x - u) * (p3.y - v)) / scale;
        const double b3 = ((p1.x - u) * (p2.y - v) - (p2.x - u) * (p1.y - v)) / scale;
        if (b1 < 0.0 || b2 < 0.0 || b3 < 0.0) continue;
        return faceRay(m, f, Vec3(b1, b2, b3), smooth_, ray);
      }
      return false;
    }
  }
}

}  // namespace lucent
