// The texture children of a <material>, one reader per kind of the texture table
// (scenegraph/texture_spec.h): <checker>, <image> here, <pattern>, <hexagon> and <brick> in
// pattern_parser.cpp.
#include "texture_parser.h"

#include "pattern_parser.h"
#include "texture_map_parser.h"

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

Texture readTexture(ElementReader& t, const ImageTexture*) {
  std::vector<std::string_view> attributes{"src", "scale", "filter", "transmit"};
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
  noChildrenButWarps(t, img.projection);
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
  if (textureUvMapped(texture))
    t.attrError("mapping", "mapping=\"uv\" is for a material's own texture, normal or map: " +
                               where + " has no (u,v) of its own");
}

}  // namespace lucent
