// <mesh src="file.obj" smooth="auto"/>  or  <mesh positions="..." indices="..."
//       normals="..." uvs="..." smooth="auto"/>
//   src        OBJ, PLY, OFF or STL file, relative to the scene file
//   positions  inline: x y z per vertex;  indices: three per triangle
//   normals    optional, one per position (normalised on load);  uvs: optional, u v each
//   smooth     auto (default: the given normals if any, else flat) / true (area-weighted
//              vertex normals, computed) / false (flat)
// The loading and orienting is MeshData's business (meshes/mesh_files.h); this shape intersects it.
// A closed, outward-oriented mesh (MeshData::closed) is a solid; otherwise every triangle
// is a loose surface. Shading normals interpolate the vertex normals (normalised again);
// (u,v) interpolate MeshData::uvs when present. Triangles of zero area are never hit.
// Hit::part is the triangle index, Hit::b1 and b2 the barycentric weights of its second
// and third corner.
#pragma once

#include "bvh.h"
#include "mesh_data.h"
#include "shape.h"
#include "watertight.h"

#include <memory>
#include <vector>

namespace lucent {

// Area-weighted vertex normals (each triangle adds its (p1 − p0) × (p2 − p0), whose length
// is twice its area, to its three corners), normalised; a vertex touched only by
// zero-area triangles gets (0, 0, 0), which the surface code treats as "no normal".
std::vector<Vec3> computeVertexNormals(const MeshData& mesh);

class TriangleMesh final : public Shape {
 public:
  // useNormals: shade with mesh->normals (ignored unless there is one per position).
  // Throws std::invalid_argument when a triangle names a vertex that does not exist.
  TriangleMesh(std::shared_ptr<const MeshData> mesh, bool useNormals);

  const char* kind() const override { return "mesh"; }
  AABB bounds() const override { return bounds_; }
  bool isSolid() const override { return mesh_->closed; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  bool occluded(const Ray& ray) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;
  bool povUV(const SurfaceInfo& s, const Hit& hit, Vec2& uv) const override;
  size_t triangleCount() const override { return mesh_->triangles.size(); }

  const MeshData& data() const { return *mesh_; }
  // The triangles' hierarchy (statistics, memory figures).
  const Bvh& bvh() const { return bvh_; }

 private:
  // Calls visit(triangleIndex) for every triangle the ray may hit with t in
  // [ray.tmin, tFar], nearest BVH boxes first unless `order` says otherwise, where tFar
  // is read again after each call (a closest-hit search shrinks it). visit returns false
  // to stop.
  template <class Visit>
  void forEachCandidate(const Ray& ray, const double& tFar, Visit&& visit,
                        Bvh::Order order = Bvh::Order::NearestFirst) const;

  // The same search a leaf at a time, for the closest and any-hit searches: exact(
  // triangleIndex, corners) for the triangles of the entered leaves that the four-lane
  // pre-test (watertight_filter.h) leaves, in slot order; exact returns false to stop.
  // Returns true if it was stopped so.
  template <class Exact>
  bool forEachLeafCandidate(const Ray& ray, const ShearedRay& sr, const double& tFar, Exact&& exact,
                            Bvh::Order order = Bvh::Order::NearestFirst) const;

  std::shared_ptr<const MeshData> mesh_;
  bool useNormals_;
  AABB bounds_;
  // Over the triangles with non-zero area (the others have an empty box: never visited);
  // it keeps its leaf order, so the visits name triangles by their index in MeshData.
  Bvh bvh_;
};

}  // namespace lucent
