// <material> (contract, "<material>"): all attributes optional, colours default to 0,
// shininess 64, ior 1. The finish and interior terms are read through their rows of the
// finish table (scenegraph/finish_terms.h); this file keeps the rest. One texture child at
// most (texture_parser.h); with a texture, diffuse defaults to 1 so the texture shows as it
// is. base="id" starts from another material and overrides what is written; default="true"
// makes a named material the one of shapes that have none.
#include "element_input.h"
#include "element_parsers.h"
#include "pattern_parser.h"
#include "pov_library.h"
#include "povray_names.h"
#include "texture_parser.h"

#include "scenegraph/finish_terms.h"
#include "scenegraph/map_blend.h"

#include <algorithm>
#include <functional>

namespace lucent {

namespace {

// id, the finish table's terms (scenegraph/finish_terms.h), base and default.
std::vector<std::string_view> materialAttributes() {
  std::vector<std::string_view> names{"id"};
  for (const FinishTerm& t : finishTerms()) names.push_back(t.info.name);
  names.push_back("base");
  names.push_back("default");
  return names;
}
// The texture elements (the table of texture kinds), then the normal perturbations.
std::vector<std::string_view> materialChildren() {
  std::vector<std::string_view> names = textureElements();
  names.insert(names.end(), {"normal", "bump-map", "layer", "material-map"});
  return names;
}

// Finds the material an attribute (base=, an entry's material=) names, reading it first when
// it comes later in the file.
using BaseResolver = std::function<std::optional<uint32_t>(ElementReader&, const char* attr)>;

// `resolve` null: a <layer>'s children (no layers, no map).
void readSurfaceChildren(ElementReader& r, Material& m, const BaseResolver* resolve);

// <layer>: a layer of POV-Ray's layered texture over its material (docs/scene-language.md,
// "Layers"): the surface terms of the finish table, a texture and a normal perturbation.
std::vector<std::string_view> layerAttributes() {
  std::vector<std::string_view> names;
  for (const FinishTerm& t : finishTerms())
    if (!t.ofInterior) names.push_back(t.info.name);
  return names;
}

Material parseLayer(ElementReader& r) {
  for (const FinishTerm& t : finishTerms())
    if (t.ofInterior && r.has(t.info.name.c_str()))
      r.attrError(t.info.name.c_str(),
                  "a term of the whole material (its interior), not of one layer: write it on "
                  "the <material>");
  static const std::vector<std::string_view> attributes = [] {
    std::vector<std::string_view> names = layerAttributes();
    for (const FinishTerm& t : finishTerms())
      if (t.ofInterior) names.push_back(t.info.name);  // reported above
    return names;
  }();
  r.checkAttributes(attributes);
  Material layer;
  layer.loc = r.loc();
  ElementInput in(r);
  for (const FinishTerm& t : finishTerms())
    if (!t.ofInterior) t.read(layer, in);
  readSurfaceChildren(r, layer, nullptr);
  if (layer.hasTexture() && !r.has("diffuse")) layer.diffuse = Color(1.0f);
  return layer;
}

// The children of a <material> (layers allowed) or a <layer>: one texture, one normal
// perturbation, and for a material its <layer>s, each over the ones before.
// The <average> of a <material-map>: its placement (attributes and <warp>s) only, the
// map's entries being what it averages.
Texture parseMapAverage(ElementReader& t) {
  t.checkAttributes(placementAttributes());
  AverageTexture a;
  a.placement = parsePlacement(t);
  t.forEachChild([&](pugi::xml_node c) {
    if (std::string_view(c.name()) == "warp") return;
    ElementReader(t.ctx(), t.file(), c)
        .error(
            "the <average> of a <material-map> holds only <warp>s: the map's <entry weight>s "
            "are what it averages");
  });
  return a;
}

// An <entry>'s place in its map: its `at` (ascending), an average's `weight`, or under an
// image read by index its number, the count of entries before it.
double entryPlace(ElementReader& t, const Material& m) {
  if (mapIndexImage(m)) {
    // Entry k shows where the image gives material number k (POV-Ray's material_map).
    if (t.has("at") || t.has("weight"))
      t.error(
          "the <entry>s of a <material-map> read by index take no 'at' or 'weight': the k-th "
          "entry (from 0) shows where the image's index is k");
    t.checkAttributes({"at", "weight", "material"});
    return static_cast<double>(m.mapEntries.size());
  }
  if (mapAverages(m)) {
    t.checkAttributes({"weight", "material"});
    if (!t.has("weight"))
      t.error("an <entry> of an averaged <material-map> needs a 'weight' (a positive number)");
    return t.number("weight", 1.0, NumberRule::positive());
  }
  t.checkAttributes({"at", "material"});
  if (!t.has("at")) t.error("<entry> needs the attribute 'at' (the pattern's value it sits at)");
  const double at = t.number("at", 0.0);
  if (!m.mapEntries.empty() && at < m.mapEntries.back().at)
    t.attrError("at", "the entries of a <material-map> must be in ascending order of 'at'");
  return at;
}

// <material-map>: its pattern first (a <pattern> without colour map, or a <checker>,
// <hexagon> or <brick>, whose colours are not used, or an <average>), then its
// <entry at material>s or <entry at><material/></entry>s, in ascending order of `at`
// (an average's entries take a `weight` instead, in any order; those of an image-pattern
// read by index neither, their order giving their numbers).
void parseMaterialMap(ElementReader& r, Material& m, const BaseResolver& resolve) {
  r.checkAttributes({});
  ParseContext& ctx = r.ctx();
  bool havePattern = false;
  m.mapPattern = std::monostate{};
  m.mapEntries.clear();
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader t(ctx, r.file(), n);
    std::string_view name = n.name();
    const std::vector<std::string_view> textures = textureElements();
    if (name != "entry") {
      if (std::find(textures.begin(), textures.end(), name) == textures.end() || name == "image") {
        t.error(
            "<material-map> holds its pattern (<pattern>, <checker>, <hexagon>, <brick> or "
            "<average>) and <entry>s, not <" +
            std::string(name) + ">");
        return;
      }
      if (havePattern) {
        t.error("<material-map> has one pattern, its first child");
        return;
      }
      havePattern = true;
      ctx.mapPatternElement = n;
      m.mapPattern = name == "average" ? parseMapAverage(t) : parseTexture(t);
      ctx.mapPatternElement = pugi::xml_node();
      if (const auto* p = std::get_if<PatternTexture>(&m.mapPattern);
          p && (!p->map.entries.empty() || !p->pigments.empty()))
        t.error(
            "a <material-map>'s <pattern> has no <color-map> or <pigment-map>: its value "
            "picks the entries");
      return;
    }
    if (!havePattern) {
      t.error(
          "a <material-map> starts with its pattern (<pattern>, <checker>, <hexagon>, <brick> "
          "or <average>), before its <entry>s");
      return;
    }
    MaterialMapEntry entry;
    entry.at = entryPlace(t, m);
    std::optional<uint32_t> index;
    if (t.has("material")) index = resolve(t, "material");
    bool inline_ = false;
    t.forEachChild([&](pugi::xml_node c) {
      ElementReader e(ctx, r.file(), c);
      if (std::string_view(c.name()) != "material" || inline_ || t.has("material")) {
        e.error("an <entry> holds one inline <material>, or names one with material=\"id\"");
        return;
      }
      inline_ = true;
      index = parseInlineMaterial(e);
    });
    if (!t.has("material") && !inline_)
      t.error("an <entry> needs a material: material=\"id\" or an inline <material>");
    if (index) entry.material = ctx.scene.materials[*index];
    entry.material.id.clear();
    m.mapEntries.push_back(std::move(entry));
  });
  if (!havePattern) r.error("a <material-map> needs its pattern and at least one <entry>");
  else if (m.mapEntries.empty()) r.error("a <material-map> needs at least one <entry>");
}

