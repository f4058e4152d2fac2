#include "light.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lucent {

namespace {

// POV-Ray averages an area light's shadow samples by recursive 4-corner subdivision: the
// weights are uniform (as Lucent's plain average) only for 2, 4, 8, ... samples per axis;
// 3 gives ¼ ½ ¼, 5 gives 1 2 2 2 1 / 8 (checked by rendering with povray 3.7.0.10).
bool povAveragesUniformly(int n) { return n >= 2 && (n & (n - 1)) == 0; }

// The contract's spot is POV-Ray's spotlight: full light inside `radius`, smoothstep to 0 at
// `falloff` (both half-angles in degrees), times cos^tightness of the angle from the axis. A
// spot-shaped area light is POV-Ray's area_light with spotlight, whose cone is also seen from the
// centre for every sample.
void writePovCone(const Light& l, PovLightOut& out) {
  const Vec3 axis = glm::normalize(l.direction);
  out.line(lightTypeInfo(LightType::Spot).pov);
  out.line("point_at " + out.vector(l.position + axis));
  out.line("radius " + out.number(std::min(l.inner, l.angle)));
  out.line("falloff " + out.number(l.angle));
  out.line("tightness " + out.number(l.tightness));
}

void writePovArea(const Light& l, PovLightOut& out) {
  if (l.hasCone()) writePovCone(l, out);
  out.line(fmt::format("{} {}, {}, {}, {}", lightTypeInfo(LightType::Area).pov, out.vector(l.u),
                       out.vector(l.v), l.samplesU, l.samplesV));
  // Lucent's adaptive light is POV-Ray's: the same corners, test and quadrant averages.
  if (l.adaptive) out.line(fmt::format("adaptive {}", *l.adaptive));
  // The same remap and the same turn as POV-Ray's (render/light_sample.h).
  if (l.circular) out.line("circular");
  if (l.orient) out.line("orient");
  // POV-Ray takes the cross products in the coordinates written, which are Lucent's.
  if (l.handedness == Handedness::Left)
    out.warning(
        "area light: handedness=\"left\" has no POV-Ray equivalent in the exported "
        "coordinates (POV-Ray turns the oriented disc as handedness=\"right\"): its grid is "
        "mirrored, each sample within 0.003 of the axis length of Lucent's");
  if (l.jitter) {
    out.line("jitter");
    out.warning(
        "area light: jitter is random in POV-Ray and a fixed hash in Lucent; the noise "
        "differs");
  }
  // Without `adaptive` POV-Ray subdivides fully (its default level is 100), with its
  // recursive weights; Lucent then averages plainly.
  if (!l.adaptive && (!povAveragesUniformly(l.samplesU) || !povAveragesUniformly(l.samplesV)))
    out.warning(
        fmt::format("area light: POV-Ray weights a {}x{} sample grid unevenly (edge "
                    "samples count less); it matches Lucent's plain average only for "
                    "2, 4, 8, ... samples per side",
                    l.samplesU, l.samplesV));
}

// POV-Ray's cylinder light is parallel (implied by `cylinder`), aimed by point_at; its
// radius, falloff and tightness are distances and an exponent, as Lucent's.
void writePovCylinder(const Light& l, PovLightOut& out) {
  out.line(lightTypeInfo(LightType::Cylindrical).pov);
  out.line("point_at " + out.vector(l.position + glm::normalize(l.direction)));
  out.line("radius " + out.number(l.radius));
  out.line("falloff " + out.number(l.falloff));
  out.line("tightness " + out.number(l.tightness));
}

// A cylindrical light's full beam lies within its edge. Not compared once a value was
// wrong: it would be compared as its default.
void finishCylindrical(Light& l, AttributeInput& in) {
  if (in.failed() || l.radius <= l.falloff) return;
  if (in.has("radius"))
    in.attrError("radius", fmt::format("'radius' ({}) must not exceed 'falloff' ({}{})", l.radius,
                                       l.falloff, in.has("falloff") ? "" : ", its default"));
  else
    in.attrError("falloff", fmt::format("'falloff' ({}) must not be less than 'radius' ({}, its "
                                        "default)",
                                        l.falloff, l.radius));
}

// An area light: any spot attribute makes it spot-shaped; u and v must span a rectangle.
void finishArea(Light& l, AttributeInput& in) {
  l.cone = in.has("direction") || in.has("look-at") || in.has("angle") || in.has("inner") ||
           in.has("tightness");
  if (!(glm::length(glm::cross(l.u, l.v)) > 0.0))
    in.error(
        "<light type=\"area\">: 'u' and 'v' must be non-zero and not parallel (they span the "
        "rectangle)");
  // POV-Ray makes an oriented light circular, and so does Lucent unless told otherwise;
  // it uses only u's length (its warning says the axes must be equal): Lucent asks for it
  // rather than quietly change the light.
  if (l.orient && in.has("circular") && !l.circular)
    in.attrError("orient",
                 "orient=\"true\" makes the light circular (a disc facing the point, as "
                 "POV-Ray's): remove circular=\"false\"");
  if (l.orient) l.circular = true;
  if (l.handedness != Handedness::Right && !l.orient)
    in.attrError("handedness",
                 "handedness turns an oriented light's disc: it needs orient=\"true\"");
  const double lu = glm::length(l.u), lv = glm::length(l.v);
  if (l.orient && std::abs(lu - lv) > 1e-9 * std::max(lu, lv))
    in.attrError("orient",
                 fmt::format("orient=\"true\" needs 'u' and 'v' of equal length (the disc's "
                             "diameter), got {} and {}",
                             lu, lv));
}

}  // namespace

