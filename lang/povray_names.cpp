#include "povray_names.h"

#include "element_parsers.h"

#include "scenegraph/finish_terms.h"

#include <vector>

namespace lucent {

namespace {

struct PovWord {
  std::string_view where;   // the Lucent element it was written on or in; "" anywhere
  std::string_view povray;  // POV-Ray's word
  std::string_view lucent;  // what Lucent says instead, as it reads in the hint
};

constexpr std::string_view kOnShape = "";  // any element without an entry of its own

// POV-Ray's own spellings (its keywords use '_', Lucent's attributes '-'). Those of the
// material's finish and interior terms are the finish table's (scenegraph/finish_terms.h).
const std::vector<PovWord> kAttributes{
    {"camera", "location", "'position'"},
    {"camera", "look_at", "'look-at'"},
    {"camera", "angle", "'fov'"},
    {"camera", "sky", "'up'"},
    {"camera", "direction", "'look-at' (the point looked at) and 'fov'"},
    {"camera", "right", "'fov-axis' and the image's width and height"},
    {"camera", "focal_point", "'focus-distance' (with type=\"thin-lens\")"},
    {"camera", "aperture", "'f-stop' (with type=\"thin-lens\")"},
    {"light", "location", "'position'"},
    {"light", "point_at", "'look-at'"},
    {"light", "falloff", "'angle' for a spot light"},
    {"light", "radius", "'inner' for a spot light"},
    {"light", "fade_distance", "'fade-distance'"},
    {"light", "fade_power", "'fade-power'"},
    {"light", "shadowless", "shadows=\"false\" highlights=\"false\""},
    {"light", "spotlight", "type=\"spot\""},
    {"light", "parallel", "type=\"directional\""},
    {"light", "area_light", "type=\"area\""},
    {"material", "pigment",
     "'diffuse' (a colour) or a <checker>, <image>, <pattern>, <hexagon> or <brick> child"},
    {"material", "finish",
     "the material's own attributes: 'ambient', 'diffuse', 'specular', 'phong', 'brilliance', "
     "'reflective'"},
    {"material", "normal", "a <normal type depth> or <bump-map src depth> child"},
    {"material", "bump_map", "a <bump-map src depth> child"},
    {"material", "interior", "the material's 'ior', 'absorption' and 'fade-distance'"},
    {"fog", "fog_type", "type=\"ground\" (fog_type 2) or the default constant fog (fog_type 1)"},
    {"fog", "fog_offset", "'offset'"},
    {"fog", "fog_alt", "'altitude'"},
    {"fog", "colour", "'color'"},
    {"render", "max_trace_level", "'max-depth'"},
    {"render", "adc_bailout", "'min-weight'"},
    {"render", "antialias", "'samples'"},
    {"render", "ambient_light", "'ambient'"},
    {kOnShape, "pigment", "a <material> child or material=\"id\""},
    {kOnShape, "texture", "a <material> child or material=\"id\""},
    {kOnShape, "finish", "a <material> child or material=\"id\""},
    {kOnShape, "color", "a <material> child or material=\"id\""},
    {kOnShape, "colour", "a <material> child or material=\"id\""},
    {kOnShape, "normal", "a <normal> inside the <material>"},
    {"pattern", "color_map", "a <color-map> child"},
    {"pattern", "noise_generator", "'noise-generator'"},
    {"normal", "bump_size", "'depth'"},
    {"normal", "noise_generator", "'noise-generator'"},
    {"bump-map", "bump_size", "'depth'"},
    {"brick", "brick_size", "'size'"},
    {kOnShape, "no_shadow", "shadows=\"false\""},
    {kOnShape, "no_image", "image=\"false\""},
    {kOnShape, "no_reflection", "reflection=\"false\""},
    {kOnShape, "double_illuminate", "double-illuminate=\"true\""},
    {kOnShape, "interior_texture", "interior-material=\"id\""},
    {kOnShape, "translate", "transform=\"translate(x y z)\""},
    {kOnShape, "rotate", "transform=\"rotate-x(degrees) ...\""},
    {kOnShape, "scale", "transform=\"scale(s)\""},
    {kOnShape, "matrix", "transform=\"matrix(...)\""},
};

const std::vector<PovWord> kElements{
    {"scene", "light_source", "<light>"},
    {"scene", "global_settings", "<render>"},
    {"scene", "background", "<render background=\"r g b\">"},
    {"scene", "object", "<use ref=\"id\">"},
    {"scene", "declare", "<defs> (named nodes) or <param> (values)"},
    {"scene", "texture", "<material id=\"...\">"},
    {"scene", "pigment", "<material id=\"...\">"},
    {"scene", "finish", "<material id=\"...\">"},
    {"scene", "mesh2", "<mesh>"},
    {"scene", "sky_sphere", "<sky>"},
    {"material", "pigment",
     "the 'diffuse' colour or a <checker>, <image>, <pattern>, <hexagon> or <brick> child"},
    {"material", "finish",
     "the material's own attributes: 'ambient', 'diffuse', 'specular', 'phong', 'brilliance', "
     "'reflective'"},
    {"material", "interior", "the material's 'ior', 'absorption' and 'fade-distance'"},
    {"pattern", "color_map", "<color-map>"},
    {"pattern", "colour_map", "<color-map>"},
    {"color-map", "entry", "<entry at color>"},
    {"material", "bump_map", "<bump-map src depth>"},
    {"normal", "bump_map", "<bump-map src depth> in the <material> instead of the <normal>"},
    {kOnShape, "normal", "<normal> inside the <material>"},
    {kOnShape, "texture", "<material>"},
    {kOnShape, "pigment", "<material>"},
    {kOnShape, "finish", "<material>"},
    {kOnShape, "light_source", "<light>"},
};

std::string hint(std::string_view word, std::string_view lucent) {
  if (lucent.rfind("no equivalent", 0) == 0)
    return " (POV-Ray's '" + std::string(word) + "' has " + std::string(lucent) + ")";
  return " (POV-Ray's '" + std::string(word) + "' is " + std::string(lucent) + " in Lucent)";
}

std::string lookup(const std::vector<PovWord>& table, std::string_view where,
                   std::string_view word) {
  const PovWord* generic = nullptr;
  for (const PovWord& w : table) {
    if (w.povray != word) continue;
    if (w.where == where) return hint(word, w.lucent);
    if (w.where == kOnShape && !generic) generic = &w;
  }
  // The generic words are for shapes and groups, not for elements that have their own.
  if (!generic || !isGeometryElement(where)) return {};
  return hint(word, generic->lucent);
}

}  // namespace

std::string povrayAttributeHint(std::string_view element, std::string_view attribute) {
  if (element == "material" || element == "layer")
    for (const FinishTerm& t : finishTerms())
      for (const PovHint& h : t.povHints)
        if (h.word == attribute)
          return hint(attribute,
                      "'" + t.info.name + "'" + (h.note.empty() ? "" : " " + std::string(h.note)));
  return lookup(kAttributes, element, attribute);
}

std::string povrayElementHint(std::string_view parent, std::string_view child) {
  return lookup(kElements, parent, child);
}

}  // namespace lucent
