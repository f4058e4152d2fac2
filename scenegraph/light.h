// Light sources of the contract's <light>, and their table (light.cpp): one row per type
// (its name, its documentation, how POV-Ray writes it, the checks between its attributes)
// and every attribute of <light> with the reader that stores it into a Light. The parser
// (lang/light_parser.cpp), the schema, `lucent check` and the POV-Ray exporter
// (povray/pov_lights.cpp) read the table and name no type.
#pragma once

#include "attribute_info.h"
#include "attribute_input.h"
#include "source_loc.h"

#include "primitives/math.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lucent {

// A new type: the enumerator and its parameters in Light (here); its row in lightTypes()
// and its attributes with their readers in lightAttributes() (light.cpp); its light in
// render/light_sample.cpp, whose lightIncidence switches over every type, so a type
// without it does not compile (docs/architecture.md).
enum class LightType { Point, Directional, Spot, Area, Cylindrical };

// The frame in which an oriented area light's cross products are taken: Lucent's
// right-handed one, or POV-Ray's left-handed one (Lucent's with z negated, as the
// importer maps POV-Ray's space), which turns the disc's grid the mirrored way.
enum class Handedness { Right, Left };

struct Light;
struct Node;  // node.h, which includes this file

// The exporter's side of writing one light (povray/pov_lights.cpp implements it): a type's
// row writes its POV-Ray keyword and modifiers through it.
class PovLightOut {
 public:
  virtual ~PovLightOut() = default;
  virtual void line(std::string_view text) = 0;
  virtual std::string number(double v) const = 0;       // POV-Ray's number syntax
  virtual std::string vector(const Vec3& v) const = 0;  // <x, y, z>
  // Where POV-Ray's light will differ from Lucent's: a warning at the light.
  virtual void warning(const std::string& message) = 0;
};

// Where POV-Ray's light_source of a type stands; the exporter switches over it.
enum class PovLightPlacement {
  Positioned,  // at position, its colour faded with the distance (the attenuation)
  Parallel,    // far along −direction, aimed at the origin; no fade
};

// Reads attributes into a light through the parser's input (an attribute's reader, or a
// type's checks between attributes).
using LightReader = std::function<void(Light&, AttributeInput&)>;
// Writes a type's POV-Ray keyword and modifiers (point_at, radius, ...).
using LightPovWriter = std::function<void(const Light&, PovLightOut&)>;

struct LightTypeInfo {
  // How POV-Ray writes the type is required: a row cannot be made without it.
  LightTypeInfo(LightType type, std::string_view name, std::string_view pov, std::string_view doc,
                PovLightPlacement povPlacement, LightPovWriter writePov, LightReader finish = {})
      : type(type),
        name(name),
        pov(pov),
        doc(doc),
        povPlacement(povPlacement),
        writePov(std::move(writePov)),
        finish(std::move(finish)) {}

  LightType type;
  std::string_view name;  // type="..."
  std::string_view pov;   // POV-Ray's light_source keyword ("" for a point light)
  std::string_view doc;   // one line, for the schema
  PovLightPlacement povPlacement;
  // The lines after the location, the colour and the fade: the keyword and its modifiers.
  LightPovWriter writePov;
  // After the attributes are read: the checks between them; may be empty.
  LightReader finish;
};
// One row per type, in LightType's order.
const std::vector<LightTypeInfo>& lightTypes();
const LightTypeInfo& lightTypeInfo(LightType type);

// An attribute of <light>, the types that take it (every type when empty) and how it is
// read into a Light: null for the attributes the parser reads for every element (type,
// id, transform). The parser calls the readers in the table's order, so a reader may use
// the attributes above it (look-at the position, inner the angle).
struct LightAttribute {
  AttributeInfo info;
  std::vector<LightType> types;
  LightReader read;
  bool takenBy(LightType t) const;
};
// Every attribute <light> takes, in the schema's order.
const std::vector<LightAttribute>& lightAttributes();

struct Light {
  LightType type = LightType::Point;
  SourceLoc loc;

  Vec3 position{0.0};
  // Unit. Directional: where light travels; spot, cylindrical: the axis.
  Vec3 direction{0.0, -1.0, 0.0};
  Color color{1.0f};
  double intensity = 1.0;           // I_L = color * intensity
  Vec3 attenuation{1.0, 0.0, 0.0};  // a b c of min(1, 1/(a + b r + c r^2))
  // POV-Ray's fade instead of the attenuation, when fadeDistance > 0 (then fadePower > 0
  // too): 2 / (1 + (r / fadeDistance)^fadePower), up to twice the colour near the light.
  double fadeDistance = 0.0;
  double fadePower = 0.0;
  bool fades() const { return fadeDistance > 0.0; }
  bool shadows = true;
  // POV-Ray's media_attenuation: the scene's fogs dim the light along its shadow rays.
  bool mediaAttenuation = false;
  // false: the light adds no phong or specular highlight (diffuse only), as POV-Ray's
  // shadowless light.
  bool highlights = true;

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
  // POV-Ray's circular: the grid's square shells pulled onto circles, so the samples fill
  // the ellipse inscribed in the rectangle (render/light_sample.h has the rule).
  bool circular = false;
  // POV-Ray's orient (circular only): the light turned at every lit point to face it, a
  // disc of diameter |u| across the direction to the centre; v's length equals u's.
  bool orient = false;
  // orient's cross products in this frame (render/light_sample.h has the rule).
  Handedness handedness = Handedness::Right;
  // POV-Ray's `adaptive N`: trace the grid's corners and subdivide where they differ, with
  // at least N forced levels, combining by recursive quadrant averages. Absent: every grid
  // point is traced and the plain average taken.
  std::optional<int> adaptive;

  // Cylindrical, as POV-Ray's cylinder light: distances from the axis (not changed by
  // transforms), full light within radius, none from falloff on.
  double radius = 0.75;
  double falloff = 1.0;
  // POV-Ray's tightness. Spot (and a spot-shaped area light): the exponent of cos θ, the
  // cosine of the angle from the axis; cylindrical: of (1 − distance/falloff). 0: no effect.
  double tightness = 0.0;

  // The instance of the <light-group> whose light this is, 0 for a global light
  // (scenegraph/light_group.h); set when the lights are placed.
  uint32_t group = 0;

  // <projected-through> (POV-Ray's projected_through): the light reaches a point only along
  // a ray that meets these objects before it reaches the light, and only what lies nearer
  // than that meeting shadows it. A group node whose children are the objects, in the
  // light's own frame (its node's); never drawn, shared by the light's placed copies.
  // Null: none.
  std::shared_ptr<Node> projectedThrough;
  // The world from the light's own frame, where placeLights put it: where the
  // projectedThrough objects stand.
  Mat4 worldFromLight{1.0};

  Color radiance() const { return color * static_cast<float>(intensity); }
};

}  // namespace lucent
