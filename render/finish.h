// What a surface does with light (the contract's <material> and "Finish"): the light it
// sends towards the viewer from one light (diffuse with brilliance, the Blinn-Phong
// `specular` highlight, the Phong `phong` highlight and `metallic`), and the weights of the
// rays it sends on (mirror and transmitted, `fresnel`, total internal reflection). The
// finish's terms are declared in scenegraph/finish_terms.h; their shading is here.
#pragma once

#include <optional>

#include "scenegraph/material.h"

namespace lucent {

// Where a surface is shaded: the world-space point, the shading normal facing the viewer
// and the direction towards the viewer (unit vectors).
struct ShadingPoint {
  Vec3 p{0.0};
  Vec3 n{0.0, 1.0, 0.0};
  Vec3 v{0.0, 0.0, 1.0};
};

// Per unit of the light's radiance. toLight: the unit direction towards the light, with
// n·toLight > 0 (a light behind the surface gives nothing, the caller skips it). kd: the
// diffuse colour times the texture.
Color surfaceResponse(const Material& m, const Color& kd, const ShadingPoint& at,
                      const Vec3& toLight);
// The same with `metal`, the colour `metallic` tints by: the metallic colour times the
// texture, or kd when the material has none (metallicBase). highlights false: the diffuse
// term alone (a light with highlights="false", as POV-Ray's shadowless light).
Color surfaceResponse(const Material& m, const Color& kd, const Color& metal,
                      const ShadingPoint& at, const Vec3& toLight, bool highlights = true);

// The colour `metallic` and reflect-metallic tint by, given the texture's colour at the hit.
inline Color metallicBase(const Material& m, const Color& texture) {
  return m.metallicColor ? *m.metallicColor * texture : m.diffuse * texture;
}

// The rays a surface sends on and their weights.
struct SecondaryRays {
  // The mirror ray's: k_r (times the Fresnel reflectance with `fresnel`, and the metallic
  // tint with reflect-metallic), plus the transmitted share under total internal
  // reflection (or 1 there, with full-tir).
  Color mirror{0.0f};
  // The transmitted ray's: k_t (times 1 − F with `fresnel`); 0 when totally reflected.
  Color transmitted{0.0f};
  // The transmitted ray goes on unbent: a surface without an inside (a thin sheet), or
  // the same index on both sides.
  bool straight = false;
  // The surface transmits but the ray cannot leave: the mirror ray took its share.
  bool totallyReflected = false;
  Vec3 refracted{0.0};  // its direction when it bends
  // The light the mirror ray brings back is raised to this power per channel (1 / the
  // material's reflect-exponent).
  double mirrorPower = 1.0;
};

// k_r at the hit, before the metallic tint: k_r, or with reflective-min or fresnel the
// reflection at the angle whose cosine with the normal is cosView (n1, n2 the indices
// fresnel takes). `f` receives the Fresnel reflectance (1 without fresnel).
Color reflectivity(const Material& m, double cosView, double n1, double n2, float& f);
// n1: the index on the viewer's side, n2: beyond (both 1 for an opaque material that needs
// no Fresnel split); solid: whether the surface has an inside. metal: metallicBase at the
// hit, needed only with reflect-metallic.
// The indices the Fresnel split takes where they are not the refraction's (POV-Ray's rule on
// leaving a nested solid: Material::nestedExitFresnel).
struct FresnelIndices {
  double n1 = 1.0, n2 = 1.0;
};
SecondaryRays secondaryRays(const Material& m, const ShadingPoint& at, bool solid, double n1,
                            double n2, const Color& metal = Color(1.0f),
                            std::optional<FresnelIndices> fresnel = std::nullopt);

// The mirror ray's weight alone, as secondaryRays gives it where the surface transmits
// nothing: a lower layer's reflection (render/surface_slots.h).
Color mirrorWeight(const Material& m, const ShadingPoint& at, double n1, double n2,
                   const Color& metal = Color(1.0f));

// POV-Ray's empirical metallic reflectivity for the angle whose cosine is `cosAngle`:
// a highlight's colour is 1 + (1 − F)·(C − 1) for the surface colour C ([DB 9/94] in its
// sources), C at normal incidence and white at grazing.
double metallicReflectivity(double cosAngle);

}  // namespace lucent
