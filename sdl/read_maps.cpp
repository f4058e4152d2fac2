// Maps and lists of whole pigments (`pigment_map`, a block pattern's `pigment {..}` list),
// `average` of pigments and of normals, normal maps, slope maps and block patterns' lists
// of normals. POV-Ray evaluates an entry at the point its
// enclosing pattern is evaluated at, so an entry's transforms are its own, from the
// enclosing pattern's space (POV-Ray's coordinates): Lucent's nested placements.
#include "read_support.h"
#include "scene_reader.h"

#include "scenegraph/images_in_maps.h"

namespace lucent::sdl {

namespace {

// A filter and a transmit added to every colour of a pattern pigment (a declared pigment
// read on its own keeps a uniform transmit as the pigment's: back into its colours).
void addToColours(Texture& t, const FilterTransmit& ft) {
  auto add = [&](FilterTransmit& c) {
    c.filter += ft.filter;
    c.transmit += ft.transmit;
  };
  if (auto* p = std::get_if<PatternTexture>(&t)) {
    for (ColorMapEntry& e : p->map.entries) add(e.ft);
  } else if (auto* c = std::get_if<CheckerTexture>(&t)) {
    add(c->ft1);
    add(c->ft2);
  } else if (auto* h = std::get_if<HexagonTexture>(&t)) {
    for (FilterTransmit& f : h->spec.ft) add(f);
  } else if (auto* b = std::get_if<BrickTexture>(&t)) {
    add(b->spec.ft1);
    add(b->spec.ft2);
  }
}

}  // namespace

TextureMapEntry entryOf(const PovPigment& p, double at) {
  TextureMapEntry e;
  e.at = at;
  if (!p.patterned()) {
    e.color = {p.color, {p.filter, p.transmit}};
    return e;
  }
  e.texture = p.pattern;
  if (PatternPlacement* place = placementOf(e.texture)) {
    // A uv-mapped entry is placed from (u, v, 0) by its own block's transforms.
    place->patternFromObject = glm::inverse((p.uv ? p.uvTransform : p.transform).povMatrix());
    place->uv = p.uv;
  }
  if (p.filter != 0.0f || p.transmit != 0.0f) addToColours(e.texture, {p.filter, p.transmit});
  return e;
}

// An entry's value: required in a map, optional in an average's (POV-Ray's weight 1 then),
// where the entry may start with the body itself.
double entryValue(TokenStream& in, bool average) {
  const Token& next = in.peek();
  const Value* v = next.kind == TokenKind::Identifier ? next.value() : nullptr;
  const bool number = next.kind == TokenKind::Number || (v && v->type == ValueType::Float) ||
                      next.is("(") || next.is("-") || next.is("+");
  const double value = !average || number ? in.parseFloat() : 1.0;
  in.allow(",");
  return value;
}

// pigment_pattern's `{ PIGMENT_BODY }`: the pigment as a map's entry, placed in the
// pattern's space by its own transforms.
std::shared_ptr<const TextureMapEntry> SceneReader::readPatternPigment(TokenStream& in) {
  const SourceLoc at = in.peek().loc();
  auto entry =
      std::make_shared<const TextureMapEntry>(entryOf(readPigment(in, defaults_.pigment), 0.0));
  refuseNestedImage(*entry, in);
  if (textureUsesUv(entry->texture))
    keepError(in, at,
              "'uv_mapping' in a pigment_pattern's pigment is not supported by Lucent (its "
              "grey level is taken at a point, which has no (u, v))");
  return entry;
}

// `pigment_map { [value PIGMENT_BODY] ... }`, the '{' next, or `pigment_map { M }`; in an
// average (`average`) the values are optional weights.
std::vector<TextureMapEntry> SceneReader::readPigmentMap(TokenStream& in, const Token& at,
                                                         bool average) {
  std::vector<TextureMapEntry> entries;
  in.expect("{");
  if (const auto* item = use<PigmentMapItem>(in.peek(), in)) {
    in.next();
    in.expect("}");
    return item->entries;
  }
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) break;
    if (isWord(t, "blend_mode") || isWord(t, "blend_gamma")) {
      keepError(in, t.loc(),
                "'" + std::string(t.text()) +
                    "' is not supported by Lucent (its pigment maps blend linearly)");
      in.parseFloat();
      continue;
    }
    if (!t.is("[")) in.error(t, "'[' or '}' expected in a pigment map, not " + t.describe());
    const double value = entryValue(in, average);
    entries.push_back(entryOf(readPigmentBody(in, defaults_.pigment, true), value));
  }
  if (entries.empty()) in.error(at, "a pigment map needs at least one entry");
  for (size_t i = 1; i < entries.size() && !average; ++i)
    if (entries[i].at < entries[i - 1].at) {
      keepError(in, at.loc(), "the pigment map's entries must be in ascending order");
      break;
    }
  return entries;
}

