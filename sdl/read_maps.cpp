// Maps and lists of whole pigments (`pigment_map`, a block pattern's `pigment {..}` list),
// `average` of pigments and of normals. POV-Ray evaluates an entry at the point its
// enclosing pattern is evaluated at, so an entry's transforms are its own, from the
// enclosing pattern's space (POV-Ray's coordinates): Lucent's nested placements.
#include "read_support.h"
#include "scene_reader.h"

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
  if (PatternPlacement* place = placementOf(e.texture))
    place->patternFromObject = glm::inverse(p.transform.povMatrix());
  if (p.filter != 0.0f || p.transmit != 0.0f) addToColours(e.texture, {p.filter, p.transmit});
  return e;
}

namespace {

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

}  // namespace

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
  if (!isWord(t, "pigment_map")) return false;
  std::vector<TextureMapEntry> entries =
      readPigmentMap(in, t, std::holds_alternative<AverageTexture>(p.pattern));
  if (auto* a = std::get_if<AverageTexture>(&p.pattern)) {
    a->entries = std::move(entries);
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

// A block pattern's `pigment {..} [,] pigment {..}` list (the first 'pigment' next).
bool SceneReader::readBlockPigments(TokenStream& in, PovPigment& p, size_t count) {
  std::vector<TextureMapEntry> list;
  const SourceLoc at = in.peek().loc();
  while (list.size() < count && isWord(in.peek(), "pigment")) {
    in.next();
    list.push_back(entryOf(readPigment(in, defaults_.pigment), 0.0));
    in.allow(",");
  }
  if (list.size() < count) {
    keepError(in, at,
              "a list of pigments in a block pattern needs " + std::to_string(count) +
                  " pigments here (Lucent does not mix pigments and colours in one list)");
    return true;
  }
  if (auto* c = std::get_if<CheckerTexture>(&p.pattern)) c->pigments = std::move(list);
  else if (auto* h = std::get_if<HexagonTexture>(&p.pattern)) h->pigments = std::move(list);
  else if (auto* b = std::get_if<BrickTexture>(&p.pattern)) b->pigments = std::move(list);
  p.map.clear();
  return true;
}

// `average` and its `normal_map { [weight NORMAL_BODY] ... }` in a normal. A normal_map of
// another pattern is refused.
bool SceneReader::readNormalAverage(const Token& t, TokenStream& in, PovNormal& n) {
  if (isWord(t, "average")) {
    n.average = true;
    n.spec.average.clear();
    return true;
  }
  if (!isWord(t, "normal_map")) return false;
  if (!n.average) {
    unsupported(t, in, true);
    return true;
  }
  in.expect("{");
  for (;;) {
    const Token e = in.next();
    if (e.is("}")) break;
    if (!e.is("[")) in.error(e, "'[' or '}' expected in a normal map, not " + e.describe());
    WeightedNormal w;
    w.weight = entryValue(in, true);
    const PovNormal entry = readNormalBody(in, nullptr, true);
    w.normal = entry.spec;
    // Placed from the average's pattern space by its own transforms.
    w.normal.pattern.placement.patternFromObject = glm::inverse(entry.transform.povMatrix());
    n.spec.average.push_back(std::move(w));
  }
  if (n.spec.average.empty()) in.error(t, "a normal map needs at least one entry");
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
