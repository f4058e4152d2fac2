#include "pov_materials.h"
#include "pov_patterns.h"
#include "scenegraph/finish_terms.h"
#include "scenegraph/images_in_maps.h"
#include "scenegraph/linear_placement.h"
#include "scenegraph/map_blend.h"
#include "scenegraph/overloaded.h"
#include "scenegraph/shape_registry.h"

#include <fmt/core.h>

#include <cmath>
#include <functional>

namespace lucent {

namespace {

Vec3 v3(const Color& c) { return Vec3(c.r, c.g, c.b); }
bool isZero(const Vec3& c) { return c.x == 0.0 && c.y == 0.0 && c.z == 0.0; }
bool isGrey(const Vec3& c) { return c.x == c.y && c.y == c.z; }
// Colours are float in both renderers: the mean as a float reads (and prints) cleanly.
double mean(const Vec3& c) { return static_cast<float>((c.x + c.y + c.z) / 3.0); }

// term / divisor per channel; a channel with term > 0 over a zero divisor cannot be made
// (POV-Ray multiplies the term by the pigment, which is 0 there): reported by `bad`.
Vec3 divide(const Vec3& term, const Vec3& divisor, bool& bad) {
  Vec3 r(0.0);
  for (int i = 0; i < 3; ++i) {
    if (term[i] == 0.0) continue;
    if (divisor[i] > 0.0) r[i] = term[i] / divisor[i];
    else bad = true;
  }
  return r;
}

// The number d with kd = d·colour (the diffuse colour as POV-Ray's pigment `colour` times
// its diffuse), to float precision; none when kd is not such a multiple.
std::optional<double> diffuseOver(const Vec3& kd, const Vec3& colour) {
  double d = -1.0;
  for (int i = 0; i < 3; ++i)
    if (colour[i] > 0.0 && d < 0.0) d = kd[i] / colour[i];
  if (d < 0.0) return isZero(kd) ? std::optional<double>(0.0) : std::nullopt;
  for (int i = 0; i < 3; ++i)
    if (std::abs(kd[i] - d * colour[i]) > 1e-6 * std::max(1.0, kd[i])) return std::nullopt;
  return d;
}

// A number computed from float colours, as short as its float value.
std::string floatText(double v) { return fmt::format("{}", static_cast<float>(v)); }

// A finish table row's lines, into the texture's finish block.
class FinishLines final : public PovFinishOut {
 public:
  explicit FinishLines(PovWriter& out) : out_(out) {}
  void line(std::string_view text) override { out_.line(text); }
  std::string number(double v) const override { return povNumber(v); }

