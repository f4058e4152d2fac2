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
  if (distribution_ == 3) binFacesByUv();
}

void MeshCameraProjection::binFacesByUv() {
  const MeshData& data = *meshes_.front().data;
  if (data.uvs.empty() || data.triangles.empty()) return;
  Vec2 lo(kInf), hi(-kInf);
  for (const auto& t : data.triangles)
    for (int k = 0; k < 3; ++k) {
      lo = glm::min(lo, data.uvs[t[k]]);
      hi = glm::max(hi, data.uvs[t[k]]);
    }
  // Boxes widened by a hair, so a point the barycentric test takes just outside a face's
  // box by rounding is still in one of its cells.
  const Vec2 pad = 1e-9 * glm::max(hi - lo, Vec2(1.0));
  lo -= pad;
  hi += pad;
  uvCells_ =
      std::clamp(static_cast<int>(std::sqrt(static_cast<double>(data.triangles.size()))), 1, 1024);
  uvLow_ = lo;
  uvCell_ = (hi - lo) / static_cast<double>(uvCells_);
  uvBins_.assign(static_cast<size_t>(uvCells_) * uvCells_, {});
  auto cell = [&](double value, int axis) {
    const double c = std::floor((value - uvLow_[axis]) / uvCell_[axis]);
    return static_cast<int>(std::clamp(c, 0.0, uvCells_ - 1.0));
  };
  for (size_t f = 0; f < data.triangles.size(); ++f) {
    const auto& t = data.triangles[f];
    Vec2 a = data.uvs[t[0]], b = a;
    for (int k = 1; k < 3; ++k) {
      a = glm::min(a, data.uvs[t[k]]);
      b = glm::max(b, data.uvs[t[k]]);
    }
    a -= pad;
    b += pad;
    for (int j = cell(a.y, 1); j <= cell(b.y, 1); ++j)
      for (int i = cell(a.x, 0); i <= cell(b.x, 0); ++i)
        uvBins_[static_cast<size_t>(j) * uvCells_ + i].push_back(static_cast<uint32_t>(f));
  }
}

bool MeshCameraProjection::uvRay(double u, double v, Ray& ray) const {
  if (uvBins_.empty()) return false;
  const double cu = std::floor((u - uvLow_.x) / uvCell_.x);
  const double cv = std::floor((v - uvLow_.y) / uvCell_.y);
  if (!(cu >= 0.0 && cu < uvCells_ && cv >= 0.0 && cv < uvCells_)) return false;  // no face there
  const Mesh& m = meshes_.front();
  for (uint32_t f : uvBins_[static_cast<size_t>(cv) * uvCells_ + static_cast<size_t>(cu)]) {
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
    default:
      return uvRay((x - 0.5) / width_, 1.0 - (y + 0.5) / height_, ray);
  }
}

}  // namespace lucent
