#include "pov_finish.h"

#include "scenegraph/wave_shape.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace lucent::sdl {

namespace {

Color withFilter(const Color& c, float f, float t) { return c * f + Color(t); }

// POV-Ray's reflection { MIN, MAX fresnel falloff exponent metallic } as Lucent's k_r
// (MAX, the return value), reflective-min, fresnel (on the reflection only: POV-Ray takes F
// from the transmitted light only through conserve_energy), reflect-falloff,
// reflect-exponent and reflect-metallic.
Color importReflection(const PovFinish& finish, Material& m) {
  const PovReflection& r = finish.reflection;
  if (maxComponent(r.max) <= 0.0f && maxComponent(r.min) <= 0.0f) return Color(0.0f);
  if (r.fresnel) {
    m.fresnel = true;
    m.fresnelTransmission = false;
  }
  // Lucent's default minimum: 0 with fresnel (k_r·F), k_r without (constant).
  if (r.fresnel ? maxComponent(glm::abs(r.min)) > 0.0f : r.min != r.max) m.reflectiveMin = r.min;
  m.reflectFalloff = r.falloff;
  m.reflectExponent = r.exponent;
  // reflection { metallic }: reflect-metallic, tinting by the metallic colour (the pigment,
  // set by importMaterial).
  m.reflectMetallic = r.metallic;
  return r.max;
}

void importFade(const PovInterior& in, Material& m) {
  if (!(in.fadeDistance > 0.0)) return;
  m.fadeOnExit = true;  // POV-Ray fades only the light passing out of the object
  if (in.fadePower >= 1000.0) {
    // exp(−(1 − fade_color)·d/fade_distance): Beer–Lambert, as Lucent's absorption.
    m.absorption = (Color(1.0f) - in.fadeColor) / static_cast<float>(in.fadeDistance);
    m.absorption = glm::max(m.absorption, Color(0.0f));
  } else {
    // fade_color + (1 − fade_color)/(1 + (d/fade_distance)^fade_power): Lucent's fade.
    m.fadeDistance = in.fadeDistance;
    m.fadePower = in.fadePower;
    m.fadeColor = in.fadeColor;
  }
}

}  // namespace

const PatternSpec& PovPigment::blockValueSpec() const {
  static const PatternSpec kUnshaped = [] {
    PatternSpec s;
    s.frequency = 0.0;
    return s;
  }();
  return blockValue ? *blockValue : kUnshaped;
}

double blockCellValue(const PatternSpec& value, int cell) {
  return shapeValue(static_cast<double>(cell), value);
}

bool blockValuesUnchanged(const PatternSpec& value, int cells) {
  for (int i = 0; i < cells; ++i)
    if (blockCellValue(value, i) != static_cast<double>(i)) return false;
  return true;
}

MaterialImport importMaterial(const PovPigment& pigment, const PovFinish& finish,
                              const PovInterior& interior, bool legacyOpacity) {
  MaterialImport out;
  Material& m = out.material;
  std::vector<std::string>& notes = out.differences;
  // A pattern pigment is Lucent's texture, which multiplies diffuse and ambient where it
  // is evaluated. Its filter and transmit here are those every colour shares (a transmit,
  // no filter); any other stays with each colour of the texture, which then scales the
  // local terms and transmits point by point (render/see_through.h).
  const bool patterned = pigment.patterned();
  const Color p = patterned ? Color(1.0f) : pigment.color;
  m.texture = pigment.pattern;
  // POV-Ray 3.7: every local term is scaled by the opacity, what shows through is
  // pigment·filter + transmit, per channel.
  // Not clamped: with filter + transmit above 1 the local terms go negative, as in POV-Ray
  // (a transmit of 100 makes a contrast amplifier: advanced/bwstripe.pov).
  const float opacity = legacyOpacity && !patterned
                            ? 1.0f - (pigment.filter * maxComponent(p) + pigment.transmit)
                            : 1.0f - pigment.filter - pigment.transmit;
  m.diffuse = p * static_cast<float>(finish.diffuse) * opacity;
  m.ambient = p * finish.ambient * opacity;
  m.ambientIsScalar = patterned;  // multiplied by the texture, or the pigment already in it
  m.innerAmbient = true;          // POV-Ray lights the inner side of a surface with ambient too
  m.nestedExitFresnel = false;    // POV-Ray's fresnel ratio on leaving a nested solid: 1
  m.emissive = p * finish.emission * opacity;
  if (patterned && maxComponent(finish.emission) > 0.0f)
    notes.push_back(
        "emission with a pattern pigment: POV-Ray multiplies the emission by the pattern's "
        "colour, Lucent's emission is one colour (imported as the emission alone)");
  m.brilliance = finish.brilliance;
  // POV-Ray subtracts rand·crand·pigment from each light's diffuse term (not scaled by
  // diffuse or the opacity, and nothing where diffuse is 0): a share of k_d here.
  const double diffuseShare = finish.diffuse * opacity;
  if (finish.crand > 0.0 && finish.diffuse > 0.0) {
    if (diffuseShare > 0.0) m.crand = finish.crand / diffuseShare;
    else
      notes.push_back(
          "crand on a pigment that lets everything through (its opacity is 0): POV-Ray's "
          "grain has no share of Lucent's diffuse colour there; left out");
  }
  // Highlights take the light's colour only: neither pigment nor opacity.
  m.phong = Color(static_cast<float>(finish.phong));
  m.phongSize = finish.phongSize;
  m.specular = Color(static_cast<float>(finish.specular));
  m.shininess = finish.roughness > 0.0 ? 1.0 / finish.roughness : 1e9;
  m.transmissive = withFilter(p, pigment.filter, pigment.transmit);
  m.ior = interior.ior;
  m.irid = finish.irid;
  m.iridThickness = finish.iridThickness;
  m.iridTurbulence = finish.iridTurbulence;
  // POV-Ray's noise point is Lucent's with z negated (the importer's space).
  m.iridLeftHanded = finish.iridTurbulence != 0.0;
  const bool transmits = m.isTransmissive();

  m.reflective = importReflection(finish, m);
  // conserve_energy: what is transmitted is what is not reflected, per channel, at the
  // hit's angle.
  m.conserveEnergy = finish.conserveEnergy && transmits;

  if (finish.metallic > 0.0 && m.hasHighlight()) {
    m.metallic = true;
    m.metallicAmount = finish.metallic;
  }
  // POV-Ray's metallic tints by the pigment (the pattern's colour where it has one), not
  // by k_d = pigment·diffuse·opacity.
  if (m.metallic || m.reflectMetallic > 0.0) m.metallicColor = p;
  importFade(interior, m);

  // Under total internal reflection POV-Ray continues the mirror ray with weight 1 (only a
  // surface that transmits can reflect totally).
  m.fullTir = transmits;
  return out;
}

}  // namespace lucent::sdl