// `average` (its pigments come in a pigment_map) and `pigment_map` in a pigment.
bool SceneReader::readPigmentMapKeyword(const Token& t, TokenStream& in, PovPigment& p) {
  if (isWord(t, "average")) {
    AverageTexture a;
    if (const PatternPlacement* was = placementOf(p.pattern)) a.placement = *was;
    p.pattern = a;
    p.map.clear();
    p.mapLoc = t.loc();
    return true;
  }
  if (isWord(t, "slope_map") || isWord(t, "normal_map")) {
    // POV-Ray's parser: "slope_map only in normal".
    keepError(in, t.loc(), "'" + std::string(t.text()) + "' belongs in a normal, not a pigment");
    skipBlock(in);
    return true;
  }
  if (!isWord(t, "pigment_map")) return false;
  std::vector<TextureMapEntry> entries =
      readPigmentMap(in, t, std::holds_alternative<AverageTexture>(p.pattern));
  if (auto* a = std::get_if<AverageTexture>(&p.pattern)) {
    a->entries = std::move(entries);
  } else if (auto* pattern = std::get_if<PatternTexture>(&p.pattern);
             pattern && pattern->pattern.type == PatternType::object) {
    in.error(t,
             "a pigment_map cannot be used with an object pattern (POV-Ray's rule: its "
             "pigments are its list of two)");
  } else if (auto* pattern = std::get_if<PatternTexture>(&p.pattern)) {
    pattern->pigments = std::move(entries);
    p.map.clear();
  } else if (p.patterned()) {
    keepError(in, t.loc(),
              "'pigment_map' on a block pattern is not supported by Lucent (give it a list of "
              "pigments: checker pigment {..} pigment {..})");
  } else {
    keepError(in, t.loc(), "'pigment_map' needs a pattern before it (gradient y pigment_map {..})");
  }
  return true;
}

// A pigment_pattern's pigment holding an image: its grey level is taken wherever the
// pattern is evaluated (normals, functions), where no image's pixels are at hand.
void SceneReader::refuseNestedImage(const TextureMapEntry& e, TokenStream& in) {
  if (!textureHoldsImage(e.texture)) return;
  const auto* image = std::get_if<ImageTexture>(&e.texture);
  std::optional<SourceLoc> at;
  if (image) at = image->loc;
  forEachImageInMaps(e.texture, [&](const ImageTexture& i) {
    if (!at) at = i.loc;
  });
  keepError(in, *at,
            "'image_map' in a pigment_pattern is not supported by Lucent (its grey level is "
            "taken without the image's pixels)");
}

// A block pattern's `pigment {..} [,] pigment {..}` list (the first 'pigment' next).
bool SceneReader::readBlockPigments(TokenStream& in, PovPigment& p, size_t count) {
  std::vector<TextureMapEntry> list;
  while (list.size() < count && isWord(in.peek(), "pigment")) {
    in.next();
    list.push_back(entryOf(readPigment(in, defaults_.pigment), 0.0));
    in.allow(",");
  }
  // POV-Ray's Parse_Blend_List: the cells the list leaves take the #default pigment; a
  // colour where a pigment was awaited is POV-Ray's error.
  if (list.size() < count && isColourStart(in.peek()))
    keepError(in, in.peek().loc(),
              "a colour after a block pattern's pigments (POV-Ray: \"No matching } in "
              "'pigment'\"; a list is pigments alone, the cells it leaves take the #default "
              "pigment)");
  while (list.size() < count) list.push_back(entryOf(defaults_.pigment, 0.0));
  // An object pattern's pigments are a map's entries at its values 0 and 1.
  for (size_t i = 0; i < list.size(); ++i) list[i].at = static_cast<double>(i);
  if (auto* o = std::get_if<PatternTexture>(&p.pattern)) o->pigments = std::move(list);
  else if (auto* c = std::get_if<CheckerTexture>(&p.pattern)) c->pigments = std::move(list);
  else if (auto* h = std::get_if<HexagonTexture>(&p.pattern)) h->pigments = std::move(list);
  else if (auto* b = std::get_if<BrickTexture>(&p.pattern)) b->pigments = std::move(list);
  p.map.clear();
  return true;
}

