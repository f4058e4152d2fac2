// <bicubic-patch points="16 points" flatness="0" u-steps="0" v-steps="0"/>: POV-Ray 3.7's
// bicubic_patch, traced as POV-Ray traces it: as triangles, not as the exact surface.
//
// The 16 control points P[i][j] (i = 0..3 along u, j = 0..3 along v; point 4i + j of the
// list) make the Bézier surface S(u, v) = sum B_i(u) B_j(v) P[i][j], with the Bernstein
// polynomials B of degree 3. POV-Ray halves the patch by de Casteljau's construction:
// while the depth is below both u-steps and v-steps, in u and in v (four parts); then in
// the direction whose steps are not yet reached only; a part stops early when it is flat
// (patchFlatness below `flatness`). So without flat parts the patch is cut into
// 2^u-steps x 2^v-steps parts. Each part is the two triangles of its corners,
// (P00, P03, P33) and (P00, P33, P30); their vertex normals are the exact surface's
// normals at the corners' (u, v) (Su x Sv, normalised; (1, 0, 0) where it vanishes, as in
// POV-Ray), interpolated and normalised again; their (u, v) for textures are POV-Ray's:
// the patch's (v, u), interpolated, then carried by `uvCorners` (POV-Ray's uv_vectors) to
// the bilinear blend of the four corners' (u, v) at that point, as POV-Ray carries its hit's.
// POV-Ray's types 0 (subdivide per ray) and 1 (subdivide once) make the same triangles; both
// are this. Not a solid.
//
// Flatness is measured in the patch's own coordinates, or, given `flatnessFrame`, on the
// parts' control points mapped by it: POV-Ray measures it after every transform (it moves
// the control points), and subdividing commutes with affine maps, so the triangles are
// POV-Ray's in the patch's own space (docs/scene-language.md, <bicubic-patch>).
#pragma once

#include "mesh_data.h"
#include "shape.h"
#include "triangle_mesh.h"

#include <array>
#include <memory>

namespace lucent {

using PatchPoints = std::array<Vec3, 16>;  // P[i][j] at 4i + j
// The texture (u, v) of the corners (POV-Ray's uv_vectors): of the patch's (v, u) = (0, 0),
// (1, 0), (1, 1) and (0, 1), in that order. The default gives the patch's own (v, u).
using PatchUvCorners = std::array<Vec2, 4>;
inline const PatchUvCorners kPatchOwnUv = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};

// The texture (u, v) at the patch's (v, u) = p: the corners' blended bilinearly.
Vec2 patchTextureUV(const PatchUvCorners& corners, const Vec2& p);

// The exact surface and its unit normal (POV-Ray's: (1, 0, 0) where Su x Sv vanishes).
Vec3 bezierPatchPoint(const PatchPoints& p, double u, double v);
Vec3 bezierPatchNormal(const PatchPoints& p, double u, double v);

// How far the part's control points lie from the plane of three of its corners (POV-Ray's
// flatness measure); negative when the corners make no plane (then never flat).
double patchFlatness(const PatchPoints& p);

// The triangles POV-Ray traces, with their normals and (u, v).
std::shared_ptr<const MeshData> bicubicPatchMesh(const PatchPoints& p, double flatness, int uSteps,
                                                 int vSteps, const Mat4& flatnessFrame = Mat4(1.0));

class BicubicPatch final : public Shape {
 public:
  // Steps from 0 to kMaxSteps; throws std::invalid_argument otherwise or for points that
  // are not finite.
  BicubicPatch(const PatchPoints& p, double flatness, int uSteps, int vSteps,
               const Mat4& flatnessFrame = Mat4(1.0),
               const PatchUvCorners& uvCorners = kPatchOwnUv);

  static constexpr int kMaxSteps = 10;

  const char* kind() const override { return "bicubic-patch"; }
  AABB bounds() const override { return mesh_.bounds(); }
  bool isSolid() const override { return false; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  bool occluded(const Ray& ray) const override { return mesh_.occluded(ray); }
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3&) const override { return false; }
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;
  // POV-Ray's precomputed (u, v) of the patch: its triangles' (bicubicPatchMesh), carried
  // by the corners (surface).
  bool povUV(const SurfaceInfo& s, const Hit& hit, Vec2& uv) const override {
    return mesh_.povUV(s, hit, uv);
  }
  size_t triangleCount() const override { return mesh_.triangleCount(); }

  const TriangleMesh& mesh() const { return mesh_; }

 private:
  TriangleMesh mesh_;
  PatchUvCorners uvCorners_;
};

}  // namespace lucent
