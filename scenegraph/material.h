// Materials of the Trace shading model (the contract's <material>); their textures are in
// texture_spec.h.
#pragma once

#include "pattern.h"
#include "source_loc.h"
#include "texture_spec.h"

#include "primitives/math.h"

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace lucent {

// <bump-map src depth>: POV-Ray's bump_map read at the shape's (u,v), or projected from
// pattern space as an <image> is: the shading normal bent by the image's grey levels
// (render/bump_map.h). The renderer loads the pixels.
struct ImageValueGrid;  // images/image_values_file.h, below the scene graph

struct BumpMapSpec {
  std::string path;    // resolved, as ImageTexture's
  double depth = 0.5;  // POV-Ray's bump_size
  SourceLoc loc;
  ImageProjection projection = ImageProjection::uv;
  PatternPlacement placement;  // a projected bump map's pattern space
  bool once = false;           // one copy: off it the normal is not bent
  ImageInterpolation interpolation = ImageInterpolation::bilinear;
  bool keepFacingAway = false;  // keep a bent normal that faces away (POV-Ray's rule)
  // POV-Ray's use_index: a palette image's indices (0..255, not scaled) are the heights
  // instead of its colours' grey levels (render/bump_map.h). `indices` holds them, read
  // when the scene is read; null for an image without a palette, which use_index leaves
  // to its grey levels.
  bool useIndex = false;
  std::shared_ptr<const ImageValueGrid> indices;

  // Read at (u,v) with OpenImageIO's bilinear filter, as before projections existed.
  bool plainUV() const {
    return projection == ImageProjection::uv && !once &&
           interpolation == ImageInterpolation::bilinear && !indices;
  }
};

struct MaterialMapEntry;

struct Material {
  std::string id;  // empty for inline materials
  SourceLoc loc;

  Color emissive{0.0f};         // k_e
  Color ambient{0.0f};          // k_a
  bool ambientIsScalar = true;  // a single-number ambient is multiplied by the texture
  Color diffuse{0.0f};          // k_d (1 when a texture is present and diffuse is not given)
  Color specular{0.0f};         // k_s
  double shininess = 64.0;      // n_s
  Color phong{0.0f};            // k_p: POV-Ray's Phong highlight k_p·(R·L)^phongSize
  double phongSize = 40.0;
  double brilliance = 1.0;  // the diffuse term is k_d·(N·L)^brilliance
  // POV-Ray's crand, as a share of k_d: each light's diffuse term loses u·crand·k_d, u in
  // [0, 1) a hash of the hit point and the light (render/tracer.cpp: directLight). 0: none.
  double crand = 0.0;
  bool metallic = false;  // highlights take the surface colour (POV-Ray's metallic)
  // The metallic tint is 1 + amount·(1 − F)·(C − 1): C the metallic colour times the
  // texture, or without one the diffuse colour times the texture (render/finish.cpp).
  double metallicAmount = 1.0;
  // POV-Ray tints by its pigment, which is not k_d when its diffuse is not 1. Unset: k_d.
  std::optional<Color> metallicColor;
  // POV-Ray's reflection { metallic }: the mirror ray's weight is tinted by the metallic
  // colour, 1 + amount·(1 − F(N·V))·(C − 1), fading out at grazing angles. 0: none.
  double reflectMetallic = 0.0;
  // The ambient term also where the surface is seen from inside its solid (POV-Ray's rule);
  // false: from inside, it is multiplied by transmissive (none inside an opaque solid).
  bool innerAmbient = false;
  // The Fresnel reflection of a ray leaving this solid while it is also inside another
  // (physical: the indices on both sides). false: POV-Ray 3.7's rule, which takes the index
  // of the last solid the ray entered (this one, when nested) over this solid's there, so
  // nothing is reflected on the way out (render/tracer.cpp: interfaceAt).
  bool nestedExitFresnel = true;
  Color reflective{0.0f};    // k_r
  Color transmissive{0.0f};  // k_t
  double ior = 1.0;          // eta
  bool fresnel = false;
  // POV-Ray's reflection { MIN, MAX }: k_r is the reflection at grazing angles and this the
  // one facing the viewer; between them by fresnel's F, or without fresnel by
  // (1 − cos θ)^reflectFalloff (render/finish.cpp: reflectivity). Unset: k_r at every
  // angle (with fresnel: k_r·F).
  std::optional<Color> reflectiveMin;
  double reflectFalloff = 1.0;
  // POV-Ray's reflection { exponent e }: the reflected light I is taken as I^(1/e).
  double reflectExponent = 1.0;
  // fresnel also takes F from the transmitted light (k_t·(1 − F)); false: from the
  // reflection only, as POV-Ray's reflection { fresnel } without conserve_energy.
  bool fresnelTransmission = true;
  // POV-Ray's conserve_energy: k_t is multiplied by 1 − k_r per channel, k_r the
  // reflection at the hit's angle (capped at 1).
  bool conserveEnergy = false;
  Color absorption{0.0f};  // Beer–Lambert coefficient per world unit
  // POV-Ray's interior fade: light travelling d inside is multiplied by
  // fadeColor + (1 − fadeColor)/(1 + (d/fadeDistance)^fadePower) (render/optics.h).
  double fadeDistance = 0.0;  // 0: no fade
  double fadePower = 2.0;
  Color fadeColor{0.0f};
  // POV-Ray's rule: the fade and absorption of a stretch inside dim only the rays that carry
  // light out at the hit ending it (transmitted, or totally reflected), not what is seen at
  // that hit itself; false: everything seen along the stretch.
  bool fadeOnExit = false;
  // Total internal reflection: false adds k_t to the mirror ray's weight k_r; true gives
  // the mirror ray weight 1, as POV-Ray's (which then skips its own reflection there).
  bool fullTir = false;
  // POV-Ray's `hollow`: the fog goes on inside the solid (a ray inside a solid that is not
  // hollow is not fogged, render/fog.h).
  bool hollow = false;
  // POV-Ray's irid, thin-film interference: the light from each light and the mirror ray's
  // are multiplied by 1 + irid·cos(φ/λ) per channel, φ = 2π·t·(|N·L| + |N·V|), t the film's
  // thickness varied by noise with the turbulence (render/finish.cpp).
  double irid = 0.0;  // the amount, 0 to 1; 0: none
  double iridThickness = 0.0;
  double iridTurbulence = 0.0;
  // The thickness noise at (x, y, −z) instead of the world point: POV-Ray's point where the
  // scene is POV-Ray's with z negated, as the POV-Ray importer writes it (its left-handed
  // space), so an imported film varies as POV-Ray's does.
  bool iridLeftHanded = false;

  Texture texture;
  // <layer>s written over this material, bottom first (POV-Ray's layered texture: the
  // last one is on top). Each holds the surface terms (emissive to irid, its texture and
  // normal); the interior terms (ior, fade, absorption, hollow, full-tir, inner-ambient)
  // are the material's. Empty for a material of one layer (render/surface_slots.h).
  std::vector<Material> layers;
  // <material-map>: POV-Ray's texture_map and block patterns of textures. The pattern's value
  // at the hit (a <pattern>'s, or the cell of a <checker>, <hexagon> or <brick>: 0, 1, 2)
  // picks the entries and blends their shaded colours (render/surface_slots.h). A material
  // with a map has no surface of its own: its entries are its surfaces.
  Texture mapPattern;
  std::vector<MaterialMapEntry> mapEntries;
  // <normal>: the shading normal perturbed by a pattern's slope (geometry unchanged).
  std::optional<NormalSpec> normal;
  // <bump-map>: the other normal perturbation (a material holds one of the two at most).
  std::optional<BumpMapSpec> bumpMap;

  bool hasTexture() const { return !std::holds_alternative<std::monostate>(texture); }
  // k_t above 0, or a texture colour with filter or transmit (which lets light through
  // where the texture takes it).
  // A layered material lets light through only where every layer does, a map where any of
  // its entries does.
  bool isTransmissive() const;
  bool layered() const { return !layers.empty(); }
  bool mapped() const { return !mapEntries.empty(); }
  bool isReflective() const { return maxComponent(reflective) > 0.0f; }
  bool isAbsorbing() const { return maxComponent(absorption) > 0.0f; }
  bool hasFade() const { return fadeDistance > 0.0; }
  // Light inside it loses something with the distance: absorption or fade.
  bool attenuates() const { return isAbsorbing() || hasFade(); }
  bool hasHighlight() const { return maxComponent(specular) > 0.0f || maxComponent(phong) > 0.0f; }

  // What a shape with no material at all gets: diffuse 0.8 and nothing else.
  static Material defaultMaterial() {
    Material m;
    m.id = "(default)";
    m.diffuse = Color(0.8f);
    return m;
  }
};

// An entry of a <material-map>: the value it sits at and the surface it shows there (its
// surface terms, texture, normal and layers, or a map of its own; its interior terms are
// the mapped material's).
struct MaterialMapEntry {
  double at = 0.0;
  Material material;
};

inline bool Material::isTransmissive() const {
  if (mapped()) {
    for (const MaterialMapEntry& e : mapEntries)
      if (e.material.isTransmissive()) return true;
    return false;
  }
  if (!(anyNonZero(transmissive) || textureSeeThrough(texture))) return false;
  for (const Material& layer : layers)
    if (!layer.isTransmissive()) return false;
  return true;
}

// Does any surface of the material (its own, a layer, a map's entry) read a pattern, an
// image or a bump map at the shape's mapped (u, v) (mapping="uv")? Only then does the
// tracer ask a leaf for POV-Ray's (u, v).
inline bool usesUvMapping(const Material& m) {
  if (textureUsesUv(m.texture) || textureUvMapped(m.mapPattern)) return true;
  if (m.normal && m.normal->pattern.placement.uv) return true;
  if (m.bumpMap && m.bumpMap->projection != ImageProjection::uv && m.bumpMap->placement.uv)
    return true;
  for (const Material& layer : m.layers)
    if (usesUvMapping(layer)) return true;
  for (const MaterialMapEntry& e : m.mapEntries)
    if (usesUvMapping(e.material)) return true;
  return false;
}

}  // namespace lucent