namespace {

// Normal patterns whose own normal POV-Ray uses (not the slope): it ignores their slope map.
bool ownNormal(PatternType t) {
  return t == PatternType::bumps || t == PatternType::dents || t == PatternType::wrinkles ||
         t == PatternType::ripples || t == PatternType::waves || t == PatternType::quilted ||
         t == PatternType::facets;
}

// A normal read as a map's or a list's entry, placed from the map's pattern space by its
// own transforms.
NormalSpec placedEntry(const PovNormal& entry) {
  NormalSpec spec = entry.spec;
  spec.pattern.placement.patternFromObject = glm::inverse(entry.transform.povMatrix());
  return spec;
}

}  // namespace

// `normal_map { [value NORMAL_BODY] ... }` (in an average, the values are optional weights)
// and `slope_map { [value, <height, slope>] ... }`, the keyword read.
bool SceneReader::readNormalMapKeyword(const Token& t, TokenStream& in, PovNormal& n) {
  if (isWord(t, "average")) {
    n.average = true;
    n.patterned = true;
    n.spec.average.clear();
    n.spec.map.clear();
    n.spec.slopeMap.clear();
    n.spec.block = NormalBlock::none;
    return true;
  }
  const bool slope = isWord(t, "slope_map");
  if (!slope && !isWord(t, "normal_map")) return false;
  const bool facets = n.patterned && !n.average && n.spec.pattern.type == PatternType::facets;
  if (n.spec.block != NormalBlock::none || (slope && n.average) || (!slope && facets)) {
    // POV-Ray's parser: "Cannot use normal_map with this normal type."
    keepError(in, t.loc(),
              "'" + std::string(t.text()) +
                  "' cannot be used with this normal type (as POV-Ray's " + "parser says)");
    skipBlock(in);
    return true;
  }
  if (slope) {
    n.spec.slopeMap = readSlopeMap(in, t);
    n.spec.map.clear();
    if (n.patterned && ownNormal(n.spec.pattern.type)) {
      warn(in, t.loc(),
           "the slope_map has no effect on " +
               std::string(patternTypeInfo(n.spec.pattern.type).pov) +
               " (POV-Ray bends by that pattern's own normal, not by a slope)");
      n.spec.slopeMap.clear();
    }
    return true;
  }
  in.expect("{");
  std::vector<NormalMapEntry> entries;
  for (;;) {
    const Token e = in.next();
    if (e.is("}")) break;
    if (!e.is("[")) in.error(e, "'[' or '}' expected in a normal map, not " + e.describe());
    NormalMapEntry entry;
    entry.at = entryValue(in, n.average);
    const PovNormal read = readNormalBody(in, nullptr, true);
    if (read.bump)
      keepError(in, read.bump->loc,
                "'bump_map' inside a normal map is not supported by Lucent (a bump map's "
                "pixels are loaded per material; give the texture the bump_map itself)");
    entry.normal = placedEntry(read);
    entries.push_back(std::move(entry));
  }
  if (entries.empty()) in.error(t, "a normal map needs at least one entry");
  if (n.average) {
    n.spec.average.clear();
    for (NormalMapEntry& e : entries) n.spec.average.push_back({e.at, std::move(e.normal)});
    return true;
  }
  for (size_t i = 1; i < entries.size(); ++i)
    if (entries[i].at < entries[i - 1].at) {
      keepError(in, t.loc(), "the normal map's entries must be in ascending order");
      break;
    }
  n.spec.map = std::move(entries);
  n.spec.slopeMap.clear();
  return true;
}

// The `{ [value, <height, slope>] ... }` of a slope_map (a float for the pair is both).
std::vector<SlopeMapEntry> SceneReader::readSlopeMap(TokenStream& in, const Token& at) {
  std::vector<SlopeMapEntry> entries;
  in.expect("{");
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) break;
    if (!t.is("[")) in.error(t, "'[' or '}' expected in a slope map, not " + t.describe());
    SlopeMapEntry e;
    e.at = in.parseFloat();
    in.allow(",");
    const Token& pairAt = in.peek();
    const Value v = in.parseExpression();
    if (v.type == ValueType::Float) e.height = e.slope = v.v[0];
    else if (v.type == ValueType::Uv) e.height = v.v[0], e.slope = v.v[1];
    else in.error(pairAt, "a slope map's entry needs <height, slope> after its value");
    in.expect("]");
    entries.push_back(e);
  }
  if (entries.empty()) in.error(at, "a slope map needs at least one entry");
  for (size_t i = 1; i < entries.size(); ++i)
    if (entries[i].at < entries[i - 1].at) {
      keepError(in, at.loc(), "the slope map's entries must be in ascending order");
      break;
    }
  return entries;
}