 private:
  PovWriter& out_;
};

std::string colourText(const Color& c) {
  if (c.r == c.g && c.g == c.b) return fmt::format("{}", c.r);
  return fmt::format("{} {} {}", c.r, c.g, c.b);
}

}  // namespace

std::string materialLabel(const Material& m) {
  if (m.id == "(default)") return "the default material";
  if (m.id.empty()) return "the inline material";
  return fmt::format("material '{}'", m.id);
}

PovSurface povSurface(const Material& m, PovIssues& issues) {
  PovSurface s;
  const std::string name = materialLabel(m);
  const Vec3 kd = v3(m.diffuse), ka = v3(m.ambient), ke = v3(m.emissive);
  const Vec3 ks = v3(m.specular), kr = v3(m.reflective), kt = v3(m.transmissive);
  const bool hasTexture = m.hasTexture();
  const bool isImage = std::holds_alternative<ImageTexture>(m.texture);
  const bool noLocal = isZero(kd) && isZero(ka) && isZero(ke);

  // Transparency. POV-Ray transmits F = P·filter + transmit and scales the local terms by
  // a = 1 − filter − transmit.
  bool filterOnly = false;
  if (!isZero(kt)) {
    if (isGrey(kt)) {
      s.transmit = kt.x;
    } else if (noLocal) {
      // Nothing local to keep: P = k_t, filter 1 gives F = k_t exactly (and a = 0).
      filterOnly = true;
      s.filter = 1.0;
      s.pigmentScale = kt;
    } else {
      s.transmit = mean(kt);
      issues.warning(m.loc, fmt::format("{}: a coloured transmissive ({}) with diffuse, ambient "
                                        "or emissive has no POV-Ray equivalent (its filter "
                                        "colour is the diffuse pigment); transmit {} is used",
                                        name, colourText(m.transmissive), floatText(s.transmit)));
    }
  }
  const double a = 1.0 - s.filter - s.transmit;
  if (!noLocal && !(a > 0.0)) {
    issues.error(m.loc, fmt::format("{}: transmissive {} with diffuse, ambient or emissive has "
                                    "no POV-Ray equivalent: POV-Ray scales those by "
                                    "1 - transmit = {}",
                                    name, colourText(m.transmissive), povNumber(a)));
    return s;
  }

  // Pigment and diffuse: POV-Ray's diffuse is one number, so a coloured k_d goes into the
  // pigment (diffuse 1) and a grey one into `diffuse` (pigment white, or the texture).
  double d = 0.0;
  if (!filterOnly) {
    s.useTexture = hasTexture;
    // POV-Ray's metallic tints highlights (and reflection { metallic } the reflection) by
    // the pigment: it must then be the metallic colour, or carry the whole diffuse colour
    // as it does for a coloured k_d.
    const bool tints = (m.metallic && m.hasHighlight()) || m.reflectMetallic > 0.0;
    const bool metallicPigment = tints && !isImage && !isZero(kd);
    const std::optional<double> byColour =
        tints && m.metallicColor && !isImage ? diffuseOver(kd, v3(*m.metallicColor)) : std::nullopt;
    if (tints && m.metallicColor && !isImage && !byColour)
      issues.warning(m.loc, fmt::format("{}: diffuse {} is not a multiple of metallic-color {}: "
                                        "POV-Ray's pigment carries both, the diffuse colour is "
                                        "kept",
                                        name, colourText(m.diffuse), colourText(*m.metallicColor)));
    if (byColour) {
      s.pigmentScale = v3(*m.metallicColor);
      d = *byColour;
    } else if (isGrey(kd) && !metallicPigment) {
      d = kd.x;
    } else if (isImage) {
      d = mean(kd);
      issues.warning(m.loc, fmt::format("{}: POV-Ray cannot tint an image map by the coloured "
                                        "diffuse {}; diffuse {} is used",
                                        name, colourText(m.diffuse), floatText(d)));
    } else {
      s.pigmentScale = kd;
      d = 1.0;
    }
  }
  s.diffuse = a > 0.0 ? d / a : 0.0;
  // Lucent's crand is a share of k_d = d·pigment; POV-Ray's multiplies the pigment alone.
  s.crand = m.crand * d;
  // A see-through texture: POV-Ray lets P·f + t through, P = pigmentScale·C, and scales the
  // local terms by 1 - f - t of each colour plus the material's own; Lucent lets C·f + t
  // through and scales k_t too (docs/scene-language.md, "Filter and transmit").
  if (textureSeeThrough(m.texture) && (!isZero(kt) || s.pigmentScale != Vec3(1.0)))
    issues.warning(m.loc, fmt::format("{}: a texture with filter or transmit on a material with "
                                      "transmissive or a coloured diffuse: POV-Ray lets through "
                                      "the pigment (diffuse colour included) and adds the "
                                      "material's transmit to each colour's",
                                      name));

  // Ambient and emission are multiplied by P·a in POV-Ray.
  if (!filterOnly) {
    const Vec3 pa = s.pigmentScale * a;
    bool bad = false;
    s.ambient = divide(ka, pa, bad);
    s.emission = divide(ke, pa, bad);
    if (bad)
      issues.error(m.loc, fmt::format("{}: ambient or emissive is non-zero in a channel where "
                                      "diffuse ({}) is zero; POV-Ray multiplies both by the "
                                      "pigment, which carries the diffuse colour",
                                      name, colourText(m.diffuse)));
    if (hasTexture && !m.ambientIsScalar && !isZero(ka))
      issues.warning(m.loc, fmt::format("{}: POV-Ray multiplies the coloured ambient by the "
                                        "texture; Lucent does so only for a single-number "
                                        "ambient",
                                        name));
    if (hasTexture && !isZero(ke))
      issues.warning(m.loc, fmt::format("{}: POV-Ray multiplies emission by the texture; "
                                        "Lucent does not",
                                        name));
  }

  // Highlight: Blinn with exponent 1/roughness, coloured by the light only.
  if (!isZero(ks)) {
    s.specular = ks.x;
    if (!isGrey(ks)) {
      s.specular = mean(ks);
      issues.warning(m.loc, fmt::format("{}: POV-Ray's specular is one number; the coloured "
                                        "specular {} becomes {}",
                                        name, colourText(m.specular), floatText(s.specular)));
    }
  }
  if (!isZero(v3(m.phong))) {
    const Vec3 kp = v3(m.phong);
    s.phong = kp.x;
    if (!isGrey(kp)) {
      s.phong = mean(kp);
      issues.warning(m.loc, fmt::format("{}: POV-Ray's phong is one number; the coloured phong "
                                        "{} becomes {}",
                                        name, colourText(m.phong), floatText(s.phong)));
    }
  }
  // `metallic` itself is its row's (scenegraph/finish_terms.cpp); what it cannot carry over is
  // said here, where the pigment is known.
  if (m.metallic && m.hasHighlight()) {
    if (filterOnly || isZero(kd))
      issues.warning(m.loc, fmt::format("{}: metallic without a diffuse colour: POV-Ray tints "
                                        "the highlights by its pigment, which here is not k_d",
                                        name));
    else if (isImage && !(isGrey(kd) && kd.x == 1.0))
      issues.warning(m.loc, fmt::format("{}: metallic with an image and diffuse {}: POV-Ray "
                                        "tints the highlights by the image alone",
                                        name, colourText(m.diffuse)));
  }
  // Reflection.
  s.reflection = kr;
  const bool transmits = !isZero(kt);
  if (m.reflectiveMin) s.reflectionMin = v3(*m.reflectiveMin);
  s.falloff = m.reflectFalloff;
  s.exponent = m.reflectExponent;
  s.conserveEnergy = m.conserveEnergy && transmits;
  if (m.fresnel && (transmits || !isZero(kr) || m.reflectiveMin)) {
    s.fresnel = true;
    if (transmits && m.fresnelTransmission) {
      // Lucent's k_t·(1 − F): POV-Ray's conserve_energy gives k_t·(1 − R), R the reflection
      // MIN + F·(MAX − MIN), which is 1 − F only for MIN 0 and MAX 1.
      const Vec3 lo = s.reflectionMin.value_or(Vec3(0.0));
      if (!(kr == Vec3(1.0) && lo == Vec3(0.0)) || m.conserveEnergy)
        issues.warning(m.loc,
                       fmt::format("{}: fresnel with reflective {}{}: POV-Ray reduces the "
                                   "transmission by 1 - R (conserve_energy, R its reflection), "
                                   "Lucent by 1 - F{} (fresnel-transmission=\"false\" with "
                                   "conserve-energy=\"true\" is POV-Ray's rule)",
                                   name, colourText(m.reflective),
                                   m.reflectiveMin ? " and reflective-min" : " (not 1)",
                                   m.conserveEnergy ? " and 1 - R" : ""));
      s.conserveEnergy = true;
    }
  }
  // Interior: index of refraction and absorption (a map's, where an entry transmits).
  const bool entryTransmits = m.mapped() && m.isTransmissive();
  if (transmits || s.fresnel || entryTransmits) {
    s.interior = true;
    s.ior = m.ior;
  }
  // Lucent's weight there is k_r + k_t (full-tir: 1, POV-Ray's).
  const Vec3 tirWeight = kr + kt;
  if (transmits && m.ior != 1.0 && !m.fullTir && !s.fresnel &&
      !(tirWeight.x == 1.0 && tirWeight.y == 1.0 && tirWeight.z == 1.0))
    issues.warning(m.loc, fmt::format("{}: under total internal reflection POV-Ray reflects "
                                      "with weight 1, Lucent with reflective + transmissive {} "
                                      "(full-tir=\"true\" is POV-Ray's rule)",
                                      name, colourText(m.reflective + m.transmissive)));
  if (transmits && !isZero(ka) && !m.innerAmbient)
    issues.warning(m.loc, fmt::format("{}: inside the object Lucent scales the ambient term by "
                                      "transmissive; POV-Ray does not",
                                      name));
  // fade-on-exit is POV-Ray's rule: nothing to say then.
  if (transmits && m.attenuates() && !m.fadeOnExit && !isZero(kr))
    issues.warning(m.loc, fmt::format("{}: POV-Ray does not attenuate light reflected inside "
                                      "an absorbing object (its fade applies to transmitted "
                                      "light only); Lucent does",
                                      name));
  // Found by the gallery (examples/gallery/absorption.xml): POV-Ray applies the interior
  // fade to the light passing out, not to the local terms at a hit inside the object, so a
  // highlight seen on the inside of the far wall keeps its full strength.
  if (transmits && m.attenuates() && !m.fadeOnExit && !isZero(ks))
    issues.warning(m.loc, fmt::format("{}: POV-Ray does not attenuate the highlights seen on "
                                      "the inside of an absorbing object; Lucent does",
                                      name));
  if ((transmits || entryTransmits) && m.hasFade()) {
    // POV-Ray's fade itself.
    s.fade = true;
    s.fadeDistance = m.fadeDistance;
    s.fadePower = m.fadePower;
    s.fadeColor = v3(m.fadeColor);
    if (m.isAbsorbing())
      issues.warning(m.loc, fmt::format("{}: absorption and a fade: POV-Ray's interior has one "
                                        "fade (the fade is written, the absorption left out)",
                                        name));
  } else if ((transmits || entryTransmits) && m.isAbsorbing()) {
    // exp(−(1 − fade_color)·d/fade_distance) = exp(−absorption·d) with fade_distance 1/max.
    Vec3 ab = v3(m.absorption);
    s.fade = true;
    s.fadeDistance = 1.0 / maxComponent(ab);
    s.fadeColor = Vec3(1.0) - ab * s.fadeDistance;
  }
  s.reflectMetallic = m.reflectMetallic;
  return s;
}

PovMaterials::PovMaterials(const std::vector<Material>& materials, PovIssues& issues)
    : materials_(materials),
      issues_(issues),
      surfaces_(materials.size()),
      layerSurfaces_(materials.size()) {
  for (size_t i = 0; i < materials.size(); ++i) {
    const Material& m = materials[i];
    std::string id = m.id == "(default)" ? "default" : m.id;
    names_.push_back(povIdentifier(fmt::format("M{}", i), id));
  }
}

const PovSurface& PovMaterials::surface(uint32_t material) const {
  std::optional<PovSurface>& s = surfaces_[material];
  if (!s) s = povSurface(materials_[material], issues_);
  return *s;
}

bool PovMaterials::anySpecular(const std::vector<bool>& used) const {
  for (uint32_t i = 0; i < surfaces_.size() && i < used.size(); ++i)
    if (used[i] && (surface(i).specular > 0.0 || surface(i).phong > 0.0)) return true;
  return false;
}

void PovMaterials::writeDeclarations(const std::vector<bool>& used, PovWriter& out) const {
  for (size_t i = 0; i < materials_.size(); ++i) {
    if (i >= used.size() || !used[i]) continue;
    const Material& m = materials_[i];
    out.line(fmt::format("// {}{}", materialLabel(m), m.loc.line > 0 ? " at " + m.loc.str() : ""));
    if (!dependsOnShape(static_cast<uint32_t>(i))) {
      out.open("#declare " + names_[i] + " = texture");
      writeTexture(static_cast<uint32_t>(i), nullptr, nullptr, nullptr, out, nullptr);
      out.close();
    }
    if (surface(static_cast<uint32_t>(i)).interior) {
      out.open("#declare I" + names_[i] + " = interior");
      writeInterior(surface(static_cast<uint32_t>(i)), out);
      out.close();
    }
  }
}

bool PovMaterials::usesImageMap(uint32_t index) const {
  return std::holds_alternative<ImageTexture>(materials_[index].texture) &&
         surface(index).useTexture;
}

namespace {

// Does any surface of the material (its own, a layer, a map's entry) show an image or a
// bump map?
bool showsImage(const Material& m) {
  if (std::holds_alternative<ImageTexture>(m.texture) || m.bumpMap) return true;
  for (const Material& layer : m.layers)
    if (showsImage(layer)) return true;
  for (const MaterialMapEntry& e : m.mapEntries)
    if (showsImage(e.material)) return true;
  return false;
}

}  // namespace

bool PovMaterials::dependsOnShape(uint32_t index) const {
  return usesImageMap(index) || showsImage(materials_[index]) || usesUvMapping(materials_[index]);
}

namespace {

// The material as POV-Ray must see it on a shape whose (u, v) run u the other way
// (ImageMapping::uvMirrored): every uv-mapped placement reads 1 - u, so POV-Ray's (u, v) land
// where Lucent's are (exactly but on the seam, which a pattern of period 1 in u hides).
Material mirroredInU(const Material& m) {
  Material out = m;
  Mat4 flip(1.0);
  flip[0][0] = -1.0;
  flip[3][0] = 1.0;
  auto mirror = [&](PatternPlacement* p) {
    if (p && p->uv) p->patternFromObject = p->patternFromObject * flip;
  };
  // The texture's placement and its entries' (a uv-mapped entry reads (u, v) itself).
  std::function<void(Texture&)> texture = [&](Texture& t) {
    auto entries = [&](std::vector<TextureMapEntry>& list) {
      for (TextureMapEntry& e : list) texture(e.texture);
    };
    if (auto* p = std::get_if<PatternTexture>(&t)) {
      mirror(&p->pattern.placement);
      entries(p->pigments);
    }
    auto blockPattern = [&](auto* b) {  // checker, hexagon, brick: a placement and a list
      if (!b) return;
      mirror(&b->placement);
      entries(b->pigments);
    };
    blockPattern(std::get_if<CheckerTexture>(&t));
    blockPattern(std::get_if<HexagonTexture>(&t));
    blockPattern(std::get_if<BrickTexture>(&t));
    if (auto* a = std::get_if<AverageTexture>(&t)) {
      mirror(&a->placement);
      entries(a->entries);
    }
    if (auto* i = std::get_if<ImageTexture>(&t); i && i->projection != ImageProjection::uv)
      mirror(&i->placement);
  };
  texture(out.texture);
  texture(out.mapPattern);
  if (out.normal) mirror(&out.normal->pattern.placement);
  if (out.bumpMap && out.bumpMap->projection != ImageProjection::uv)
    mirror(&out.bumpMap->placement);
  for (Material& layer : out.layers) layer = mirroredInU(layer);
  for (MaterialMapEntry& e : out.mapEntries) e.material = mirroredInU(e.material);
  return out;
}

// The image maps inside the texture's maps and lists: readable, projected, and not tinted
// (POV-Ray cannot multiply an image_map's colours, as it multiplies a colour's).
void checkImagesInMaps(const Texture& t, const Vec3& pigmentScale, const std::string& name,
                       PovIssues& issues) {
  forEachImageInMaps(t, [&](const ImageTexture& image) {
    if (!checkNestedImage(image, name, issues)) return;
    if (pigmentScale != Vec3(1.0))
      issues.error(image.loc, fmt::format("{}: an image map inside a map or a list of pigments "
                                          "of a material with a coloured diffuse, which POV-Ray "
                                          "cannot tint",
                                          name));
  });
}

// The mapping with its mirror taken: what is left for the material written through it.
ImageMapping unmirrored(const ImageMapping& mapping) {
  ImageMapping m = mapping;
  m.uvMirrored = false;
  return m;
}

}  // namespace

void PovMaterials::writeFor(uint32_t index, const ShapeSpec& shape, const SourceLoc& loc,
                            PovWriter& out, PovIssues& issues, bool interior) const {
  writeFor(index, shapeTypeOf(shape).povImageMapping(shape), shapeElementName(shape), loc, out,
           issues, interior);
}

void PovMaterials::writeInteriorFor(uint32_t index, PovWriter& out) const {
  if (surface(index).interior) out.line("interior { I" + names_[index] + " }");
  // POV-Ray's hollow is the object's, promoted to its interior.
  if (materials_[index].hollow) out.line("hollow");
}

void PovMaterials::writeFor(uint32_t index, const ImageMapping& mapping, const char* shapeName,
                            const SourceLoc& loc, PovWriter& out, PovIssues& issues,
                            bool interior) const {
  if (dependsOnShape(index)) {
    out.open("texture");
    writeTexture(index, &mapping, shapeName, &loc, out, &issues);
    out.close();
  } else {
    out.line("texture { " + names_[index] + " }");
  }
  if (interior) writeInteriorFor(index, out);
}

void PovMaterials::writeInteriorTexture(uint32_t index, const ShapeSpec& shape,
                                        const SourceLoc& loc, PovWriter& out,
                                        PovIssues& issues) const {
  writeInteriorTexture(index, shapeTypeOf(shape).povImageMapping(shape), shapeElementName(shape),
                       loc, out, issues);
}

void PovMaterials::writeInteriorTexture(uint32_t index, const ImageMapping& mapping,
                                        const char* shapeName, const SourceLoc& loc, PovWriter& out,
                                        PovIssues& issues) const {
  if (!dependsOnShape(index)) {
    out.line("interior_texture { " + names_[index] + " }");
    return;
  }
  out.open("interior_texture");
  writeTexture(index, &mapping, shapeName, &loc, out, &issues);
  out.close();
}

void PovMaterials::writeTexture(uint32_t index, const ImageMapping* mapping, const char* shapeName,
                                const SourceLoc* loc, PovWriter& out, PovIssues* issues) const {
  if (materials_[index].mapped()) {
    writeMap(materials_[index], mapping, shapeName, loc, out, issues);
    return;
  }
  writeLayer(materials_[index], surface(index), mapping, shapeName, loc, out, issues);
  // A layered material: each layer is a texture { } written after the one below it (the
  // caller opened the first and closes the last).
  const std::vector<PovSurface>& layers = layerSurfaces(index);
  for (size_t k = 0; k < layers.size(); ++k) {
    out.close();
    out.open("texture");
    writeLayer(materials_[index].layers[k], layers[k], mapping, shapeName, loc, out, issues);
  }
}

namespace {

// The entry as POV-Ray must see it: POV-Ray evaluates an entry's patterns at the point the
// map's pattern was evaluated at (in the map's pattern space), Lucent in the object's, so
// each of the entry's placements is taken from the map's space: P_entry·P_map⁻¹.
// A uv-mapped entry of a map that is not keeps its placement (POV-Ray's uv_mapping ignores
// the point it is given); in a uv-mapped map every entry must be uv-mapped (`mixed` if not),
// and is then evaluated at the map's point.
void intoMapSpace(Material& m, const Mat4& mapFromPattern, bool mapUv, bool& mixed) {
  auto move = [&](PatternPlacement* p) {
    if (!p || (p->uv && !mapUv)) return;
    if (mapUv && !p->uv) mixed = true;
    p->patternFromObject = p->patternFromObject * mapFromPattern;
    p->uv = false;
  };
  auto texture = [&](Texture& t) {
    if (auto* p = std::get_if<PatternTexture>(&t)) move(&p->pattern.placement);
    if (auto* c = std::get_if<CheckerTexture>(&t)) move(&c->placement);
    if (auto* h = std::get_if<HexagonTexture>(&t)) move(&h->placement);
    if (auto* b = std::get_if<BrickTexture>(&t)) move(&b->placement);
    if (auto* a = std::get_if<AverageTexture>(&t)) move(&a->placement);
  };
  texture(m.texture);
  if (m.normal) move(&m.normal->pattern.placement);
  for (Material& layer : m.layers) intoMapSpace(layer, mapFromPattern, mapUv, mixed);
  texture(m.mapPattern);
}

const PatternPlacement* mapPlacement(const Texture& t) {
  if (const auto* p = std::get_if<PatternTexture>(&t)) return &p->pattern.placement;
  if (const auto* c = std::get_if<CheckerTexture>(&t)) return &c->placement;
  if (const auto* h = std::get_if<HexagonTexture>(&t)) return &h->placement;
  if (const auto* b = std::get_if<BrickTexture>(&t)) return &b->placement;
  if (const auto* a = std::get_if<AverageTexture>(&t)) return &a->placement;
  return nullptr;
}

}  // namespace

// A uv-mapped normal on a shape export-pov writes mirrored (POV-Ray's u runs the other way,
// so the bent normal would be mirrored too) is an export error.
void refuseMirroredUvNormal(const Material& m, const ImageMapping* mapping, const char* shapeName,
                            const SourceLoc* loc, PovIssues& issues) {
  if (!mapping || !mapping->uvMirrored || !m.normal || !m.normal->pattern.placement.uv) return;
  issues.error(loc ? *loc : m.loc,
               fmt::format("{}: a uv-mapped normal on <{}>: the shape is written mirrored, so "
                           "POV-Ray's u runs the other way and its bent normal would be "
                           "mirrored too",
                           materialLabel(m), shapeName ? shapeName : "shape"));
}

// A material map: POV-Ray's texture_map of a pattern, or a block pattern's list of textures
// (its cells 0, 1, 2 each showing the entry the map gives that value alone).
void PovMaterials::writeMap(const Material& m, const ImageMapping* mapping, const char* shapeName,
                            const SourceLoc* loc, PovWriter& out, PovIssues* issues) const {
  refuseMirroredUvNormal(m, mapping, shapeName, loc, issues ? *issues : issues_);
  if (mapping && mapping->uvMirrored && usesUvMapping(m)) {
    const ImageMapping plain = unmirrored(*mapping);
    writeMap(mirroredInU(m), &plain, shapeName, loc, out, issues);
    return;
  }
  PovIssues& report = issues ? *issues : issues_;
  const PatternPlacement* place = mapPlacement(m.mapPattern);
  // Both hand the entries the map's warped point (render/map_entries.h): Lucent's entries
  // are placed from the object, composed with the map's linear placement, POV-Ray's from
  // the map's pattern space.
  const Mat4 mapFromPattern = place ? glm::inverse(linearPatternFromObject(*place)) : Mat4(1.0);
  const bool moved = place && (!place->warps.empty() || place->turbulence != Vec3(0.0));
  if (place && place->uv && moved)
    report.warning(m.loc, materialLabel(m) +
                              ": a uv-mapped map with warps or turbulence: POV-Ray evaluates "
                              "its entries at the warped (u, v) point, Lucent at (u, v)");
  // The entries as POV-Ray sees them, and the layered ones declared first: a texture_map
  // entry is a texture's body, which cannot hold layers unless it names a declared texture.
  std::vector<Material> entries;
  std::vector<std::string> declared(m.mapEntries.size());
  const bool uv = place && place->uv;
  bool mixed = false;
  for (size_t k = 0; k < m.mapEntries.size(); ++k) {
    entries.push_back(m.mapEntries[k].material);
    intoMapSpace(entries.back(), mapFromPattern, uv, mixed);
    const Material& entry = entries.back();
    if (entry.mapped() || !entry.layered()) continue;
    declared[k] = fmt::format("LucentLayers{}", layeredEntries_++);
    out.open("#declare " + declared[k] + " = texture");
    writeLayer(entry, povSurface(entry, report), mapping, shapeName, loc, out, issues);
    for (const Material& layer : entry.layers) {
      out.close();
      out.open("texture");
      writeLayer(layer, povSurface(layer, report), mapping, shapeName, loc, out, issues);
    }
    out.close();
  }
  // An entry's texture body: a declared layered texture's name, a map, or one layer.
  auto entryBody = [&](size_t k) {
    const Material& entry = entries[k];
    if (!declared[k].empty()) out.line(declared[k]);
    else if (entry.mapped()) writeMap(entry, mapping, shapeName, loc, out, issues);
    else writeLayer(entry, povSurface(entry, report), mapping, shapeName, loc, out, issues);
  };
  if (mixed)
    report.error(m.loc, materialLabel(m) +
                            ": the map is mapped at (u,v) and an entry is not, which POV-Ray "
                            "cannot write (it evaluates every entry at the map's point)");
  // The rest of the texture is the map POV-Ray evaluates at (u, v, 0).
  if (uv) out.line("uv_mapping");
  // The entries' values (an average's weights) and textures.
  auto textureMap = [&] {
    out.open("texture_map");
    for (size_t k = 0; k < entries.size(); ++k) {
      out.line("[" + povNumber(m.mapEntries[k].at));
      entryBody(k);
      out.line("]");
    }
    out.close();
  };
  if (const auto* a = std::get_if<AverageTexture>(&m.mapPattern)) {
    out.line(std::string(AverageTexture::kind.pov));
    textureMap();
    writePlacement(a->placement, out);
    return;
  }
  if (const ImagePattern* image = mapIndexImage(m)) {
    // POV-Ray's material_map: the k-th texture where the image gives number k; only
    // transforms follow it (Parse_Texture_Transform).
    const PatternSpec& spec = std::get<PatternTexture>(m.mapPattern).pattern;
    if (!spec.placement.warps.empty() || spec.placement.turbulence != Vec3(0.0))
      report.error(m.loc, materialLabel(m) +
                              ": a material map read by index with warps or turbulence, which "
                              "POV-Ray's material_map does not take");
    out.open("material_map");
    out.line(imageReadingSpec(*image));
    for (size_t k = 0; k < entries.size(); ++k) {
      out.open("texture");
      entryBody(k);
      out.close();
    }
    out.close();
    writePlacement(spec.placement, out);
    return;
  }
  if (const auto* p = std::get_if<PatternTexture>(&m.mapPattern);
      p && p->pattern.type == PatternType::object) {
    // `object { NAME texture {..} texture {..} }`: the first entry outside, the last inside.
    if (entries.size() > 2 && !objectPatternTwoValued(p->pattern))
      report.error(m.loc, materialLabel(m) +
                              ": an object pattern with a frequency or a wave and more than two "
                              "entries, which POV-Ray's list of two textures cannot write");
    out.open("object");
    out.line(p->pattern.object ? povObjectPatternName(*p->pattern.object) : "sphere { 0, 0 }");
    for (size_t k : {size_t(0), entries.size() - 1}) {
      out.open("texture");
      entryBody(k);
      out.close();
    }
    out.close();
    writeValueModifiers(p->pattern, out);
    writePlacement(p->pattern.placement, out);
    return;
  }
  if (const auto* p = std::get_if<PatternTexture>(&m.mapPattern)) {
    writePigmentFunctions(p->pattern, out);
    writePatternKeyword(p->pattern, out);
    textureMap();
    writeValueModifiers(p->pattern, out);
    writePlacement(p->pattern.placement, out);
    return;
  }
  // A block pattern: each cell the entry its value picks (a blend there cannot be written).
  int cells = 2;
  if (std::holds_alternative<CheckerTexture>(m.mapPattern)) {
    out.line("checker");
  } else if (std::holds_alternative<HexagonTexture>(m.mapPattern)) {
    out.line("hexagon");
    cells = 3;
  } else {
    out.line("brick");
  }
  for (int cell = 0; cell < cells; ++cell) {
    const MapBlend blend = mapBlend(m.mapEntries, cell);
    if (blend.a != blend.b && blend.wb > 0.0f)
      report.error(m.loc, materialLabel(m) + fmt::format(": the map blends two entries in cell "
                                                         "{} of its block pattern, which POV-Ray's "
                                                         "list of textures cannot",
                                                         cell));
    out.open("texture");
    entryBody(blend.a);
    out.close();
  }
  if (const auto* c = std::get_if<CheckerTexture>(&m.mapPattern)) {
    if (c->scale != 1.0) out.line("scale " + povNumber(c->scale));
    writePlacement(c->placement, out);
  } else if (const auto* h = std::get_if<HexagonTexture>(&m.mapPattern)) {
    writePlacement(h->placement, out);
  } else {
    const auto& b = std::get<BrickTexture>(m.mapPattern);
    out.line("brick_size " + povVector(b.spec.size) + " mortar " + povNumber(b.spec.mortar));
    writePlacement(b.placement, out);
  }
}

const std::vector<PovSurface>& PovMaterials::layerSurfaces(uint32_t material) const {
  std::optional<std::vector<PovSurface>>& layers = layerSurfaces_[material];
  if (!layers) {
    layers.emplace();
    for (const Material& layer : materials_[material].layers)
      layers->push_back(povSurface(layer, issues_));
  }
  return *layers;
}

void PovMaterials::writeLayer(const Material& m, const PovSurface& s, const ImageMapping* mapping,
                              const char* shapeName, const SourceLoc* loc, PovWriter& out,
                              PovIssues* issues) const {
  refuseMirroredUvNormal(m, mapping, shapeName, loc, issues ? *issues : issues_);
  if (mapping && mapping->uvMirrored && usesUvMapping(m)) {
    const ImageMapping plain = unmirrored(*mapping);
    writeLayer(mirroredInU(m), s, &plain, shapeName, loc, out, issues);
    return;
  }
  // The pigment of each kind of texture (std::visit needs every kind); a material whose
  // texture POV-Ray cannot show (useTexture false, an image without a mapping) gets its
  // plain colour.
  auto plain = [&] {
    out.line("pigment { " + povRgbft(s.pigmentScale, s.filter, s.transmit) + " }");
  };
  auto pigment = Overloaded{
      [&](std::monostate) { plain(); },
      [&](const CheckerTexture& checker) {
        writeCheckerPigment(checker, s.pigmentScale, s.filter, s.transmit, out);
      },
      [&](const ImageTexture& image) {
        if (image.projection != ImageProjection::uv && issues)
          return writeProjectedImagePigment(image, s.filter, s.transmit, materialLabel(m), out,
                                            *issues);
        if (!mapping) return plain();
        writeImagePigment(image, s.filter, s.transmit, *mapping, shapeName, *loc, materialLabel(m),
                          out, *issues);
      },
      [&](const PatternTexture& pattern) {
        writePatternPigment(pattern, s.pigmentScale, s.filter, s.transmit, out);
      },
      [&](const HexagonTexture& hexagon) {
        writeHexagonPigment(hexagon, s.pigmentScale, s.filter, s.transmit, out);
      },
      [&](const BrickTexture& brick) {
        writeBrickPigment(brick, s.pigmentScale, s.filter, s.transmit, out);
      },
      [&](const AverageTexture& average) {
        writeAveragePigment(average, s.pigmentScale, s.filter, s.transmit, out);
      },
  };
  // A normal bent in the object space at (u, v): POV-Ray's texture { uv_mapping ... }, which
  // bends the normal in the space of the transforms after the texture (the object's, written
  // after it) and reads the pigment at (u, v) too.
  if (m.normal && m.normal->pattern.placement.uv && !m.normal->bendInWorld) {
    if (s.useTexture && !std::holds_alternative<std::monostate>(m.texture) &&
        !textureUvMapped(m.texture))
      (issues ? *issues : issues_)
          .error(loc ? *loc : m.loc,
                 fmt::format("{}: a normal bent in the object space at (u, v) beside a texture "
                             "not read at (u, v): POV-Ray's texture {{ uv_mapping }} reads both "
                             "there",
                             materialLabel(m)));
    out.line("uv_mapping");
  }
  if (s.useTexture && !std::holds_alternative<ImageTexture>(m.texture))
    checkImagesInMaps(m.texture, s.pigmentScale, materialLabel(m), issues ? *issues : issues_);
  if (s.useTexture) std::visit(pigment, m.texture);
  else plain();
  if (m.normal) writeNormal(*m.normal, out);
  if (m.bumpMap && m.bumpMap->projection != ImageProjection::uv && issues)
    writeProjectedBumpMapNormal(*m.bumpMap, materialLabel(m), out, *issues);
  else if (m.bumpMap && mapping)
    writeBumpMapNormal(*m.bumpMap, *mapping, shapeName, *loc, materialLabel(m), out, *issues);

  out.open("finish");
  out.line("ambient " + povRgb(s.ambient));
  out.line("emission " + povRgb(s.emission));
  out.line("diffuse " + povFloat(s.diffuse));
  if (s.crand > 0.0) out.line("crand " + povFloat(s.crand));
  out.line("phong " + povFloat(s.phong));
  out.line("specular " + povFloat(s.specular));
  const std::string metallic =
      s.reflectMetallic > 0.0 ? " metallic " + povNumber(s.reflectMetallic) : "";
  // The minimum: 0 with fresnel when none is given (POV-Ray's own default there), else k_r.
  const Vec3 lo = s.reflectionMin.value_or(s.fresnel ? Vec3(0.0) : s.reflection);
  std::string options = s.fresnel ? " fresnel on" : "";
  if (!s.fresnel && s.falloff != 1.0) options += " falloff " + povNumber(s.falloff);
  if (s.exponent != 1.0) options += " exponent " + povNumber(s.exponent);
  if (s.fresnel || lo != s.reflection)
    out.line("reflection { " + povRgb(lo) + ", " + povRgb(s.reflection) + options + metallic +
             " }");
  else out.line("reflection { " + povRgb(s.reflection) + options + metallic + " }");
  if (s.conserveEnergy) out.line("conserve_energy");
  // The terms POV-Ray has as they are, each written by its row of the finish table.
  FinishLines finishLines(out);
  for (const FinishTerm& t : finishTerms())
    if (t.writePov) t.writePov(m, finishLines);
  out.close();
}

void PovMaterials::writeInterior(const PovSurface& s, PovWriter& out) const {
  out.line("ior " + povNumber(s.ior));
  if (s.fade) {
    // fade_power >= 1000 selects POV-Ray's exponential fade (absorption's).
    out.line("fade_power " + povNumber(s.fadePower));
    out.line("fade_distance " + povNumber(s.fadeDistance));
    out.line("fade_color " + povRgb(s.fadeColor));
  }
}

}  // namespace lucent