void readSurfaceChildren(ElementReader& r, Material& m, const BaseResolver* resolve) {
  ParseContext& ctx = r.ctx();
  const bool isMaterial = resolve != nullptr;
  const char* element = isMaterial ? "<material>" : "<layer>";
  std::optional<SourceLoc> textureLoc, normalLoc, mapLoc;
  bool ownLayers = false;
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader t(ctx, r.file(), n);
    std::string_view name = n.name();
    if (name == "material-map" && isMaterial) {
      if (mapLoc) {
        t.error("<material> holds one <material-map> at most; the first is at " + mapLoc->str());
        return;
      }
      mapLoc = t.loc();
      parseMaterialMap(t, m, *resolve);
      return;
    }
    if (name == "layer" && isMaterial) {
      if (!ownLayers) m.layers.clear();  // the base's layers are replaced
      ownLayers = true;
      m.layers.push_back(parseLayer(t));
      return;
    }
    if (name == "normal" || name == "bump-map") {
      if (normalLoc) {
        t.error(std::string(element) +
                " holds one normal perturbation (<normal> or <bump-map>) at most; the first "
                "is at " +
                normalLoc->str());
        return;
      }
      normalLoc = t.loc();
      // Either replaces the base's normal perturbation, whichever kind that was.
      m.normal.reset();
      m.bumpMap.reset();
      if (name == "normal") m.normal = parseNormal(t);
      else m.bumpMap = parseBumpMap(t);
      return;
    }
    const std::vector<std::string_view> textures = textureElements();
    if (std::find(textures.begin(), textures.end(), name) == textures.end()) {
      std::vector<std::string_view> children = materialChildren();
      if (!isMaterial) children.resize(children.size() - 2);  // no <layer>, no map
      std::string pov = povrayElementHint("material", name);
      t.error(std::string(element) + " may hold a texture (" + elementList(textures) +
              "), a <normal> or <bump-map>" +
              (isMaterial ? ", <layer>s and a <material-map>" : "") + ", not <" +
              std::string(name) + ">" + (pov.empty() ? didYouMean(name, children) : pov));
      return;
    }
    if (textureLoc) {
      t.error(std::string(element) + " holds one texture at most; the first is at " +
              textureLoc->str());
      return;
    }
    textureLoc = t.loc();
    m.texture = parseTexture(t);
  });
  if (mapLoc && (textureLoc || normalLoc || ownLayers))
    r.error(
        "a <material> with a <material-map> has no texture, normal or <layer> of its own: "
        "its entries are its surfaces");
  if (mapLoc) {
    m.texture = std::monostate{};
    m.normal.reset();
    m.bumpMap.reset();
    m.layers.clear();
  } else if (textureLoc || normalLoc || ownLayers) {
    m.mapEntries.clear();  // the base's map is replaced by a surface of its own
    m.mapPattern = std::monostate{};
  }
}

