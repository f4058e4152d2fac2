// Light sources of the contract's <light>, and the table of light types and attributes that
// the parser's checks, the schema, `lucent check` and the POV-Ray exporter read (light.cpp).
#pragma once

#include "attribute_info.h"
#include "source_loc.h"

#include "primitives/math.h"

#include <optional>
#include <string_view>
#include <vector>

namespace lucent {

// A new type: a row in lightTypes() and its attributes in lightAttributes() (light.cpp),
// its light in render/light_sample.cpp and its POV-Ray text in povray/pov_lights.cpp; both
// switch over every type, so a type without them does not compile (docs/architecture.md).
enum class LightType { Point, Directional, Spot, Area };

struct LightTypeInfo {
  LightType type;
  std::string_view name;  // type="..."
  std::string_view pov;   // POV-Ray's light_source modifier ("" for a point light)
  std::string_view doc;   // one line, for the schema
};
// One row per type, in LightType's order.
const std::vector<LightTypeInfo>& lightTypes();
const LightTypeInfo& lightTypeInfo(LightType type);

// An attribute of <light>, and the types that take it (every type when empty).
struct LightAttribute {
  AttributeInfo info;
  std::vector<LightType> types;
  bool takenBy(LightType t) const;
};
// Every attribute <light> takes, in the schema's order.
const std::vector<LightAttribute>& lightAttributes();

struct Light {
  LightType type = LightType::Point;
  SourceLoc loc;

  Vec3 position{0.0};
  Vec3 direction{0.0, -1.0, 0.0};  // unit; directional: where light travels; spot: the axis
  Color color{1.0f};
  double intensity = 1.0;           // I_L = color * intensity
  Vec3 attenuation{1.0, 0.0, 0.0};  // a b c of min(1, 1/(a + b r + c r^2))
  bool shadows = true;

  // Spot: outer and inner half-angles in degrees.
  double angle = 30.0;
  double inner = 30.0;
  // Area: shaped by the spot cone (direction, angle, inner) seen from its centre, as
  // POV-Ray's area_light with spotlight (set when an area light has a spot attribute).
  bool cone = false;
  bool hasCone() const { return type == LightType::Spot || (type == LightType::Area && cone); }

  // Area: edge vectors of a rectangle centred on position, sample grid, jitter.
  Vec3 u{1.0, 0.0, 0.0};
  Vec3 v{0.0, 0.0, 1.0};
  int samplesU = 4;
  int samplesV = 4;
  bool jitter = false;
  // POV-Ray's `adaptive N`: trace the grid's corners and subdivide where they differ, with
  // at least N forced levels, combining by recursive quadrant averages. Absent: every grid
  // point is traced and the plain average taken.
  std::optional<int> adaptive;

  Color radiance() const { return color * static_cast<float>(intensity); }
};

}  // namespace lucent
