#include "normal_map_parser.h"

#include "expression.h"
#include "pattern_parser.h"

namespace lucent {

namespace {

// The <entry> children of r, each read by `read`.
template <class Read>
void forEachEntry(ElementReader& r, Read read) {
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader e(r.ctx(), r.file(), n);
    if (std::string_view(n.name()) != "entry") {
      e.error(r.tag() + " holds <entry> elements, not <" + std::string(n.name()) + ">");
      return;
    }
    read(e);
  });
}

// An entry's `at`: required, 0 to 1, not below the entry before it.
template <class Entry>
double entryAt(ElementReader& e, const std::vector<Entry>& before, const std::string& list) {
  if (!e.has("at")) e.error("<entry> needs 'at' (a value from 0 to 1)");
  const double at = e.number("at", 0.0, NumberRule::between(0.0, 1.0, "a number from 0 to 1"));
  if (!before.empty() && at < before.back().at)
    e.attrError("at", "the entries of a <" + list +
                          "> go in increasing order of 'at'; this one is below the one before (" +
                          formatNumber(before.back().at) + ")");
  return at;
}

// An entry's <normal> child; none is `flat` where allowed.
void entryNormal(ElementReader& e, NormalMapEntry& entry, bool flatAllowed) {
  int normals = 0;
  e.forEachChild([&](pugi::xml_node n) {
    ElementReader c(e.ctx(), e.file(), n);
    if (std::string_view(n.name()) != "normal")
      c.error("an <entry> of a <" + std::string(e.element().parent().name()) +
              "> holds one <normal>, not <" + std::string(n.name()) + ">");
    else if (normals++ > 0)
      c.error("an <entry> of a <" + std::string(e.element().parent().name()) +
              "> holds one <normal>");
    else {
      entry.normal = parseNormal(c);
      refuseNormalUvMapping(c, entry.normal);
    }
  });
  entry.flat = normals == 0;
  if (entry.flat && !flatAllowed && !e.failed())
    e.error("<entry> needs a <normal> child (the normal at that value)");
}

}  // namespace

std::vector<NormalMapEntry> parseNormalMap(ElementReader& r) {
  r.checkAttributes({});
  std::vector<NormalMapEntry> entries;
  forEachEntry(r, [&](ElementReader& e) {
    e.checkAttributes({"at"});
    NormalMapEntry entry;
    entry.at = entryAt(e, entries, "normal-map");
    entryNormal(e, entry, false);
    entries.push_back(std::move(entry));
  });
  if (entries.empty() && !r.failed())
    r.error("<normal-map> needs at least one <entry at><normal/></entry>");
  return entries;
}

std::vector<NormalMapEntry> parseNormalList(ElementReader& r, size_t count) {
  r.checkAttributes({});
  std::vector<NormalMapEntry> entries;
  forEachEntry(r, [&](ElementReader& e) {
    e.checkAttributes({});
    NormalMapEntry entry;
    entry.at = static_cast<double>(entries.size());
    entryNormal(e, entry, true);
    entries.push_back(std::move(entry));
  });
  if (entries.size() != count && !r.failed())
    r.error("<normal-list> of a <normal type=\"" +
            std::string(r.element().parent().attribute("type").as_string()) + "\"> needs " +
            std::to_string(count) + " entries, got " + std::to_string(entries.size()));
  return entries;
}

std::vector<SlopeMapEntry> parseSlopeMap(ElementReader& r) {
  r.checkAttributes({});
  std::vector<SlopeMapEntry> entries;
  forEachEntry(r, [&](ElementReader& e) {
    e.checkAttributes({"at", "height", "slope"});
    SlopeMapEntry entry;
    entry.at = entryAt(e, entries, "slope-map");
    if (!e.has("height") || !e.has("slope"))
      e.error(
          "<entry> of a <slope-map> needs 'height' and 'slope' (POV-Ray's [at <height, slope>])");
    entry.height = e.number("height", 0.0);
    entry.slope = e.number("slope", 0.0);
    e.forEachChild([&](pugi::xml_node n) {
      ElementReader(e.ctx(), e.file(), n)
          .error("an <entry> of a <slope-map> takes no child elements");
    });
    entries.push_back(entry);
  });
  if (entries.empty() && !r.failed())
    r.error("<slope-map> needs at least one <entry at height slope>");
  return entries;
}

}  // namespace lucent
