#include "texture_map_parser.h"

#include "expression.h"
#include "pattern_parser.h"
#include "texture_parser.h"

#include <algorithm>

namespace lucent {

namespace {

bool isTextureElement(std::string_view name) {
  const std::vector<std::string_view> names = textureElements();
  return std::find(names.begin(), names.end(), name) != names.end();
}

// An <entry>'s value attribute: "at" (a pigment map's), "weight" (an average's) or none.
enum class EntryValue { at, weight, none };

// One <entry>: its value, then a plain colour or one texture child. An image there is
// projected (an entry is read at its map's pattern point, which has no (u,v)).
TextureMapEntry parseEntry(ElementReader& e, EntryValue value) {
  std::vector<std::string_view> attributes{"color", "filter", "transmit"};
  if (value == EntryValue::at) attributes.push_back("at");
  if (value == EntryValue::weight) attributes.push_back("weight");
  e.checkAttributes(attributes);
  TextureMapEntry entry;
  if (value == EntryValue::at) {
    if (!e.has("at")) e.error("<entry> needs 'at' (a value from 0 to 1)");
    entry.at = e.number("at", 0.0, NumberRule::between(0.0, 1.0, "a number from 0 to 1"));
  } else if (value == EntryValue::weight) {
    if (!e.has("weight")) e.error("<entry> needs a 'weight' (a positive number)");
    entry.at = e.number("weight", 1.0, NumberRule::positive());
  }
  const bool plain = e.has("color");
  entry.color = {e.color("color", Color(0.0f)), parseFilterTransmit(e, "")};
  std::optional<SourceLoc> textureLoc;
  e.forEachChild([&](pugi::xml_node n) {
    ElementReader c(e.ctx(), e.file(), n);
    const std::string name = n.name();
    if (!isTextureElement(name)) {
      c.error(e.tag() +
              " holds one texture element (pattern, checker, hexagon, brick, average or image), "
              "not <" +
              name + ">");
      e.markFailed();
      return;
    }
    if (textureLoc) {
      c.error(e.tag() + " holds one texture; the first is at " + textureLoc->str());
      return;
    }
    if (plain || e.has("filter") || e.has("transmit")) {
      c.error((e.name() == "entry" ? "an " : "a ") + e.tag() +
              " with a texture takes no color, filter or transmit (the texture's own colours have "
              "them)");
      e.markFailed();
      return;
    }
    textureLoc = c.loc();
    entry.texture = parseTexture(c);
    if (const auto* image = std::get_if<ImageTexture>(&entry.texture);
        image && image->projection == ImageProjection::uv && !c.failed())
      c.error(
          "an <image> inside a map or a list of pigments needs a 'projection' (planar is "
          "POV-Ray's image_map's): an entry is read at its map's pattern point, which has no "
          "(u,v)");
  });
  if (!plain && !textureLoc && !e.failed())
    e.error(e.tag() +
            " needs a 'color' or a texture element (pattern, checker, hexagon, brick or "
            "average)");
  return entry;
}

// The <entry> children of r, each read by `read`.
template <class Read>
void forEachEntry(ElementReader& r, Read read) {
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader e(r.ctx(), r.file(), n);
    // An average's <warp>s belong to its placement (lang/warp_parser.h).
    if (std::string_view(n.name()) == "warp" && (r.name() == "average" || r.name() == "normal"))
      return;
    if (std::string_view(n.name()) != "entry") {
      e.error(r.tag() + " holds <entry> elements, not <" + std::string(n.name()) + ">");
      return;
    }
    read(e);
  });
}

}  // namespace

std::vector<TextureMapEntry> parsePigmentMap(ElementReader& r) {
  r.checkAttributes({});
  std::vector<TextureMapEntry> entries;
  forEachEntry(r, [&](ElementReader& e) {
    TextureMapEntry entry = parseEntry(e, EntryValue::at);
    if (!entries.empty() && entry.at < entries.back().at) {
      e.attrError("at",
                  "the entries of a <pigment-map> go in increasing order of 'at'; this one is "
                  "below the one before (" +
                      formatNumber(entries.back().at) + ")");
      return;
    }
    entries.push_back(std::move(entry));
  });
  if (entries.empty() && !r.failed()) r.error("<pigment-map> needs at least one <entry at>");
  return entries;
}

std::shared_ptr<const TextureMapEntry> parsePatternPigment(ElementReader& r) {
  return std::make_shared<const TextureMapEntry>(parseEntry(r, EntryValue::none));
}

std::vector<TextureMapEntry> parsePigmentList(ElementReader& r, size_t count) {
  r.checkAttributes({});
  std::vector<TextureMapEntry> entries;
  forEachEntry(r, [&](ElementReader& e) { entries.push_back(parseEntry(e, EntryValue::none)); });
  if (entries.size() != count && !r.failed())
    r.error("<pigment-list> of <" + std::string(r.element().parent().name()) + "> needs " +
            std::to_string(count) + " entries, got " + std::to_string(entries.size()));
  return entries;
}

Texture parseAverageTexture(ElementReader& r) {
  r.checkAttributes(placementAttributes());
  AverageTexture t;
  t.placement = parsePlacement(r);
  forEachEntry(r,
               [&](ElementReader& e) { t.entries.push_back(parseEntry(e, EntryValue::weight)); });
  if (t.entries.empty() && !r.failed()) r.error("<average> needs at least one <entry weight>");
  return t;
}

std::vector<WeightedNormal> parseNormalAverage(ElementReader& r) {
  std::vector<WeightedNormal> average;
  forEachEntry(r, [&](ElementReader& e) {
    e.checkAttributes({"weight"});
    WeightedNormal w;
    if (!e.has("weight")) e.error("<entry> needs a 'weight' (a positive number)");
    w.weight = e.number("weight", 1.0, NumberRule::positive());
    int normals = 0;
    e.forEachChild([&](pugi::xml_node n) {
      ElementReader c(e.ctx(), e.file(), n);
      if (std::string_view(n.name()) != "normal") {
        c.error("an <entry> of an average <normal> holds one <normal>, not <" +
                std::string(n.name()) + ">");
      } else if (normals++ > 0) {
        c.error("an <entry> of an average <normal> holds one <normal>");
      } else {
        w.normal = parseNormal(c);
        refuseNormalUvMapping(c, w.normal);
      }
    });
    if (normals == 0 && !e.failed()) e.error("<entry> needs a <normal> child");
    average.push_back(std::move(w));
  });
  if (average.empty() && !r.failed())
    r.error("<normal type=\"average\"> needs at least one <entry weight><normal/></entry>");
  return average;
}

}  // namespace lucent
