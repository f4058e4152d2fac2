// What rendering a parsed scene would refuse, found without rendering it: `lucent check`
// and `lucent render` both call it (cli/load_scene.cpp), so they refuse the same scenes.
#pragma once

#include "scenegraph/located_error.h"
#include "scenegraph/scene.h"

namespace lucent {

// Throws LocatedError, in the order a render meets them: transforms down to a node that
// multiply beyond double range (no shape is built), the camera that cannot form an image
// at the scene's render size (a cube map without whole-pixel faces...), an image texture
// whose file header cannot be read or is too large (Kind::Input).
void checkRenderable(const Scene& scene, const Camera& camera);

}  // namespace lucent
