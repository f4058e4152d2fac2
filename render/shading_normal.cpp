#include "shading_normal.h"

#include "bump_map.h"
#include "patterns/normal_perturbation.h"

namespace lucent {

Vec3 perturbedShadingNormal(const NormalSpec& normal, const Transform& worldFromObject,
                            const SurfaceInfo& surface, const Vec3& n, const Vec3& v) {
  // Normals are covariant: the world normal is M^-T times the object one, so the object
  // normal is M^T times the world one.
  const Vec3 objectNormal =
      glm::normalize(glm::transpose(Mat3(worldFromObject.worldFromObject())) * n);
  const Vec3 bent = perturbNormal(normal, surface.pObject, objectNormal);
  const Vec3 world = worldFromObject.normalToWorld(bent);
  return normal.keepFacingAway || glm::dot(world, v) > 0.0 ? world : n;
}

Vec3 bumpedShadingNormal(const ImageMap& map, const BumpMapSpec& bump, const SurfaceInfo& surface,
                         const Vec3& n, const Vec3& v) {
  const Vec3 bent = bumpMapNormal(map, bump.depth, surface.hasUV ? surface.uv : Vec2(0.0), n);
  return glm::dot(bent, v) > 0.0 ? bent : n;
}

}  // namespace lucent
