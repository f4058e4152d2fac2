// POV-Ray's light_source and its meaning in Lucent (docs/povray-import.md, "Lights").
#pragma once

#include "pov_space.h"

#include "scenegraph/light.h"
#include "scenegraph/source_loc.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lucent::sdl {

enum class PovLightKind { Point, Spotlight, Cylinder };

// `area_light <axis1>, <axis2>, size1, size2` and its modifiers.
struct PovAreaLight {
  Vec3 axis1{1.0, 0.0, 0.0};
  Vec3 axis2{0.0, 0.0, 1.0};
  int size1 = 2;
  int size2 = 2;
  // Absent: POV-Ray traces every grid point (its default level is effectively unbounded).
  std::optional<int> adaptive;
  bool jitter = false;
  bool circular = false;
  bool orient = false;
};

// What a `light_source { ... }` block says, in POV-Ray's space, with POV-Ray's defaults.
// The spotlight's and the cylinder's radius and falloff have different defaults and units
// (degrees for a spotlight, distances for a cylinder): unset here, they take their kind's.
struct PovLight {
  SourceLoc loc;
  Vec3 location{0.0};
  Color color{1.0f};  // the colour's filter and transmit play no part in a light
  PovLightKind kind = PovLightKind::Point;
  bool parallel = false;
  Vec3 pointAt{0.0, 0.0, 1.0};
  std::optional<double> radius;   // spotlight: 30 degrees; cylinder: 0.75
  std::optional<double> falloff;  // spotlight: 45 degrees; cylinder: 1
  double tightness = 0.0;
  std::optional<PovAreaLight> area;
  bool shadowless = false;
  bool mediaAttenuation = false;  // media_attenuation: the fogs dim the light
  double fadeDistance = 0.0;      // both needed (> 0) for any fading
  double fadePower = 0.0;
  PovTransform transform;  // translate, rotate, ... inside the block
  // `looks_like { OBJECT }` (SceneReader::toNode). Behind a pointer: every object read
  // holds a light's worth of room, and nested objects recurse on the stack.
  std::shared_ptr<const struct PovLooksLike> looksLike;
  // `projected_through { OBJECT }`: the object and the light's transform where it was
  // written, as looks_like's (SceneReader::toNode).
  std::shared_ptr<const struct PovLooksLike> projectedThrough;
};

// POV-Ray's attenuation of a light at distance d: 2 / (1 + (d/fade_distance)^fade_power),
// or 1 without both.
double povLightFade(const PovLight& light, double distance);
// POV-Ray's spotlight factor at the angle θ from the axis (cosθ given), tightness included.
double povSpotFactor(const PovLight& light, double cosTheta);

struct LightImport {
  Light light;
  std::vector<std::string> differences;  // what Lucent's light cannot do as POV-Ray's does
};
LightImport importLight(const PovLight& light);

}  // namespace lucent::sdl
