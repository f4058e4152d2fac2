// <material> (contract, "<material>"): all attributes optional, colours default to 0,
// shininess 64, ior 1. One texture child at most: <checker color1 color2 scale> or
// <image src scale>; with a texture, diffuse defaults to 1 so the texture shows as it is.
#include "element_parsers.h"
#include "povray_names.h"

#include <algorithm>

namespace lucent {

namespace {

const std::vector<std::string_view> kMaterialAttributes{
    "id",       "emissive",   "ambient",      "diffuse", "specular", "shininess",
    "reflective", "transmissive", "ior",      "fresnel", "absorption", "phong",
    "phong-size", "brilliance", "metallic"};
const std::vector<std::string_view> kTextureElements{"checker", "image"};

Texture parseChecker(ElementReader& t) {
  t.checkAttributes({"color1", "color2", "scale"});
  CheckerTexture c;
  c.color1 = t.color("color1", c.color1);
  c.color2 = t.color("color2", c.color2);
  c.scale = t.number("scale", c.scale, NumberRule::positive());
  t.forEachChild([&](pugi::xml_node n) {
    ElementReader(t.ctx(), t.file(), n).error("<checker> takes no child elements, got <" +
                                                std::string(n.name()) + ">");
  });
  return c;
}

Texture parseImage(ElementReader& t) {
  t.checkAttributes({"src", "scale"});
  ImageTexture img;
  img.loc = t.loc();
  if (!t.has("src")) {
    t.error("<image> needs a 'src' attribute (the image file)");
  } else if (auto src = t.text("src")) {
    FileAccess::Resolved f = t.ctx().files.resolve(*src, t.file().folder());
    if (f.path.empty()) t.attrError("src", f.error);
    else img.path = f.path.string();
  }
  if (auto s = t.text("scale")) {
    auto list = parseNumberList(*s);
    if (!list) {
      t.attrError("scale", list.error);
    } else if (list->size() != 2 && list->size() != 1) {
      t.attrError("scale", "expected 2 numbers (u v) or 1, got " + std::to_string(list->size()));
    } else {
      Vec2 v = list->size() == 1 ? Vec2((*list)[0]) : Vec2((*list)[0], (*list)[1]);
      if (v.x == 0.0 || v.y == 0.0) t.attrError("scale", "the scale must not be zero, got '" + *s + "'");
      else img.scale = v;
    }
  }
  t.forEachChild([&](pugi::xml_node n) {
    ElementReader(t.ctx(), t.file(), n).error("<image> takes no child elements, got <" +
                                                std::string(n.name()) + ">");
  });
  return img;
}

std::optional<uint32_t> parseMaterial(ElementReader& r, bool topLevel) {
  r.checkAttributes(kMaterialAttributes);
  Material m;
  m.loc = r.loc();
  if (topLevel) {
    if (!r.has("id")) r.error("a top-level <material> needs an 'id' so that shapes can name it");
    else if (auto id = r.text("id")) {
      if (!isValidId(*id)) r.attrError("id", "an id must be non-empty and contain no spaces, got '" + *id + "'");
      else m.id = *id;
    }
  } else if (r.has("id")) {
    r.attrError("id", "an inline <material> has no id; declare it at the top level of <scene> to share it");
  }

  m.emissive = r.color("emissive", m.emissive);
  m.ambient = r.color("ambient", m.ambient, &m.ambientIsScalar);
  m.diffuse = r.color("diffuse", m.diffuse);
  m.specular = r.color("specular", m.specular);
  m.shininess = r.number("shininess", m.shininess, NumberRule::nonNegative());
  m.reflective = r.color("reflective", m.reflective);
  m.transmissive = r.color("transmissive", m.transmissive);
  m.ior = r.number("ior", m.ior, NumberRule::positive());
  m.fresnel = r.boolean("fresnel", m.fresnel);
  m.absorption = r.color("absorption", m.absorption);
  m.phong = r.color("phong", m.phong);
  m.phongSize = r.number("phong-size", m.phongSize, NumberRule::positive());
  m.brilliance = r.number("brilliance", m.brilliance, NumberRule::nonNegative());
  m.metallic = r.boolean("metallic", m.metallic);

  SourceLoc textureLoc;
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader t(r.ctx(), r.file(), n);
    std::string_view name = n.name();
    if (name != "checker" && name != "image") {
      std::string pov = povrayElementHint("material", name);
      t.error("<material> may hold a texture (" + elementList(kTextureElements) + "), not <" +
              std::string(name) + ">" + (pov.empty() ? didYouMean(name, kTextureElements) : pov));
      return;
    }
    if (m.hasTexture()) {
      t.error("<material> holds one texture at most; the first is at " + textureLoc.str());
      return;
    }
    textureLoc = t.loc();
    m.texture = name == "checker" ? parseChecker(t) : parseImage(t);
  });
  // The contract: with a texture and no diffuse, the texture shows as it is.
  if (m.hasTexture() && !r.has("diffuse")) m.diffuse = Color(1.0f);

  if (topLevel && !m.id.empty()) {
    auto [it, inserted] = r.ctx().materialIds.try_emplace(m.id, 0);
    if (!inserted) {
      r.error("material '" + m.id + "' is already defined (first defined at " +
              r.ctx().scene.materials[it->second].loc.str() + ")");
      return std::nullopt;
    }
    it->second = static_cast<uint32_t>(r.ctx().scene.materials.size());
  }
  r.ctx().scene.materials.push_back(std::move(m));
  return static_cast<uint32_t>(r.ctx().scene.materials.size() - 1);
}

}  // namespace

std::optional<uint32_t> parseNamedMaterial(ElementReader& r) { return parseMaterial(r, true); }
std::optional<uint32_t> parseInlineMaterial(ElementReader& r) { return parseMaterial(r, false); }

std::optional<uint32_t> lookupMaterial(ElementReader& r, const char* attr) {
  auto id = r.text(attr);
  if (!id) return std::nullopt;
  auto& ids = r.ctx().materialIds;
  if (auto it = ids.find(*id); it != ids.end()) return it->second;
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