bool isPovName(std::string_view id) { return id.rfind(kPovPrefix, 0) == 0; }

bool isPovLibraryFile(const SourceFile& f) {
  const PovLibrary* lib = povLibrary();
  return lib && &lib->file == &f;
}

std::optional<uint32_t> parseMaterial(ElementReader& r, bool topLevel, const BaseResolver& baseOf);

// `material="pov:NAME"` (or base=): the library's material, read into the scene on its first
// use and named by its id from then on.
std::optional<uint32_t> povMaterial(ElementReader& r, const char* attr, const std::string& id) {
  const PovLibrary* lib = povLibrary();
  if (!lib) {
    r.attrError(attr, "this program has no 'pov:' library (the lucent command has it)");
    return std::nullopt;
  }
  if (auto it = r.ctx().materialIds.find(id); it != r.ctx().materialIds.end()) return it->second;
  auto it = lib->materials.find(id);
  if (it == lib->materials.end()) {
    std::string what = lib->colours.count(id) ? " ('" + id + "' is a colour: diffuse=\"" + id +
                                                    "\" or color=\"" + id + "\" take it)"
                                              : didYouMean(id, lib->materialNames);
    r.attrError(attr, "POV-Ray's library has no texture, pigment or material '" +
                          id.substr(kPovPrefix.size()) + "'" + what);
    return std::nullopt;
  }
  ElementReader library(r.ctx(), lib->file, it->second);
  return parseMaterial(library, true, [](ElementReader& e, const char* a) {
    e.attrError(a, "a material of the pov: library has no base");
    return std::optional<uint32_t>{};
  });
}

std::optional<uint32_t> parseMaterial(ElementReader& r, bool topLevel, const BaseResolver& baseOf) {
  static const std::vector<std::string_view> attributes = materialAttributes();
  r.checkAttributes(attributes);
  ParseContext& ctx = r.ctx();
  Material m;
  bool wroteDiffuse = false;
  if (r.has("base")) {
    if (std::optional<uint32_t> base = baseOf(r, "base")) {
      m = ctx.scene.materials[*base];
      wroteDiffuse = ctx.materialsWithDiffuse.count(*base) > 0;
    }
  }
  m.id.clear();
  m.loc = r.loc();
  if (topLevel) {
    if (!r.has("id")) r.error("a top-level <material> needs an 'id' so that shapes can name it");
    else if (auto id = r.text("id")) {
      if (!isValidId(*id))
        r.attrError("id", "an id must be non-empty and contain no spaces, got '" + *id + "'");
      else if (isPovName(*id) && !isPovLibraryFile(r.file()))
        r.attrError("id", "'pov:' names POV-Ray's library (material=\"" + *id +
                              "\" uses it); give your material an id of its own");
      else m.id = *id;
    }
  } else if (r.has("id")) {
    r.attrError(
        "id", "an inline <material> has no id; declare it at the top level of <scene> to share it");
  }
  const bool isDefault = r.boolean("default", false);
  if (!topLevel && r.has("default"))
    r.attrError("default", "only a top-level <material> with an id can be the default material");

  // The finish and interior terms, each by its row of the finish table.
  ElementInput in(r);
  for (const FinishTerm& t : finishTerms()) t.read(m, in);
  wroteDiffuse = wroteDiffuse || r.has("diffuse");

  // A texture (or normal) of its own replaces the base's; layers of its own replace the
  // base's layers.
  readSurfaceChildren(r, m, &baseOf);
  // The contract: with a texture and no diffuse, the texture shows as it is.
  if (m.hasTexture() && !wroteDiffuse) m.diffuse = Color(1.0f);

  if (topLevel && !m.id.empty()) {
    auto [it, inserted] = ctx.materialIds.try_emplace(m.id, 0);
    if (!inserted) {
      r.error("material '" + m.id + "' is already defined (first defined at " +
              ctx.scene.materials[it->second].loc.str() + ")");
      return std::nullopt;
    }
    it->second = static_cast<uint32_t>(ctx.scene.materials.size());
  }
  if (isDefault && topLevel) {
    if (ctx.defaultMaterialLoc) {
      r.attrError("default", "there is already a default material (at " +
                                 ctx.defaultMaterialLoc->str() + "); at most one may be");
    } else {
      ctx.defaultMaterialLoc = m.loc;
      // Index 0 is what a shape without any material gets.
      ctx.scene.materials[0] = m;
    }
  }
  const auto index = static_cast<uint32_t>(ctx.scene.materials.size());
  if (wroteDiffuse) ctx.materialsWithDiffuse.insert(index);
  ctx.scene.materials.push_back(std::move(m));
  return index;
}

}  // namespace