// A list of normals, `normal {..} [,] normal {..}`, up to `count` of them, each placed by
// its own transforms: the entries of a block pattern's or an object pattern's normal.
void SceneReader::readNormalList(TokenStream& in, PovNormal& n, size_t count) {
  while (n.spec.map.size() < count && isWord(in.peek(), "normal")) {
    in.next();
    NormalMapEntry e;
    e.at = static_cast<double>(n.spec.map.size());
    const PovNormal read = readNormal(in, nullptr);
    if (read.uv)
      keepError(in, read.uvLoc,
                "'uv_mapping' in a list of normals is not supported by Lucent (an entry is bent "
                "at its pattern's point; map the whole normal instead)");
    if (read.bump)
      keepError(in, read.bump->loc,
                "'bump_map' in a list of normals is not supported by Lucent (a bump map's "
                "pixels are loaded per material; give the texture the bump_map itself)");
    e.normal = placedEntry(read);
    n.spec.map.push_back(std::move(e));
    in.allow(",");
  }
}

// A block pattern in a normal, its keyword read: `checker`, `hexagon` or `brick`, then its
// list `normal {..} [,] normal {..}` (as many as cells at most). Missing normals are the
// #default normal's, as POV-Ray's; without one POV-Ray 3.7 stops, and so does Lucent.
// Without any, the normal is bent by the slope of the cell index.
bool SceneReader::readBlockNormal(const Token& t, TokenStream& in, PovNormal& n) {
  NormalBlock block = NormalBlock::none;
  if (isWord(t, "checker")) block = NormalBlock::checker;
  else if (isWord(t, "hexagon")) block = NormalBlock::hexagon;
  else if (isWord(t, "brick")) block = NormalBlock::brick;
  else return false;
  const size_t count = block == NormalBlock::hexagon ? 3 : 2;
  n.spec.block = block;
  n.spec.pattern.frequency = 0.0;  // POV-Ray's: the cell number as it is, unless given
  n.spec.brick = BrickSpec{};
  n.spec.map.clear();
  n.spec.slopeMap.clear();
  n.spec.average.clear();
  n.average = false;
  n.patterned = true;
  readNormalList(in, n, count);
  // POV-Ray's optional amount after the pattern (unused by a list of normals).
  if (in.allow(",") || startsNumber(in.peek())) n.spec.depth = in.parseFloat();
  if (n.spec.map.empty()) return true;  // the slope of the cell index, as POV-Ray's
  while (n.spec.map.size() < count) {
    if (!defaults_.normal || !defaults_.normal->patterned) {
      keepError(in, t.loc(),
                "the list of normals needs " + std::to_string(count) +
                    " normals here (POV-Ray 3.7 fills a shorter list with the #default normal, "
                    "and there is none)");
      return true;
    }
    NormalMapEntry e;
    e.at = static_cast<double>(n.spec.map.size());
    e.normal = placedEntry(*defaults_.normal);
    n.spec.map.push_back(std::move(e));
  }
  return true;
}

// What an entry of a map cannot hold, refused; the rest of the entry skipped to its ']'.
void SceneReader::skipEntryRest(const Token& t, TokenStream& in) {
  if (const auto* item = dynamic_cast<const SceneItem*>(itemOf(t)); item && !item->refused.empty())
    reportRefused(*item, t.loc(), in);
  else if (t.kind != TokenKind::Keyword)
    in.error(t, "unexpected " + t.describe() + " in a map's entry");
  else if (!refusePattern(t, in, true)) unsupported(t, in, false);
  int depth = 0;
  for (;;) {
    const Token& k = in.next();
    if (k.kind == TokenKind::End) in.error(k, "the map's entry is not closed (']' expected)");
    if (k.is("{")) ++depth;
    if (k.is("}")) --depth;
    if (depth == 0 && k.is("]")) return;
  }
}

}  // namespace lucent::sdl
