// Lucent's scene graph: a parsed scene (settings, cameras, lights, materials, the node
// hierarchy) and the world built from it for rendering.
#pragma once

#include "camera.h"
#include "fog.h"
#include "light.h"
#include "material.h"
#include "node.h"
#include "rainbow.h"
#include "render_settings.h"
#include "sky.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lucent {

// <animation frames clock-from clock-to cyclic>: the scene is a sequence of frames, and the
// built-in names frame, frames and clock change from one to the next.
struct Animation {
  bool present = false;  // the scene has an <animation> element
  int frames = 1;
  double clockFrom = 0.0, clockTo = 1.0;
  bool cyclic = false;

  // clock in frame f (1-based): clock-from + (clock-to - clock-from) * (f - 1) / (N - 1),
  // or / N when cyclic; clock-from when N = 1.
  double clockOf(int frame) const;
};

struct Scene {
  std::string file;  // the scene file named on the command line
  Animation animation;
  int frame = 1;       // which frame of the animation this scene is (1 without one)
  double clock = 0.0;  // its clock
  RenderSettings render;
  std::vector<Camera> cameras;    // at least one
  std::vector<Light> lights;      // in world space: what the renderer and the exporter read
  std::vector<Fog> fogs;          // <fog>s, in scene order; all apply
  std::vector<Rainbow> rainbows;  // <rainbow>s, in scene order; their effects averaged
  // Index 0 is the default material (diffuse 0.8) for shapes with none at all.
  std::vector<Material> materials{Material::defaultMaterial()};
  // The top-level geometry: a group with identity transform. <defs> are not under it.
  std::unique_ptr<Node> root = std::make_unique<Node>();
  // The top-level lights (and those of top-level <repeat>s and <if>s), as light nodes of a
  // group with identity transform beside root; lights in the hierarchy are under root or
  // in defs. Scene::lights holds them all placed in the world (light_placement.h).
  std::unique_ptr<Node> lightRoot = std::make_unique<Node>();
  // Nodes declared in <defs>: instantiated only through <use>.
  std::vector<std::unique_ptr<Node>> defs;
  // <sky>, if the scene has one.
  std::optional<Sky> sky;

  // The camera used for rendering: by name, or the first. Null if the name is unknown.
  const Camera* findCamera(const std::string& name) const;
};

}  // namespace lucent
