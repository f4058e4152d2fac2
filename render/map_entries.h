// Where a material map's entries are shaded. POV-Ray 3.7 hands the entries of a texture_map
// and of an average of textures the point its pattern was evaluated at, after the pattern's
// transforms, warps and turbulence (Trace::ComputeOneTextureColour, Warp_EPoint; as facts).
// Lucent's entries are placed from the object's space, composed with the map's linear
// placement (its transform and the transform steps between its warps), so they are shaded
// at that warped point carried back by the inverse of the linear placement: the object
// point itself when the map has no other warp and no turbulence that moves it.
#pragma once

#include "primitives/hit.h"
#include "scenegraph/texture_spec.h"

namespace lucent {

// `s` itself, or (kept in `scratch`) `s` with the entries' object point. A uv-mapped map's
// entries read (u, v) themselves, so `s` is returned for it.
const SurfaceInfo& mapEntrySurface(const Texture& mapPattern, const SurfaceInfo& s,
                                   SurfaceInfo& scratch);

}  // namespace lucent
