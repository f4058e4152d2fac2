// <light-group>, POV-Ray 3.7's light_group: which lights light which geometry.
//
// - A group's lights are its light children (a <light>, a <use> of one, those a <repeat>
//   or <if> makes there); a light deeper down (in a <group> inside) is a global light, as
//   POV-Ray's light in a union inside a light_group.
// - A leaf is lit by the lights of the innermost group around it that holds both lights and
//   geometry: an outer group's lights do not reach into a nested group (POV-Ray gives the
//   outer lights to the nested group's object, never to its children). A group without
//   lights or without geometry lights nothing and is a plain group for this rule.
// - The scene's other lights (global: outside every group, or deeper in one) light a leaf
//   when the outermost group around it says global-lights="true" (POV-Ray sets the flag on
//   every leaf inside, outer groups last, so the outermost wins), or when it is in none.
// - Shadows do not care: every object shadows every light.
// Each instance of a group (a <use> of one is another) is numbered 1, 2, ... in the order
// a depth-first walk from the root meets it (0: no group). placeLights and flattenScene
// walk so, each numbering with a LightGroupCounter, and so agree.
#pragma once

#include "node.h"

#include <cstdint>

namespace lucent {

// Does the light group hold both lights and geometry (so that its lights light something)?
inline bool groupLightsSomething(const Node& group) {
  bool lights = false, geometry = false;
  for (const auto& c : group.children) (c->isLight() ? lights : geometry) = true;
  return lights && geometry;
}

// What a leaf inherits from the light groups around it.
struct LightGroupScope {
  uint32_t group = 0;  // the innermost group that lights something; 0: none
  // The outermost group's global-lights; -1: in no group.
  int8_t global = -1;

  // Inside the light group `node`, numbered `number`.
  LightGroupScope inside(const Node& node, uint32_t number) const {
    LightGroupScope s = *this;
    if (groupLightsSomething(node)) s.group = number;
    if (s.global < 0) s.global = node.globalLights ? 1 : 0;
    return s;
  }
  bool globalLights() const { return global != 0; }
};

}  // namespace lucent
