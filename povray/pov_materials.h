// Materials as POV-Ray textures (pigment + finish) and interiors, following POV-Ray 3.7's
// lighting model. POV-Ray's local colour is
//   P·(ambient·ambient_light + emission)·a + Σ P·Lc·diffuse·a·(N·L) +
//   Lc·specular·(N·Ĥ)^(1/roughness)
// with opacity a = 1 − filter − transmit, reflection not scaled by P or a, and the light
// behind it multiplied by F = P·filter + transmit. Lucent's is
//   k_e + k_a·I_La + Σ I_L·[k_d (N·L)^b + k_s (N·H)^n_s + k_p (R·L)^size] + k_r·I_r + k_t·I_t
// (brilliance b, phong and metallic mean the same in both).
// So the pigment carries the diffuse colour, and every term multiplied by P·a in POV-Ray is
// divided by it here.
#pragma once

#include "pov_image_map.h"
#include "pov_writer.h"

#include "scenegraph/material.h"
#include "scenegraph/shape_spec.h"

#include <optional>
#include <string>
#include <vector>

namespace lucent {

// The numbers of one material's POV-Ray texture and interior that are converted together;
// the finish terms POV-Ray has as they are (brilliance, phong_size, roughness, metallic)
// are written by their rows of the finish table (scenegraph/finish_terms.h).
struct PovSurface {
  // Pigment = pigmentScale ⊙ texture colour (checker colours premultiplied; an image map
  // needs pigmentScale = 1), with `filter` and `transmit` on every pigment colour.
  Vec3 pigmentScale{1.0};
  double filter = 0.0;
  double transmit = 0.0;
  bool useTexture = false;  // false: a plain pigment (no texture, or one that cannot show)

  // finish
  Vec3 ambient{0.0};   // colour, multiplied by ambient_light and the pigment
  Vec3 emission{0.0};  // colour, multiplied by the pigment
  double diffuse = 0.0;
  double crand = 0.0;  // POV-Ray's: subtracted times its pigment, not times diffuse
  double specular = 0.0;
  double phong = 0.0;
  Vec3 reflection{0.0};  // the maximum (fresnel, or with a minimum) or constant reflection
  std::optional<Vec3> reflectionMin;  // reflection { MIN, MAX }: facing the viewer
  double falloff = 1.0;
  double exponent = 1.0;
  bool fresnel = false;
  bool conserveEnergy = false;
  double reflectMetallic = 0.0;  // reflection { metallic amount }

  // interior
  bool interior = false;
  double ior = 1.0;
  bool fade = false;  // the fade, or Beer–Lambert absorption as fade_power 1001
  double fadeDistance = 1.0;
  double fadePower = 1001.0;
  Vec3 fadeColor{1.0};
};

// Maps one material; problems go to `issues` at the material's location. `name` is how
// messages call the material ("material 'glass'").
PovSurface povSurface(const Material& m, PovIssues& issues);

// Writes `#declare` of a texture (and an interior where needed) for every material whose
// flag in `used` is set, except image textures, which depend on the shape and are written
// inline by writeTexture(). A material is converted when first used, so an unused one (a
// whole included library, say) gives no error or warning.
class PovMaterials {
 public:
  PovMaterials(const std::vector<Material>& materials, PovIssues& issues);

  void writeDeclarations(const std::vector<bool>& used, PovWriter& out) const;
  // Inside a shape block: its texture and interior (unless `interior` is false: the
  // enclosing CSG object holds it). `shape` chooses the image mapping; `loc` is the
  // shape's location for errors.
  void writeFor(uint32_t material, const ShapeSpec& shape, const SourceLoc& loc, PovWriter& out,
                PovIssues& issues, bool interior = true) const;
  // The same with an explicit image mapping (a box face).
  void writeFor(uint32_t material, const ImageMapping& mapping, const char* shapeName,
                const SourceLoc& loc, PovWriter& out, PovIssues& issues,
                bool interior = true) const;
  // An interior-material as the shape's interior_texture block.
  void writeInteriorTexture(uint32_t material, const ShapeSpec& shape, const SourceLoc& loc,
                            PovWriter& out, PovIssues& issues) const;
  void writeInteriorTexture(uint32_t material, const ImageMapping& mapping, const char* shapeName,
                            const SourceLoc& loc, PovWriter& out, PovIssues& issues) const;
  // The interior alone (and `hollow` for a hollow material), for a CSG object whose
  // operands share it.
  void writeInteriorFor(uint32_t material, PovWriter& out) const;
  // Does the material show an image map (whose mapping depends on the shape)?
  bool usesImageMap(uint32_t material) const;
  // Is its texture written per shape (an image map, or a bump map)?
  bool dependsOnShape(uint32_t material) const;

  const std::string& textureName(uint32_t material) const { return names_[material]; }
  const PovSurface& surface(uint32_t material) const;
  // Has any material flagged in `used` a highlight?
  bool anySpecular(const std::vector<bool>& used) const;

 private:
  // With `mapping` null: the declaration (no image map).
  void writeTexture(uint32_t index, const ImageMapping* mapping, const char* shapeName,
                    const SourceLoc* loc, PovWriter& out, PovIssues* issues) const;
  // One layer's pigment, normal and finish: a material's own or one of its <layer>s.
  void writeLayer(const Material& m, const PovSurface& s, const ImageMapping* mapping,
                  const char* shapeName, const SourceLoc* loc, PovWriter& out,
                  PovIssues* issues) const;
  // A material map's pattern and its entries' textures, inside the texture block.
  void writeMap(const Material& m, const ImageMapping* mapping, const char* shapeName,
                const SourceLoc* loc, PovWriter& out, PovIssues* issues) const;
  // The POV-Ray numbers of a material's <layer>s, converted on first use.
  const std::vector<PovSurface>& layerSurfaces(uint32_t material) const;
  void writeInterior(const PovSurface& s, PovWriter& out) const;

  const std::vector<Material>& materials_;
  PovIssues& issues_;
  mutable std::vector<std::optional<PovSurface>> surfaces_;  // converted on first use
  mutable std::vector<std::optional<std::vector<PovSurface>>> layerSurfaces_;  // the same
  mutable int layeredEntries_ = 0;  // names the layered map entries declared so far
  std::vector<std::string> names_;  // the texture identifier; interior: "I" + name
};

// How a material is called in messages: "material 'glass'" or "the inline material".
std::string materialLabel(const Material& m);

}  // namespace lucent
