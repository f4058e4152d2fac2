#include "shading_normal.h"

#include "bump_map.h"
#include "image_projection.h"
#include "patterns/normal_perturbation.h"
#include "patterns/pattern_point.h"
#include "patterns/warp.h"
#include "uv_mapping.h"

namespace lucent {

Vec3 perturbedShadingNormal(const NormalSpec& normal, const Transform& worldFromObject,
                            const SurfaceInfo& hit, const Vec3& n, const Vec3& v) {
  SurfaceInfo uvView;
  const SurfaceInfo& surface = surfaceFor(normal.pattern.placement, hit, uvView);
  if (normal.bendInWorld) {
    // The world normal carried into pattern space by the placement alone.
    const Vec3 bent = perturbNormal(normal, surface.pObject, n);
    return normal.keepFacingAway || glm::dot(bent, v) > 0.0 ? bent : n;
  }
  // Normals are covariant: the world normal is M^-T times the object one, so the object
  // normal is M^T times the world one.
  const Vec3 objectNormal =
      glm::normalize(glm::transpose(Mat3(worldFromObject.worldFromObject())) * n);
  const Vec3 bent = perturbNormal(normal, surface.pObject, objectNormal);
  const Vec3 world = worldFromObject.normalToWorld(bent);
  return normal.keepFacingAway || glm::dot(world, v) > 0.0 ? world : n;
}

namespace {

// A projected bump map's bent normal: the world normal carried into the bump map's pattern
// space (through the object's and the placement's inverse transposes, normalised as POV-Ray's
// Warp_Normal), bent there, and carried back; n itself off a `once` image.
Vec3 projectedBump(const ImageMap& map, const BumpMapSpec& bump, const Transform& worldFromObject,
                   const SurfaceInfo& hit, const Vec3& n) {
  SurfaceInfo uvView;
  const SurfaceInfo& surface = surfaceFor(bump.placement, hit, uvView);
  const std::optional<Vec2> xy =
      projectToImage(bump.projection, warpPoint(bump.placement, surface.pObject), map.width(),
                     map.height(), bump.once);
  if (!xy) return n;
  const Mat3 place(linearPatternFromObject(bump.placement));
  const Vec3 objectNormal =
      glm::normalize(glm::transpose(Mat3(worldFromObject.worldFromObject())) * n);
  const Vec3 patternNormal = glm::normalize(glm::transpose(glm::inverse(place)) * objectNormal);
  const Vec3 bent = bumpMapNormalAt(map.pixels(), bump.depth, *xy, bump.interpolation, bump.once,
                                    patternNormal, bump.indices.get());
  return glm::normalize(
      worldFromObject.normalToWorld(glm::normalize(glm::transpose(place) * bent)));
}

}  // namespace

Vec3 bumpedShadingNormal(const ImageMap& map, const BumpMapSpec& bump,
                         const Transform& worldFromObject, const SurfaceInfo& surface,
                         const Vec3& n, const Vec3& v) {
  const Vec2 uv = surface.hasUV ? surface.uv : Vec2(0.0);
  Vec3 bent;
  if (bump.plainUV()) {
    bent = bumpMapNormal(map, bump.depth, uv, n);
  } else if (bump.projection == ImageProjection::uv) {
    // At (u,v) with POV-Ray's own filters; off a `once` image the normal is not bent.
    const std::optional<Vec2> xy = uvToImage(uv, Vec2(1.0), map.width(), map.height(), bump.once);
    if (!xy) return n;
    bent = bumpMapNormalAt(map.pixels(), bump.depth, *xy, bump.interpolation, bump.once, n,
                           bump.indices.get());
  } else {
    bent = projectedBump(map, bump, worldFromObject, surface, n);
  }
  return bump.keepFacingAway || glm::dot(bent, v) > 0.0 ? bent : n;
}

}  // namespace lucent