const std::vector<LightTypeInfo>& lightTypes() {
  using P = PovLightPlacement;
  static const std::vector<LightTypeInfo> table{
      {LightType::Point, "point", "", "A point light at position.", P::Positioned,
       [](const Light&, PovLightOut&) {}},
      {LightType::Directional, "directional", "parallel",
       "Parallel light travelling along direction.", P::Parallel,
       [](const Light&, PovLightOut& out) { out.line(lightTypeInfo(LightType::Directional).pov); }},
      {LightType::Spot, "spot", "spotlight",
       "A point light limited to a cone: direction or look-at, angle, inner.", P::Positioned,
       writePovCone},
      {LightType::Area, "area", "area_light",
       "A rectangle u × v centred on position, sampled on a samples grid for soft shadows.",
       P::Positioned, writePovArea, finishArea},
      {LightType::Cylindrical, "cylindrical", "cylinder",
       "Parallel light along direction within a cylinder about the axis through position: full "
       "within radius, none from falloff on, nothing behind position.",
       P::Positioned, writePovCylinder, finishCylindrical},
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

// The readers of the plain attributes: the value, or the light's own when the attribute is
// absent or wrong (reported by the input).
LightReader readVector(const char* name, Vec3 Light::*m) {
  return [name, m](Light& l, AttributeInput& in) { l.*m = in.vector(name, l.*m); };
}
LightReader readNumber(const char* name, double Light::*m, NumberRule rule) {
  return [name, m, rule](Light& l, AttributeInput& in) { l.*m = in.number(name, l.*m, rule); };
}
LightReader readBoolean(const char* name, bool Light::*m) {
  return [name, m](Light& l, AttributeInput& in) { l.*m = in.boolean(name, l.*m); };
}
const std::vector<std::string_view> kHandedness{"right", "left"};
void readHandedness(Light& l, AttributeInput& in) {
  l.handedness = static_cast<Handedness>(
      in.choice("handedness", static_cast<size_t>(l.handedness), kHandedness));
}

// "a b c" of min(1, 1/(a + b·r + c·r²)): none negative, not all zero.
void readAttenuation(Light& l, AttributeInput& in) {
  const Vec3 v = in.vector("attenuation", l.attenuation);
  if (v.x < 0.0 || v.y < 0.0 || v.z < 0.0 || (v.x == 0.0 && v.y == 0.0 && v.z == 0.0))
    in.attrError("attenuation", "expected 3 numbers a b c >= 0, not all zero, got '" +
                                    in.text("attenuation").value_or("") + "'");
  else l.attenuation = v;
}

// POV-Ray's fade, instead of the attenuation: fade-distance (read just before) and
// fade-power, either of them making the light fade, the other then at its default (1, 2).
void readFadePower(Light& l, AttributeInput& in) {
  const bool distance = in.has("fade-distance"), power = in.has("fade-power");
  if (!distance && !power) return;
  l.fadePower = in.number("fade-power", power ? l.fadePower : 2.0, NumberRule::positive());
  if (!distance) l.fadeDistance = 1.0;
  if (in.has("attenuation"))
    in.attrError(distance ? "fade-distance" : "fade-power",
                 "give either 'attenuation' or POV-Ray's fade ('fade-distance', 'fade-power'), "
                 "not both");
}

// A point on the axis, instead of direction (read just before it): the direction from the
// position (read before both).
void readLookAt(Light& l, AttributeInput& in) {
  if (!in.has("look-at")) return;
  if (in.has("direction")) {
    in.attrError("look-at", "give either 'direction' or 'look-at', not both");
    return;
  }
  const Vec3 d = in.vector("look-at", l.position + l.direction) - l.position;
  const double len = glm::length(d);
  if (!(len > 0.0)) in.attrError("look-at", "'look-at' must differ from 'position'");
  else l.direction = d / len;
}

// The inner half-angle: by default the angle (read before it), never beyond it.
void readInner(Light& l, AttributeInput& in) {
  // The light's own value is the default handed to the input, as every reader of the table
  // does, so that the scene writer reads it back through the same call (lang/attribute_probe.h).
  l.inner = in.has("inner") ? in.number("inner", l.inner,
                                        NumberRule::between(0.0, 180.0, "an angle from 0 to 180"))
                            : l.angle;
  if (l.inner > l.angle)
    in.attrError("inner",
                 fmt::format("'inner' ({}) must not exceed 'angle' ({})", l.inner, l.angle));
}

// "nu nv", or one number for both: each from 2 to 1024.
void readSamples(Light& l, AttributeInput& in) {
  const auto list = in.integers("samples");
  if (!list) return;
  if (list->size() != 2 && list->size() != 1) {
    in.attrError("samples",
                 "expected 2 whole numbers (nu nv), got " + std::to_string(list->size()));
    return;
  }
  const long long nu = (*list)[0], nv = list->size() == 2 ? (*list)[1] : nu;
  if (nu < 2 || nv < 2 || nu > 1024 || nv > 1024) {
    in.attrError("samples",
                 "each count must be from 2 to 1024 (the grid includes the edges), got '" +
                     in.text("samples").value_or("") + "'");
    return;
  }
  l.samplesU = static_cast<int>(nu);
  l.samplesV = static_cast<int>(nv);
}

// Levels of forced subdivision; a 1024-point axis is fully split within 10, so larger
// values are all alike and are clamped to fit an int.
void readAdaptive(Light& l, AttributeInput& in) {
  if (!in.has("adaptive")) return;
  const long long n = in.integer("adaptive", -1, 0, kNoIntegerLimit);
  if (n >= 0) l.adaptive = static_cast<int>(std::min(n, 1LL << 20));
}

}  // namespace

const std::vector<LightAttribute>& lightAttributes() {
  using T = LightType;
  const std::vector<T> positioned{T::Point, T::Spot, T::Area, T::Cylindrical},
      aimed{T::Spot, T::Area, T::Cylindrical}, cone{T::Spot, T::Area}, area{T::Area},
      cylindrical{T::Cylindrical};
  const NumberRule spotAngle =
      NumberRule::between(0.0, 180.0, "an angle above 0 and at most 180", true);
  static const std::vector<LightAttribute> table{
      {[] {
         AttributeInfo a = attribute("type", AttrType::Choice, "lightType", "point", "");
         a.choices = typeNames();
         for (std::string_view name : a.choices)
           a.doc += (a.doc.empty() ? "" : " | ") + std::string(name);
         a.doc += ".";
         return a;
       }(),
       {},
       nullptr},
      {attribute("position", AttrType::Vector, {}, "",
                 "point, spot, area, cylindrical: the light's position (area: the centre of the "
                 "rectangle; cylindrical: a point on the beam's axis, where the beam starts). "
                 "Default 0 0 0."),
       positioned, readVector("position", &Light::position)},
      {attribute("color", AttrType::Vector, "signedColor", "1",
                 "Light colour. The light's I_L is color × intensity. A negative component "
                 "takes light away (POV-Ray's negative lights)."),
       {},
       [](Light& l, AttributeInput& in) { l.color = in.signedColor("color", l.color); }},
      {attribute("intensity", AttrType::Number, "nonNegativeNumber", "1", "Multiplier of color."),
       {},
       readNumber("intensity", &Light::intensity, NumberRule::nonNegative())},
      {attribute("attenuation", AttrType::Vector, "nonNegativeVector3", "",
                 "point, spot, area, cylindrical: \"a b c\" (>= 0, not all 0), distance factor "
                 "min(1, 1/(a + b·r + c·r²)); cylindrical: r is the distance along the axis. "
                 "Default 1 0 0 (none)."),
       positioned, readAttenuation},
      {attribute("fade-distance", AttrType::Number, "positiveNumber", "",
                 "point, spot, area, cylindrical: POV-Ray's fade_distance fd (above 0; 1 when "
                 "only fade-power is given), instead of attenuation: the distance factor is "
                 "2/(1 + (r/fd)^fp), which exceeds 1 within fd (up to twice the colour at the "
                 "light); cylindrical: r is the distance along the axis. Default: no fade."),
       positioned,
       [](Light& l, AttributeInput& in) {
         if (in.has("fade-distance"))
           l.fadeDistance = in.number("fade-distance", l.fadeDistance, NumberRule::positive());
       }},
      {attribute("fade-power", AttrType::Number, "positiveNumber", "",
                 "point, spot, area, cylindrical: POV-Ray's fade_power fp (above 0; 2 when only "
                 "fade-distance is given). Default: no fade."),
       positioned, readFadePower},
      {attribute("direction", AttrType::Direction, {}, "",
                 "directional: the direction towards which light travels. spot and spot-shaped "
                 "area: the cone's axis; cylindrical: the beam's (or give look-at). Default 0 "
                 "-1 0."),
       {T::Directional, T::Spot, T::Area, T::Cylindrical},
       [](Light& l, AttributeInput& in) { l.direction = in.direction("direction", l.direction); }},
      {attribute("look-at", AttrType::Vector, {}, "",
                 "spot and spot-shaped area, cylindrical: a point on the axis (instead of "
                 "direction)."),
       aimed, readLookAt},
      {attribute(
           "angle", AttrType::Number, "spotAngle", "",
           "spot and spot-shaped area (seen from its centre): outer half-angle in degrees, "
           "above 0 and at most 180; no light beyond it, nor behind the plane across the axis "
           "at the light (POV-Ray's falloff). Default 30."),
       cone, readNumber("angle", &Light::angle, spotAngle)},
      {attribute("inner", AttrType::Number, "spotAngle", "",
                 "spot and spot-shaped area: half-angle of full intensity in degrees, at most "
                 "angle. Default = angle. Between inner and angle the factor is the smoothstep "
                 "(3−2u)u² of u = (cos θ − cos angle)/(cos inner − cos angle)."),
       cone, readInner},
      {attribute("radius", AttrType::Number, "nonNegativeNumber", "",
                 "cylindrical: the distance from the axis within which the light is full, at most "
                 "falloff. Between radius and falloff the factor is the smoothstep (3−2u)u² of u = "
                 "(falloff − ρ)/(falloff − radius), ρ the distance from the axis. Not changed by "
                 "transforms. Default 0.75."),
       cylindrical, readNumber("radius", &Light::radius, NumberRule::nonNegative())},
      {attribute("falloff", AttrType::Number, "positiveNumber", "",
                 "cylindrical: the distance from the axis from which there is no light. Not "
                 "changed by transforms. Default 1."),
       cylindrical, readNumber("falloff", &Light::falloff, NumberRule::positive())},
      {attribute("tightness", AttrType::Number, "nonNegativeNumber", "",
                 "spot and spot-shaped area: the light is also multiplied by cos^tightness θ, θ "
                 "the angle from the axis, inside the inner cone too; cylindrical: by (1 − "
                 "ρ/falloff)^tightness. As POV-Ray's tightness. Default 0 (no effect)."),
       {T::Spot, T::Area, T::Cylindrical},
       readNumber("tightness", &Light::tightness, NumberRule::nonNegative())},
      {attribute("u", AttrType::Vector, {}, "",
                 "area: first edge vector of the rectangle centred on position. Default 1 0 0."),
       area, readVector("u", &Light::u)},
      {attribute("v", AttrType::Vector, {}, "",
                 "area: second edge vector of the rectangle centred on position. Default 0 0 1."),
       area, readVector("v", &Light::v)},
      {attribute("samples", AttrType::IntegerList, "sampleGrid", "",
                 "area: \"nu nv\" (or one number for both), the shadow sample grid, each 2 to "
                 "1024; the grid includes the rectangle's edges. Default 4 4."),
       area, readSamples},
      {attribute("jitter", AttrType::Boolean, {}, "",
                 "area: jitter the sample positions within their grid cells. Default false."),
       area, readBoolean("jitter", &Light::jitter)},
      {attribute("circular", AttrType::Boolean, {}, "",
                 "area: POV-Ray's circular. The grid's square shells are pulled onto circles, so "
                 "the samples fill the ellipse inscribed in the rectangle u × v. Default false."),
       area, readBoolean("circular", &Light::circular)},
      {attribute(
           "orient", AttrType::Boolean, {}, "",
           "area: POV-Ray's orient (makes the light circular; u and v of equal length). At "
           "every lit point the disc is turned to face it: its axes become perpendicular to the "
           "direction to the centre, each as long as u. Default false."),
       area, readBoolean("orient", &Light::orient)},
      {[] {
         AttributeInfo a = attribute(
             "handedness", AttrType::Choice, "handedness", "right",
             "area with orient: the frame of the cross products that turn the disc. right "
             "(default): Lucent's; left: POV-Ray's left-handed space (Lucent's with z negated, "
             "as the importer maps it), whose disc is turned the mirrored way, as POV-Ray "
             "renders an imported scene.");
         a.choices = kHandedness;
         return a;
       }(),
       area, readHandedness},
      {attribute("adaptive", AttrType::Number, "wholeNumber", "",
                 "area: POV-Ray's adaptive N. Trace the grid's 4 corners and split a rectangle "
                 "of samples into quadrants where its neighbouring corners differ (by more than "
                 "0.1 in the sum of the channels of the light reaching the point), at least N "
                 "levels deep, down to the full grid; the shadow is the recursive mean of the "
                 "quadrants (POV-Ray's weights). Absent: every sample is traced and the plain "
                 "average taken."),
       area, readAdaptive},
      {attribute("shadows", AttrType::Boolean, {}, "true",
                 "Does the light cast shadows? Shadow rays go straight and are filtered by "
                 "transparent surfaces (transmissive colour, absorption)."),
       {},
       readBoolean("shadows", &Light::shadows)},
      {attribute("media-attenuation", AttrType::Boolean, {}, "false",
                 "true: the scene's fogs dim the light along its shadow rays (the stretches "
                 "outside solids or inside hollow ones only), by the share each fog keeps, as "
                 "POV-Ray's media_attenuation on. Default false: fog does not dim lights."),
       {},
       readBoolean("media-attenuation", &Light::mediaAttenuation)},
      {attribute("highlights", AttrType::Boolean, {}, "true",
                 "Does the light give phong and specular highlights? false: diffuse light only, as "
                 "POV-Ray's shadowless light (set it with shadows=\"false\" for POV-Ray's "
                 "shadowless)."),
       {},
       readBoolean("highlights", &Light::highlights)},
      {attribute("id", AttrType::Text, "name", "",
                 "A name for <use ref=\"id\"/>, which places the light again in the use's frame. "
                 "Optional; unique among nodes."),
       {},
       nullptr},
      {attribute("transform", AttrType::Text, "transform", "",
                 "The light's own transform, applied before its parent's: it moves position and "
                 "look-at as points, direction, u and v as vectors. Default: identity."),
       {},
       nullptr},
  };
  return table;
}

}  // namespace lucent
