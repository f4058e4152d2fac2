#include "light.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace lucent {

const std::vector<LightTypeInfo>& lightTypes() {
  static const std::vector<LightTypeInfo> table{
      {LightType::Point, "point", "", "A point light at position."},
      {LightType::Directional, "directional", "parallel",
       "Parallel light travelling along direction."},
      {LightType::Spot, "spot", "spotlight",
       "A point light limited to a cone: direction or look-at, angle, inner."},
      {LightType::Area, "area", "area_light",
       "A rectangle u × v centred on position, sampled on a samples grid for soft shadows."},
  };
  return table;
}

const LightTypeInfo& lightTypeInfo(LightType type) {
  const auto& table = lightTypes();
  const auto i = static_cast<size_t>(type);
  if (i >= table.size() || table[i].type != type)
    throw std::logic_error("lightTypes(): the rows are not in LightType's order");
  return table[i];
}

bool LightAttribute::takenBy(LightType t) const {
  return types.empty() || std::find(types.begin(), types.end(), t) != types.end();
}

namespace {

AttributeInfo attribute(const char* name, AttrType type, std::string_view schemaType,
                        std::string defaultText, std::string doc) {
  AttributeInfo a;
  a.name = name;
  a.type = type;
  a.schemaType = schemaType;
  a.defaultText = std::move(defaultText);
  a.doc = std::move(doc);
  return a;
}

std::vector<std::string_view> typeNames() {
  std::vector<std::string_view> names;
  for (const LightTypeInfo& t : lightTypes()) names.push_back(t.name);
  return names;
}

}  // namespace

const std::vector<LightAttribute>& lightAttributes() {
  using T = LightType;
  const std::vector<T> positioned{T::Point, T::Spot, T::Area}, cone{T::Spot, T::Area},
      area{T::Area};
  static const std::vector<LightAttribute> table{
      {[] {
         AttributeInfo a = attribute("type", AttrType::Choice, "lightType", "point", "");
         a.choices = typeNames();
         for (std::string_view name : a.choices)
           a.doc += (a.doc.empty() ? "" : " | ") + std::string(name);
         a.doc += ".";
         return a;
       }(),
       {}},
      {attribute("position", AttrType::Vector, {}, "",
                 "point, spot, area: the light's position (area: the centre of the rectangle). "
                 "Default 0 0 0."),
       positioned},
      {attribute("color", AttrType::Vector, "color", "1",
                 "Light colour. The light's I_L is color × intensity."),
       {}},
      {attribute("intensity", AttrType::Number, "nonNegativeNumber", "1", "Multiplier of color."),
       {}},
      {attribute("attenuation", AttrType::Vector, "nonNegativeVector3", "",
                 "point, spot, area: \"a b c\" (>= 0, not all 0), distance factor min(1, 1/(a + "
                 "b·r + c·r²)). Default 1 0 0 (none)."),
       positioned},
      {attribute("direction", AttrType::Direction, {}, "",
                 "directional: the direction towards which light travels. spot and spot-shaped "
                 "area: the cone's axis (or give look-at). Default 0 -1 0."),
       {T::Directional, T::Spot, T::Area}},
      {attribute("look-at", AttrType::Vector, {}, "",
                 "spot and spot-shaped area: a point on the cone's axis (instead of direction)."),
       cone},
      {attribute("angle", AttrType::Number, "spotAngle", "",
                 "spot and spot-shaped area (seen from its centre): outer half-angle in degrees, "
                 "above 0 and at most 90; no light beyond it. Default 30."),
       cone},
      {attribute("inner", AttrType::Number, "spotAngle", "",
                 "spot and spot-shaped area: half-angle of full intensity in degrees, at most "
                 "angle. Default = angle. Between inner and angle the factor is the smoothstep "
                 "(3−2u)u² of u = (cos θ − cos angle)/(cos inner − cos angle)."),
       cone},
      {attribute("u", AttrType::Vector, {}, "",
                 "area: first edge vector of the rectangle centred on position. Default 1 0 0."),
       area},
      {attribute("v", AttrType::Vector, {}, "",
                 "area: second edge vector of the rectangle centred on position. Default 0 0 1."),
       area},
      {attribute("samples", AttrType::IntegerList, "sampleGrid", "",
                 "area: \"nu nv\" (or one number for both), the shadow sample grid, each 2 to "
                 "1024; the grid includes the rectangle's edges. Default 4 4."),
       area},
      {attribute("jitter", AttrType::Boolean, {}, "",
                 "area: jitter the sample positions within their grid cells. Default false."),
       area},
      {attribute("adaptive", AttrType::Number, "wholeNumber", "",
                 "area: POV-Ray's adaptive N. Trace the grid's 4 corners and split a rectangle "
                 "of samples into quadrants where its neighbouring corners differ (by more than "
                 "0.1 in the sum of the channels of the light reaching the point), at least N "
                 "levels deep, down to the full grid; the shadow is the recursive mean of the "
                 "quadrants (POV-Ray's weights). Absent: every sample is traced and the plain "
                 "average taken."),
       area},
      {attribute("shadows", AttrType::Boolean, {}, "true",
                 "Does the light cast shadows? Shadow rays go straight and are filtered by "
                 "transparent surfaces (transmissive colour, absorption)."),
       {}},
      {attribute("id", AttrType::Text, "name", "",
                 "A name for <use ref=\"id\"/>, which places the light again in the use's frame. "
                 "Optional; unique among nodes."),
       {}},
      {attribute("transform", AttrType::Text, "transform", "",
                 "The light's own transform, applied before its parent's: it moves position and "
                 "look-at as points, direction, u and v as vectors. Default: identity."),
       {}},
  };
  return table;
}

}  // namespace lucent
