// The texture children of a <material>, one reader per kind of the texture table
// (scenegraph/texture_spec.h): <checker>, <image> here, <pattern>, <hexagon> and <brick> in
// pattern_parser.cpp.
#include "texture_parser.h"

#include "gamma_attribute.h"
#include "pattern_parser.h"
#include "texture_map_parser.h"

#include "images/image_values_file.h"

#include <fmt/core.h>

#include <utility>

namespace lucent {

namespace {

Texture readTexture(ElementReader& t, const CheckerTexture*) {
  std::vector<std::string_view> attributes{"color1",    "color2",    "filter1", "filter2",
                                           "transmit1", "transmit2", "scale"};
  attributes.insert(attributes.end(), placementAttributes().begin(), placementAttributes().end());
  t.checkAttributes(attributes);
  CheckerTexture c;
  c.placement = parsePlacement(t);
  c.color1 = t.color("color1", c.color1);
  c.color2 = t.color("color2", c.color2);
  c.ft1 = parseFilterTransmit(t, "1");
  c.ft2 = parseFilterTransmit(t, "2");
  c.scale = t.number("scale", c.scale, NumberRule::positive());
  c.pigments = parseBlockPigments(
      t, 2, {"color1", "color2", "filter1", "filter2", "transmit1", "transmit2"});
  return c;
}

// <image>'s own attributes beside those <bump-map> shares (pattern_parser.h).
void readImageProjection(ElementReader& t, ImageTexture& img) {
  if (img.projection != ImageProjection::uv && t.has("scale"))
    t.attrError("scale",
                "'scale' is for an image at the shape's (u,v); a projected image "
                "is placed by 'transform'");
  img.all = parseFilterTransmit(t, "");
}

// <image>'s <palette index filter transmit> children: a palette image's entries with their own
// filter and transmit (POV-Ray's `filter N, F`, `transmit N, F`), and the image's palette
// indices, read now (POV-Ray's errors for an image without a palette and an index past it).
void readPaletteEntries(ElementReader& t, ImageTexture& img) {
  std::vector<std::pair<PaletteEntryFT, pugi::xml_node>> entries;
  t.forEachChild([&](pugi::xml_node n) {
    if (std::string_view(n.name()) != "palette") return;
    ElementReader e(t.ctx(), t.file(), n);
    e.checkAttributes({"index", "filter", "transmit"});
    if (!e.has("index")) return e.error("<palette> needs an 'index' (the palette entry's number)");
    PaletteEntryFT entry;
    entry.index = static_cast<int>(e.integer("index", 0, 0, 255));
    if (auto f = e.optionalNumber("filter")) entry.filter = static_cast<float>(*f);
    if (auto tr = e.optionalNumber("transmit")) entry.transmit = static_cast<float>(*tr);
    if (!e.has("filter") && !e.has("transmit"))
      return e.error("<palette> needs a 'filter' or a 'transmit' (the entry's own)");
    for (const auto& [was, node] : entries)
      if (was.index == entry.index)
        return e.attrError("index", fmt::format("palette entry {} is given twice (line {})",
                                                entry.index, t.file().loc(node).line));
    entries.emplace_back(entry, n);
  });
  if (entries.empty() || img.path.empty()) return;
  try {
    img.paletteIndices = paletteIndices(img.path);
  } catch (const std::exception& e) {  // ImageValuesError, a library's own
    return t.attrError("src", "cannot read the image's palette: " + std::string(e.what()));
  }
  if (!img.paletteIndices)
    return t.attrError("src",
                       "<palette> entries need a palette image (a PNG with a palette or a GIF, as "
                       "POV-Ray's filter and transmit of an index need a colour-mapped image)");
  const int size = img.paletteIndices->paletteSize;
  for (const auto& [entry, node] : entries) {
    if (entry.index < size) {
      img.palette.push_back(entry);
      continue;
    }
    ElementReader e(t.ctx(), t.file(), node);
    e.attrError("index", fmt::format("palette index {} is past the image's palette of {} "
                                     "entries (0 to {})",
                                     entry.index, size, size - 1));
  }
}

Texture readTexture(ElementReader& t, const ImageTexture*) {
  std::vector<std::string_view> attributes{"src",      "scale",     "filter",
                                           "transmit", "use-alpha", "gamma"};
  attributes.insert(attributes.end(), imageReadingAttributes().begin(),
                    imageReadingAttributes().end());
  t.checkAttributes(attributes);
  ImageTexture img;
  parseImageReading(t, img.projection, img.placement, img.once, img.interpolation);
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
      if (v.x == 0.0 || v.y == 0.0)
        t.attrError("scale", "the scale must not be zero, got '" + *s + "'");
      else img.scale = v;
    }
  }
  readImageProjection(t, img);
  readPaletteEntries(t, img);
  img.useAlpha = t.boolean("use-alpha", false);
  img.fileGamma = readGammaAttribute(t, "gamma");
  if (img.useAlpha && !img.path.empty()) {
    try {
      img.alphaTransmit = readImageTransmit(img.path);
    } catch (const std::exception& e) {  // ImageValuesError, a library's own
      t.attrError("src", "cannot read the image's transparency: " + std::string(e.what()));
    }
  }
  noChildrenButWarps(t, img.projection, "palette");
  return img;
}

Texture readTexture(ElementReader& t, const PatternTexture*) { return parsePatternTexture(t); }
Texture readTexture(ElementReader& t, const HexagonTexture*) { return parseHexagonTexture(t); }
Texture readTexture(ElementReader& t, const BrickTexture*) { return parseBrickTexture(t); }
Texture readTexture(ElementReader& t, const AverageTexture*) { return parseAverageTexture(t); }

// The reader of the kind whose element this is: a kind without a readTexture overload does
// not compile.
template <class... Kinds>
Texture readKind(ElementReader& t, const std::variant<std::monostate, Kinds...>*) {
  Texture texture;
  const std::string name = t.name();
  ((name == Kinds::kind.element
        ? (void)(texture = readTexture(t, static_cast<const Kinds*>(nullptr)))
        : void()),
   ...);
  return texture;
}

}  // namespace

std::vector<std::string_view> textureElements() {
  std::vector<std::string_view> names;
  for (const TextureKindInfo& k : textureKinds()) names.push_back(k.element);
  return names;
}

Texture parseTexture(ElementReader& t) { return readKind(t, static_cast<const Texture*>(nullptr)); }

}  // namespace lucent

namespace lucent {

void refuseUvMapping(ElementReader& t, const Texture& texture, const std::string& where) {
  if (!textureUsesUv(texture)) return;
  const std::string message =
      "mapping=\"uv\" is for a surface's textures (a material's own, "
      "its normal or map, and their entries): " +
      where + " has no (u,v) of its own";
  if (textureUvMapped(texture)) t.attrError("mapping", message);
  else t.error(message + " (an entry of its maps says mapping=\"uv\")");
}

}  // namespace lucent
