// Materials of the Trace shading model (the contract's <material>) and their textures.
#pragma once

#include "pattern.h"
#include "source_loc.h"

#include "primitives/math.h"

#include <memory>
#include <optional>
#include <string>
#include <variant>

namespace lucent {

// <checker color1 color2 scale>: a solid 3-D checker in the shape's object space;
// the cube [0, scale)^3 has color1.
struct CheckerTexture {
  Color color1{1.0f};
  Color color2{0.0f};
  double scale = 1.0;
};

// <image src scale>: an image looked up with the shape's (u,v). The pixels are loaded by
// the renderer; the scene keeps the resolved path.
struct ImageTexture {
  std::string path;  // resolved, absolute or relative to the working directory
  Vec2 scale{1.0, 1.0};
  SourceLoc loc;
};

// <pattern type>: a procedural pattern's value turned into a colour by its colour map (an
// empty map: the value is the grey level).
struct PatternTexture {
  PatternSpec pattern;
  ColorMap map;
};

// <hexagon> and <brick>: block patterns with colours of their own.
struct HexagonTexture {
  HexagonSpec spec;
  PatternPlacement placement;
};
struct BrickTexture {
  BrickSpec spec;
  PatternPlacement placement;
};

// <bump-map src depth>: POV-Ray's bump_map read at the shape's (u,v): the shading normal
// bent by the image's grey levels (render/bump_map.h). The renderer loads the pixels.
struct BumpMapSpec {
  std::string path;    // resolved, as ImageTexture's
  double depth = 0.5;  // POV-Ray's bump_size
  SourceLoc loc;
};

using Texture = std::variant<std::monostate, CheckerTexture, ImageTexture, PatternTexture,
                             HexagonTexture, BrickTexture>;

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
  double brilliance = 1.0;   // the diffuse term is k_d·(N·L)^brilliance
  bool metallic = false;     // highlights take the surface colour (POV-Ray's metallic)
  Color reflective{0.0f};    // k_r
  Color transmissive{0.0f};  // k_t
  double ior = 1.0;          // eta
  bool fresnel = false;
  Color absorption{0.0f};  // Beer–Lambert coefficient per world unit
  // POV-Ray's irid, thin-film interference: the light from each light and the mirror ray's
  // are multiplied by 1 + irid·cos(φ/λ) per channel, φ = 2π·t·(|N·L| + |N·V|), t the film's
  // thickness varied by noise with the turbulence (render/finish.cpp).
  double irid = 0.0;  // the amount, 0 to 1; 0: none
  double iridThickness = 0.0;
  double iridTurbulence = 0.0;

  Texture texture;
  // <normal>: the shading normal perturbed by a pattern's slope (geometry unchanged).
  std::optional<NormalSpec> normal;
  // <bump-map>: the other normal perturbation (a material holds one of the two at most).
  std::optional<BumpMapSpec> bumpMap;

  bool hasTexture() const { return !std::holds_alternative<std::monostate>(texture); }
  bool isTransmissive() const { return maxComponent(transmissive) > 0.0f; }
  bool isReflective() const { return maxComponent(reflective) > 0.0f; }
  bool isAbsorbing() const { return maxComponent(absorption) > 0.0f; }
  bool hasHighlight() const { return maxComponent(specular) > 0.0f || maxComponent(phong) > 0.0f; }

  // What a shape with no material at all gets: diffuse 0.8 and nothing else.
  static Material defaultMaterial() {
    Material m;
    m.id = "(default)";
    m.diffuse = Color(0.8f);
    return m;
  }
};

}  // namespace lucent
