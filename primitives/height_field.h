// <height-field src="image" smooth="false" water-level="0"/>: POV-Ray 3.7's height_field.
// The image's W x H pixels are grid points spanning x, z in [0, 1] (pixel column c at
// x = c / (W - 1), image row r at z = 1 - r / (H - 1)) at heights y = h / 65536 of the
// 16-bit height h (primitives/height_map.h). Each cell is two triangles split along the
// diagonal from (i + 1, j) to (i, j + 1), as in POV-Ray. `smooth` interpolates POV-Ray's
// vertex normals (each the normalised sum of the four neighbouring face normals, quantised
// to 16 bits as POV-Ray stores them) bilinearly over the cell, each taken to world space
// first (worldShadingNormal), as POV-Ray does.
//
// The solid: the points of the unit square (x, z) with floor <= y < height(x, z), where the
// floor is the water level less 0.001 / 65536 (POV-Ray's HFIELD_OFFSET). It is closed by
// vertical walls over the square's edges and that floor, so the parts below the water
// level are gone (POV-Ray clips them by its bounding box, whose bottom is there) while the
// surface at the water level stays, and crossings alternate. POV-Ray's height field has neither
// walls nor floor (its inside goes on below the surface without end): the two agree wherever the
// surface is seen from above and the edges lie at the water level. `open` (POV-Ray's look):
// the surface alone, without walls and floor, still cut at the floor; a surface then, not a
// solid (no inside, as Lucent's other open shapes).
//
// Method: a 2-D grid walk over the cells (Amanatides & Woo 1987, "A fast voxel traversal
// algorithm for ray tracing") that skips whole blocks of cells through a min/max mip
// pyramid (Tevs, Ihrke & Seidel 2008, "Maximum mipmaps for fast, accurate, and scalable
// dynamic height field rendering"): a block is skipped when the ray's heights over it lie
// wholly above its highest or below its lowest point. The breaks of the ray's path (cell
// edges and diagonals) split it into pieces over one triangle each, along which the
// surface is linear; the sign of (ray height - surface height) is evaluated once at each
// break and shared by the two pieces that meet there, so every crossing is found once and
// they alternate by construction. A crossing is the exact ray-plane intersection of its
// piece's triangle.
#pragma once

#include "height_map.h"
#include "shape.h"

#include <memory>
#include <vector>

namespace lucent {

class HeightField final : public Shape {
 public:
  // Throws std::invalid_argument for a grid smaller than 2 x 2, a non-finite water level or
  // one at or above the highest point.
  HeightField(std::shared_ptr<const HeightMap> map, bool smooth, double waterLevel,
              bool open = false);

  const char* kind() const override { return "height-field"; }
  AABB bounds() const override { return bounds_; }
  bool isSolid() const override { return !open_; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;
  // Smooth: POV-Ray's blend of the vertex normals taken to world space one by one.
  bool worldShadingNormal(const Ray& objectRay, const Hit& hit, const Transform& worldFromObject,
                          Vec3& ns) const override;
  size_t triangleCount() const override;

  // The surface's height at the object point (x, z) of the unit square (not clamped to
  // the water level).
  double height(double x, double z) const;
  // The grid point's height (h / 65536).
  double gridHeight(int x, int z) const { return map_->at(x, z) * (1.0 / 65536.0); }

  // Hit::part of the walls and the floor; a triangle's part is 2 * (z * (W - 1) + x) + upper.
  static constexpr uint32_t kWallX0 = 0xFFFFFFF0u, kWallX1 = 0xFFFFFFF1u, kWallZ0 = 0xFFFFFFF2u,
                            kWallZ1 = 0xFFFFFFF3u, kFloor = 0xFFFFFFF4u, kTop = 0xFFFFFFF5u;

 private:
  struct MinMax {
    uint16_t lo, hi;
  };
  // Calls sink(t, part, entering) for each crossing along the whole line, in order, until
  // it returns true.
  template <class Sink>
  void walk(const Ray& ray, Sink&& sink) const;
  double triangleHeightGrid(int i, int j, bool upper, double X, double Z) const;
  Vec3 flatNormal(int i, int j, bool upper) const;
  Vec3 smoothNormal(double X, double Z) const;
  // The bilinear blend of the cell's vertex normals, each mapped by `toWorld` first.
  template <class Map>
  Vec3 blendNormals(double X, double Z, Map&& toWorld) const;

  std::shared_ptr<const HeightMap> map_;
  bool smooth_;
  bool open_;  // the surface without walls and floor
  double water_;
  double floor_;  // the solid's bottom: just under the water level
  int cellsX_, cellsZ_;
  std::vector<std::vector<MinMax>> levels_;  // levels_[L]: blocks of 2^L x 2^L cells
  std::vector<int> levelWidth_;
  std::vector<Vec3> vertexNormals_;  // object space, unit (smooth only)
  AABB bounds_;
};

}  // namespace lucent
