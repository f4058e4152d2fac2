#include "finish_terms.h"

#include <fmt/format.h>

namespace lucent {

namespace {

using Read = std::function<void(Material&, AttributeInput&)>;
using WritePov = std::function<void(const Material&, PovFinishOut&)>;

// A term's attribute and its reader; the default a number or boolean attribute shows in the
// schema is Material's own default member value, so it is written once. A colour shows
// none there (its doc says it): an absent colour keeps the base material's.
struct Attribute {
  AttributeInfo info;
  Read read;
};

AttributeInfo info(const char* name, AttrType type, std::string defaultText, std::string doc) {
  AttributeInfo a;
  a.name = name;
  a.type = type;
  a.defaultText = std::move(defaultText);
  a.doc = std::move(doc);
  return a;
}

Attribute color(const char* name, Color Material::*m, std::string doc) {
  AttributeInfo a = info(name, AttrType::Vector, "", std::move(doc));
  a.schemaType = "color";
  return {a, [name, m](Material& s, AttributeInput& in) { s.*m = in.color(name, s.*m, nullptr); }};
}

// A colour whose components may be negative (AttributeInput::signedColor).
Attribute signedColor(const char* name, Color Material::*m, std::string doc) {
  AttributeInfo a = info(name, AttrType::Vector, "", std::move(doc));
  a.schemaType = "signedColor";
  return {a, [name, m](Material& s, AttributeInput& in) { s.*m = in.signedColor(name, s.*m); }};
}

Attribute number(const char* name, double Material::*m, NumberRule rule, std::string doc) {
  AttributeInfo a = info(name, AttrType::Number, fmt::format("{}", Material{}.*m), std::move(doc));
  a.rule = rule;
  return {a,
          [name, m, rule](Material& s, AttributeInput& in) { s.*m = in.number(name, s.*m, rule); }};
}

Attribute boolean(const char* name, bool Material::*m, std::string doc) {
  AttributeInfo a = info(name, AttrType::Boolean, Material{}.*m ? "true" : "false", std::move(doc));
  return {a, [name, m](Material& s, AttributeInput& in) { s.*m = in.boolean(name, s.*m); }};
}

FinishTerm term(Attribute a, std::string_view pov, std::vector<PovHint> hints = {},
                WritePov write = nullptr) {
  return {std::move(a.info), std::move(a.read), pov, std::move(hints), std::move(write)};
}

// The terms of the whole material, which its <layer>s do not take: the interior (what
// light meets inside the solid) and the rules for the ray that crosses the surface.
std::vector<FinishTerm> markInterior(std::vector<FinishTerm> table) {
  static constexpr std::string_view kInterior[] = {
      "ior",        "full-tir",     "absorption", "fade-distance", "fade-power",
      "fade-color", "fade-on-exit", "hollow",     "inner-ambient", "nested-exit-fresnel"};
  for (FinishTerm& t : table)
    for (std::string_view name : kInterior)
      if (t.info.name == name) t.ofInterior = true;
  return table;
}

}  // namespace

const std::vector<FinishTerm>& finishTerms() {
  static const std::vector<FinishTerm> table = markInterior({
      term(signedColor("emissive", &Material::emissive,
                       "k_e, emitted colour (added as is; does not light other objects). Default "
                       "0. May be negative, as ambient."),
           "finish { emission }, divided by the pigment", {{"emission"}}),
      term(
          [] {
            Attribute a = signedColor(
                "ambient", &Material::ambient,
                "k_a, ambient reflectance, times the global ambient (render ambient). Default 0. "
                "A single number is also multiplied by the texture colour. May be negative, as "
                "diffuse.");
            // Whether it was one number decides whether the texture multiplies it.
            a.read = [](Material& m, AttributeInput& in) {
              m.ambient = in.signedColor("ambient", m.ambient, &m.ambientIsScalar);
            };
            return a;
          }(),
          "finish { ambient }, divided by the pigment"),
      term(signedColor("diffuse", &Material::diffuse,
                       "k_d, Lambertian reflectance. Default 0, or 1 when the material has a "
                       "texture (the texture colour multiplies it). A negative component "
                       "darkens what the lights give (POV-Ray's surface whose filter and "
                       "transmit add up to more than 1: its own colour is subtracted)."),
           "the pigment's colour and finish { diffuse }", {{"color"}, {"colour"}, {"rgb"}}),
      term(color("specular", &Material::specular,
                 "k_s, Blinn-Phong highlight colour: k_s (N·H)^shininess. Default 0."),
           "finish { specular } (one number: the mean of a colour)"),
      term(number("shininess", &Material::shininess, NumberRule::nonNegative(),
                  "n_s, Blinn-Phong exponent."),
           "finish { roughness }, 1/shininess", {{"roughness", "(1/roughness)"}},
           [](const Material& m, PovFinishOut& out) {
             // n_s = 0 means (N·H)^0 = 1: an exponent of 1e-9 differs from it by less than
             // float resolution for any N·H above 1e-30.
             out.line("roughness " + out.number(m.shininess > 0.0 ? 1.0 / m.shininess : 1e9));
           }),
      term(color("reflective", &Material::reflective, "k_r, mirror reflection colour. Default 0."),
           "finish { reflection }", {{"reflection"}}),
      term(signedColor("transmissive", &Material::transmissive,
                       "k_t, transmission colour (refraction with ior; also filters shadow "
                       "rays); a negative component subtracts what the ray sees (POV-Ray's "
                       "transmit -1). Default 0."),
           "the pigment's filter or transmit", {{"filter"}, {"transmit"}}),
      term(number("ior", &Material::ior, NumberRule::positive(),
                  "η, index of refraction (> 0). Default 1. Glass 1.5, water 1.33, diamond "
                  "2.42."),
           "interior { ior }"),
      term(boolean("fresnel", &Material::fresnel,
                   "true: k_r becomes k_r·F and k_t becomes k_t·(1−F), F the unpolarised "
                   "dielectric Fresnel reflectance for ior."),
           "finish { reflection { 0, k_r fresnel on } conserve_energy }"),
      term(
          [] {
            Attribute a{info("reflective-min", AttrType::Vector, "",
                             "POV-Ray's reflection { MIN, MAX }: the mirror reflection facing "
                             "the viewer, k_r being the one at grazing angles; between them "
                             "k_min + w·(k_r − k_min), w the Fresnel reflectance F with "
                             "fresnel, else (1 − cos θ)^reflect-falloff. Absent: k_r at "
                             "every angle (with fresnel: k_r·F, a minimum of 0)."),
                        nullptr};
            a.info.schemaType = "color";
            // Unset is not a colour: only a colour that was set is written (as metallic-color).
            a.read = [](Material& m, AttributeInput& in) {
              if (in.has("reflective-min"))
                m.reflectiveMin =
                    in.color("reflective-min", m.reflectiveMin.value_or(Color(-1.0f)));
            };
            return a;
          }(),
          "finish { reflection { MIN, MAX } }, written with the reflection"),
      term(number("reflect-falloff", &Material::reflectFalloff, NumberRule::nonNegative(),
                  "With reflective-min and without fresnel: the exponent k of (1 − cos θ) "
                  "that takes the reflection from reflective-min facing the viewer to "
                  "reflective at grazing angles, >= 0 (POV-Ray's falloff)."),
           "finish { reflection { falloff } }, written with the reflection", {{"falloff"}}),
      term(number("reflect-exponent", &Material::reflectExponent, NumberRule::positive(),
                  "POV-Ray's reflection { exponent e }: the light the mirror ray brings back, "
                  "I, counts as I^(1/e) per channel (> 0; 1: as it is)."),
           "finish { reflection { exponent } }, written with the reflection",
           {{"reflection_exponent"}}),
      term(boolean("fresnel-transmission", &Material::fresnelTransmission,
                   "With fresnel: true takes F from the transmitted light too (k_t·(1−F)); "
                   "false from the reflection only, as POV-Ray's reflection { fresnel } "
                   "without conserve_energy."),
           "POV-Ray's reflection { fresnel } without conserve_energy when false"),
      term(boolean("conserve-energy", &Material::conserveEnergy,
                   "POV-Ray's conserve_energy: k_t is multiplied by 1 − k_r per channel (at "
                   "most 1), k_r the reflection at the hit's angle (with reflective-min, "
                   "fresnel and reflect-metallic)."),
           "finish { conserve_energy }", {{"conserve_energy"}}),
      term(boolean("full-tir", &Material::fullTir,
                   "true: under total internal reflection the mirror ray has weight 1 (in "
                   "place of k_r's reflection), as POV-Ray's; false: k_t is added to "
                   "the mirror ray's k_r."),
           // No POV-Ray line: POV-Ray's own rule is true (povray/ says where false differs).
           "POV-Ray's rule (it has no keyword: a totally reflected ray keeps its weight)"),
      term(color("absorption", &Material::absorption,
                 "Beer–Lambert absorption coefficient per world unit inside the object: light "
                 "travelling d inside is multiplied by exp(−absorption·d). Default 0."),
           "interior { fade_power 1001 fade_distance fade_color }"),
      term(number("fade-distance", &Material::fadeDistance, NumberRule::nonNegative(),
                  "POV-Ray's interior fade: light travelling d inside the object is multiplied "
                  "by fade-color + (1 − fade-color)/(1 + (d/fade-distance)^fade-power) per "
                  "channel (from fade-power 1000 up by exp(−(1 − fade-color)·d/fade-distance)). "
                  ">= 0; 0: no fade."),
           "interior { fade_distance }", {{"fade_distance"}}),
      term(number("fade-power", &Material::fadePower, NumberRule::nonNegative(),
                  "The fade's power, >= 0: 1 linear, 2 quadratic; 0 a constant (1 + "
                  "fade-color)/2 that shadow rays do not take; 1000 or more: exponential."),
           "interior { fade_power }", {{"fade_power"}}),
      term(color("fade-color", &Material::fadeColor,
                 "The colour the fade tends to far inside the object. Default 0."),
           "interior { fade_color }", {{"fade_color"}, {"fade_colour"}}),
      term(boolean("fade-on-exit", &Material::fadeOnExit,
                   "true: the fade and absorption dim only the light leaving the solid (the "
                   "transmitted ray, or the totally reflected one, at a hit reached from "
                   "inside), as POV-Ray's interior; false: everything seen along a stretch "
                   "inside, the hit's own lighting and partial reflection included."),
           // No POV-Ray line: POV-Ray's own rule is true (povray/ says where false differs).
           "POV-Ray's rule (it has no keyword: its fade dims only light passing out)"),
      term(boolean("hollow", &Material::hollow,
                   "true: the scene's fogs go on inside the solid, as inside POV-Ray's hollow "
                   "objects. Default false: a ray inside a solid is not fogged (POV-Ray's "
                   "objects are not hollow by default)."),
           // Written on the objects (povray/pov_materials.cpp: writeInteriorFor).
           "the object's hollow"),
      term(color("phong", &Material::phong,
                 "k_p, Phong highlight colour: k_p (R·L)^phong-size with R the mirror "
                 "direction of the view, as POV-Ray's phong. Default 0."),
           "finish { phong } (one number: the mean of a colour)"),
      term(number("phong-size", &Material::phongSize, NumberRule::positive(),
                  "Phong exponent (> 0), as POV-Ray's phong_size."),
           "finish { phong_size }", {{"phong_size"}},
           [](const Material& m, PovFinishOut& out) {
             if (maxComponent(m.phong) > 0.0f) out.line("phong_size " + out.number(m.phongSize));
           }),
      term(number("brilliance", &Material::brilliance, NumberRule::nonNegative(),
                  "The diffuse term becomes k_d (N·L)^brilliance, as POV-Ray's brilliance."),
           "finish { brilliance }", {},
           [](const Material& m, PovFinishOut& out) {
             out.line("brilliance " + out.number(m.brilliance));
           }),
      term(number("crand", &Material::crand, NumberRule::nonNegative(),
                  "POV-Ray's crand, graininess: each light's diffuse term loses u·crand·k_d "
                  "(times the texture), u in [0, 1) drawn anew for every hit point and light "
                  "(a hash of the point, so an image is the same on every run). POV-Ray's "
                  "crand c with its diffuse d and opacity a is c/(d·a) here. >= 0; 0: none."),
           // POV-Ray's crand multiplies its pigment, not k_d: povray/pov_materials.cpp
           // writes it beside diffuse.
           "finish { crand }"),
      term(boolean("metallic", &Material::metallic,
                   "true: the specular and phong highlights take the surface's diffuse colour "
                   "(times the texture), fading to the light's colour at grazing light as "
                   "POV-Ray's metallic."),
           "finish { metallic }", {},
           [](const Material& m, PovFinishOut& out) {
             // It tints highlights only: without one, POV-Ray has nothing to tint either.
             if (m.metallic && m.hasHighlight())
               out.line(m.metallicAmount == 1.0 ? "metallic"
                                                : "metallic " + out.number(m.metallicAmount));
           }),
      term(number("metallic-amount", &Material::metallicAmount, NumberRule::nonNegative(),
                  "metallic: how much of the tint the highlights take, >= 0 (POV-Ray's "
                  "metallic amount): the tint is 1 + amount·(1 − F)·(C − 1)."),
           "finish { metallic amount }, written by metallic's row"),
      term(
          [] {
            Attribute a{info("metallic-color", AttrType::Vector, "",
                             "metallic and reflect-metallic: the colour C they tint by, times "
                             "the texture (POV-Ray's pigment). Absent: the diffuse colour "
                             "times the texture."),
                        nullptr};
            a.info.schemaType = "color";
            // Unset is not a colour: the writer's probe compares an impossible value, so
            // that only a colour that was set is written (and any colour that was).
            a.read = [](Material& m, AttributeInput& in) {
              if (in.has("metallic-color"))
                m.metallicColor =
                    in.color("metallic-color", m.metallicColor.value_or(Color(-1.0f)));
            };
            return a;
          }(),
          "the pigment a metallic finish tints by"),
      term(number("reflect-metallic", &Material::reflectMetallic, NumberRule::nonNegative(),
                  "POV-Ray's reflection { metallic amount }: the mirror ray's weight is "
                  "multiplied by 1 + amount·(1 − F)·(C − 1), F metallic's reflectivity at the "
                  "angle between N and the viewer and C the metallic colour: tinted facing the "
                  "viewer, untinted at grazing angles. >= 0; 0: none."),
           "finish { reflection { metallic amount } }", {{"reflect_metallic"}}),
      term(boolean("inner-ambient", &Material::innerAmbient,
                   "true: the ambient term also where the surface is seen from inside its "
                   "solid, as POV-Ray lights every surface. Default false: seen from inside, "
                   "the ambient is multiplied by transmissive (an opaque solid's inner side "
                   "gets none, so that a camera inside a backdrop does not see it glow)."),
           // No POV-Ray line: POV-Ray's own rule is true (povray/ says where false differs).
           "POV-Ray's rule (it has no keyword: every surface gets its ambient)"),
      term(boolean("nested-exit-fresnel", &Material::nestedExitFresnel,
                   "With fresnel: whether a ray leaving this solid while it is also inside "
                   "another solid is reflected by Fresnel's law (default true, the indices on "
                   "both sides). false: POV-Ray 3.7's rule, which takes the index of the last "
                   "solid the ray entered over this solid's there: 1 when this solid is the "
                   "innermost, so nothing is reflected on the way out (a glass seen from a "
                   "camera inside a sky sphere)."),
           // No POV-Ray line: POV-Ray's own rule is false (it has no keyword).
           "POV-Ray's rule (it has no keyword: leaving a nested solid, fresnel reflects "
           "nothing)"),
      term(
          [] {
            Attribute a = number("irid", &Material::irid,
                                 NumberRule::between(0.0, 1.0, "a number from 0 to 1"),
                                 "POV-Ray's irid, thin-film interference: the light from each "
                                 "light and the reflected light are multiplied, per channel, "
                                 "by 1 + irid·cos(2π·t·(|N·L| + |N·V|)/λ), t the film's "
                                 "thickness (irid-thickness, varied by irid-turbulence), L "
                                 "the light's direction (the reflected ray's for reflection) "
                                 "and λ POV-Ray's default irid_wavelength 0.70 0.52 0.48 "
                                 "(red, green, blue). 0 to 1; 0: none.");
            a.info.schemaType = "unitInterval";
            return a;
          }(),
          "finish { irid { amount thickness t turbulence u } }", {},
          [](const Material& m, PovFinishOut& out) {
            // POV-Ray's irid_wavelength is left at its default, the wavelengths Lucent uses.
            if (m.irid > 0.0)
              out.line("irid { " + out.number(m.irid) + " thickness " +
                       out.number(m.iridThickness) + " turbulence " + out.number(m.iridTurbulence) +
                       " }");
          }),
      term(number("irid-thickness", &Material::iridThickness, NumberRule::nonNegative(),
                  "irid: the film's thickness t, >= 0; at 0 the factor is 1 + irid everywhere."),
           "finish { irid { thickness } }, written by irid's row", {{"thickness"}}),
      term(number("irid-turbulence", &Material::iridTurbulence, NumberRule::nonNegative(),
                  "irid: the thickness varies over the surface as t·(1 + irid-turbulence·(2τ − "
                  "1)), τ POV-Ray's turbulence (5 octaves, omega 0.5, lambda 2, noise "
                  "generator 2) at the world-space point, >= 0."),
           "finish { irid { turbulence } }, written by irid's row"),
      term(boolean("irid-left-handed", &Material::iridLeftHanded,
                   "irid: the thickness noise taken at (x, y, −z) instead of the world-space "
                   "point: POV-Ray's point in a scene written in POV-Ray's space with z "
                   "negated, as the POV-Ray importer writes scenes (and export-pov reads them "
                   "back), so the film varies as in POV-Ray. Default false."),
           // export-pov writes Lucent's z negated: POV-Ray's noise is at this film's point.
           "POV-Ray's irid noise in its own (left-handed) space"),
  });
  return table;
}

}  // namespace lucent
