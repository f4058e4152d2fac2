#include "map_entries.h"

#include "patterns/pattern_point.h"
#include "patterns/warp.h"

namespace lucent {

const SurfaceInfo& mapEntrySurface(const Texture& mapPattern, const SurfaceInfo& s,
                                   SurfaceInfo& scratch) {
  const PatternPlacement* place = texturePlacement(mapPattern);
  if (!place || place->uv) return s;
  // Marble's and wood's turbulence works inside the pattern: it does not move the point.
  bool displace = true;
  if (const auto* p = std::get_if<PatternTexture>(&mapPattern))
    displace = turbulenceDisplaces(p->pattern.type);
  const bool turbulent = displace && place->turbulence != Vec3(0.0);
  if (place->warps.empty() && !turbulent) return s;
  scratch = s;
  const Vec3 q = warpPoint(*place, s.pObject, displace);
  scratch.pObject = Vec3(glm::inverse(linearPatternFromObject(*place)) * Vec4(q, 1.0));
  return scratch;
}

}  // namespace lucent
