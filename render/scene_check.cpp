#include "scene_check.h"

#include "projection.h"
#include "texture.h"

#include "scenegraph/world.h"

namespace lucent {

void checkRenderable(const Scene& scene, const Camera& camera) {
  checkWorld(scene);
  makeProjection(camera, scene.render.width, scene.render.height);
  checkImageTextures(scene.materials);
}

}  // namespace lucent