std::optional<uint32_t> parseInlineMaterial(ElementReader& r) {
  // Every named material is read by now.
  return parseMaterial(r, false,
                       [](ElementReader& e, const char* attr) { return lookupMaterial(e, attr); });
}

void parseNamedMaterials(ParseContext& ctx, const std::vector<TopLevelItem>& items) {
  // The <material>s, and the first one of each id as written (for forward bases).
  std::vector<const TopLevelItem*> materials;
  std::unordered_map<std::string, size_t> byId;
  for (const TopLevelItem& item : items) {
    if (std::string_view(item.element.name()) != "material") continue;
    byId.try_emplace(item.element.attribute("id").value(), materials.size());
    materials.push_back(&item);
  }
  enum class State { unread, reading, read };
  std::vector<State> state(materials.size(), State::unread);
  std::vector<std::optional<uint32_t>> index(materials.size());
  std::vector<size_t> chain;  // the materials being read, outermost first

  std::function<void(size_t)> read = [&](size_t i) {
    state[i] = State::reading;
    chain.push_back(i);
    ElementReader r(ctx, *materials[i]->file, materials[i]->element);
    index[i] =
        parseMaterial(r, true, [&](ElementReader& e, const char* attr) -> std::optional<uint32_t> {
          auto id = e.text(attr);
          if (!id) return std::nullopt;
          auto it = byId.find(*id);
          if (it == byId.end() && isPovName(*id)) return povMaterial(e, attr, *id);
          if (it == byId.end()) {
            std::vector<std::string_view> names;
            for (const auto& [name, k] : byId) names.push_back(name);
            std::sort(names.begin(), names.end());  // a stable hint whatever the hash order
            e.attrError(attr, "no material has the id '" + *id + "'" + didYouMean(*id, names));
            return std::nullopt;
          }
          const size_t b = it->second;
          if (state[b] == State::reading) {
            std::string cycle;
            for (size_t k = std::find(chain.begin(), chain.end(), b) - chain.begin();
                 k < chain.size(); ++k)
              cycle +=
                  "'" + std::string(materials[chain[k]]->element.attribute("id").value()) + "' -> ";
            e.attrError(attr,
                        "materials are based on each other in a cycle: " + cycle + "'" + *id + "'");
            return std::nullopt;
          }
          if (state[b] == State::unread) {
            if (chain.size() >= static_cast<size_t>(kMaxElementDepth)) {
              e.attrError(attr, "base= chains are longer than " + std::to_string(kMaxElementDepth) +
                                    " materials");
              return std::nullopt;
            }
            read(b);
          }
          return index[b];
        });
    chain.pop_back();
    state[i] = State::read;
  };
  for (size_t i = 0; i < materials.size(); ++i)
    if (state[i] == State::unread) read(i);
}

std::optional<uint32_t> lookupMaterial(ElementReader& r, const char* attr) {
  auto id = r.text(attr);
  if (!id) return std::nullopt;
  auto& ids = r.ctx().materialIds;
  if (auto it = ids.find(*id); it != ids.end()) return it->second;
  if (isPovName(*id)) return povMaterial(r, attr, *id);
  std::vector<std::string_view> names;
  names.reserve(ids.size());
  for (const auto& [name, index] : ids) names.push_back(name);
  std::sort(names.begin(), names.end());  // a stable hint whatever the hash order
  r.attrError(attr, "no material has the id '" + *id + "'" + didYouMean(*id, names));
  return std::nullopt;
}

bool isValidId(std::string_view id) {
  if (id.empty()) return false;
  for (char c : id)
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') return false;
  return true;
}

}  // namespace lucent
