// Lights in the hierarchy (docs/scene-language.md, "Lights in the hierarchy"): a <light>
// may stand in groups, CSG operations and <defs>, and be instantiated by <use>; its
// position, direction and area axes are in its node's frame. Placing them gives the
// world-space lights the renderer and the exporter read (Scene::lights), one per path
// to a light node: the top-level lights first (Scene::lightRoot, in document order), then
// those under the root, in the order of a depth-first walk.
#pragma once

#include "scene.h"

#include <cstddef>
#include <vector>

namespace lucent {

// The light with its own frame mapped by worldFromLight: the position as a point, the
// direction (normalised) and the area axes u, v as vectors, as POV-Ray transforms a
// light_source. Angles and attenuation stay as written (POV-Ray's radius, falloff and
// fade_distance do not scale either).
Light placedLight(const Light& local, const Mat4& worldFromLight);

// Every light of Scene::lightRoot and reachable from Scene::root, placed. Throws LocatedError when
// more than `limit` would be placed (each <use> of a group of lights makes another copy, and uses
// of uses multiply), or when a light's world transform is not finite or flattens it.
std::vector<Light> placeLights(const Scene& scene, size_t limit);

}  // namespace lucent
