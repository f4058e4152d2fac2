// The mesh camera, POV-Ray 3.7's `mesh_camera`: each ray starts on a face of a mesh and
// leaves along the face's normal. XML:
//   <camera type="mesh" distribution="0" rays-per-pixel="1" offset="0" reverse="false"
//           smooth="false" far="inf">
//     <mesh positions="..." indices="..." [uvs="..."] [normals="..."] [transform="..."]/> ...
//   </camera>
// A face is a mesh's triangle in the order written; its ray starts at its centroid and goes
// along its normal normalize((b − a) × (c − a)), moved `offset` along that normal first and
// turned back with `reverse`; then the mesh's transform (the direction as a normal) and the
// camera's. The film point (fx, fy) is POV-Ray's pixel position (x, y) = (fx, fy − 1), each
// held within [0, width − 1] and [0, height − 1] (POV-Ray's mesh camera sees its rows one
// pixel lower than its other cameras). By `distribution`:
//   0: ray r of a sample comes from mesh r, face ⌊y⌋·width + ⌊x⌋ (rays-per-pixel at most
//      the number of meshes); the sample averages the rays whose face exists;
//   1: the face ⌊y⌋·width + ⌊x⌋ of the meshes' faces counted on from one mesh to the next
//      (POV-Ray 3.7 puts ray r > 0 past the last face, so only ray 0 exists);
//   2: mesh m = ⌊x / (width / M)⌋ of M side by side, its face ⌊y⌋·⌊width / M⌋ + ⌊x⌋ (POV-Ray's,
//      x not reduced to the mesh's own column);
//   3: the first face of the first mesh whose (u, v) triangle holds u = (x − 0.5) / width,
//      v = 1 − (y + 0.5) / height; the ray starts at that point of the face, along the face
//      normal or, with `smooth`, the vertex normals interpolated there.
// A sample without a ray gets the background.
#pragma once

#include "projection.h"

#include <vector>

namespace lucent {

class MeshCameraProjection final : public Projection {
 public:
  MeshCameraProjection(const CameraFrame& frame, const Camera& camera, int width, int height);
  bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const override;
  int raysPerSample() const override { return rays_; }
  bool generateRayNumber(const Vec2& film, const Vec2& lens, int index, Ray& ray) const override;
  bool fixedOrigin() const override { return false; }

 private:
  struct Mesh {
    const MeshData* data;
    Mat4 worldFromMesh;  // the mesh's transform, then the camera's
    Mat3 normalToWorld;  // its inverse transpose
  };
  // The ray from face `face` of mesh `m` at barycentric weights w (a face's centroid: 1/3 each).
  bool faceRay(const Mesh& m, size_t face, const Vec3& w, bool interpolate, Ray& ray) const;
  // Distribution 3: the first mesh's faces binned by their (u, v) boxes, each cell's list in
  // face order, so the first face of a cell's list that holds a point is the first of all.
  void binFacesByUv();
  bool uvRay(double u, double v, Ray& ray) const;

  std::vector<Mesh> meshes_;
  std::vector<size_t> firstFace_;  // of each mesh among all meshes' faces, and their total
  Vec2 uvLow_{0.0}, uvCell_{1.0};  // the grid's corner and cell size (distribution 3)
  int uvCells_ = 0;                // cells a side
  std::vector<std::vector<uint32_t>> uvBins_;  // row-major, the faces of each cell
  int rays_;
  int distribution_;
  double offset_;
  bool reverse_;
  bool smooth_;
};

}  // namespace lucent
