// Textures: pigment, normal, finish, texture and interior blocks, each starting from what
// POV-Ray starts it from (the #default, or an identifier written first). The patterns,
// their colours and modifiers are read by read_patterns.cpp.
#include "read_support.h"
#include "scene_reader.h"

#include "lang/expression.h"

#include <cmath>

#include <algorithm>

namespace lucent::sdl {

PovPigment SceneReader::readPigment(TokenStream& in, const PovPigment& start) {
  in.expect("{");
  return readPigmentBody(in, start, false);
}

PovPigment SceneReader::readPigmentBody(TokenStream& in, const PovPigment& start, bool inEntry) {
  PovPigment p = start;
  if (const auto* item = use<PigmentItem>(in.peek(), in)) {
    in.next();
    p = item->pigment;
  }
  bool uvBlock = false, first = true;
  for (;;) {
    const Token t = in.next();
    const bool atStart = first;
    first = false;
    if (t.is(inEntry ? "]" : "}")) {
      settlePavement(t, in, specOf(p.pattern));
      resolvePigmentColours(p, in, inEntry);
      if (uvBlock) p.uvTransform = p.transform;
      return p;
    }
    if (isWord(t, "uv_mapping")) {
      // POV-Ray: the rest of the block is a new pigment (from the #default's) that the
      // outer one evaluates at (u, v, 0); an identifier before it is dropped. An entry of a
      // map reads (u, v, 0) too, whatever point its map hands it.
      if (!atStart) in.error(t, "'uv_mapping' must come first in a pigment, as POV-Ray reads it");
      p = defaults_.pigment;
      if (const auto* item = use<PigmentItem>(in.peek(), in)) {
        in.next();
        p = item->pigment;
      }
      p.uv = uvBlock = true;
    } else if (isColourStart(t)) {
      in.unget();
      const PovColour c = readColour(in);
      p.color = c.rgb;
      p.filter = c.filter;
      p.transmit = c.transmit;
      p.pattern = std::monostate{};
      p.map.clear();
    } else if (!readTransform(t, in, p.transform) &&
               !readWarp(t, in, placementOf(p.pattern), p.transform) &&
               !readPigmentMapKeyword(t, in, p) && !readPatternKeyword(t, in, p)) {
      if (inEntry) skipEntryRest(t, in);
      else if (!refusePattern(t, in)) unreadInBlock(t, in);
      return p;
    }
  }
}

// `normal { [Identifier] PATTERN [amount] modifiers bump_size F }`.
PovNormal SceneReader::readNormal(TokenStream& in, const PovNormal* start) {
  in.expect("{");
  return readNormalBody(in, start, false);
}

PovNormal SceneReader::readNormalBody(TokenStream& in, const PovNormal* start, bool inEntry) {
  PovNormal n;
  if (start) n = *start;
  else if (defaults_.normal) n = *defaults_.normal;  // POV-Ray copies the #default normal
  if (const auto* item = use<NormalItem>(in.peek(), in)) {
    in.next();
    n = item->normal;
  }
  bool uvBlock = false, first = true;
  for (;;) {
    const Token t = in.next();
    const bool atStart = first;
    first = false;
    if (t.is(inEntry ? "]" : "}")) {
      settlePavement(t, in, &n.spec.pattern);
      if (n.average && n.spec.average.empty())
        keepError(in, t.loc(), "'average' needs a normal_map (the normals it averages)");
      if (n.spec.block != NormalBlock::none &&
          !blockValuesUnchanged(n.spec.pattern, n.spec.block == NormalBlock::hexagon ? 3 : 2))
        keepError(in, t.loc(),
                  "frequency, phase or a wave on a block pattern's normal is not supported by "
                  "Lucent (POV-Ray bends by the changed cell number)");
      if (uvBlock) n.uvTransform = n.transform;
      return n;
    }
    if (isWord(t, "uv_mapping")) {
      // POV-Ray: the rest of the block is a new normal (from the #default's) bent at (u, v, 0)
      // of the shape, the world normal bent by it; an identifier before it is dropped.
      if (!atStart) in.error(t, "'uv_mapping' must come first in a normal, as POV-Ray reads it");
      if (inEntry)
        keepError(in, t.loc(),
                  "'uv_mapping' inside a map or a list of normals is not supported by Lucent "
                  "(an entry is bent at its map's point; map the whole normal instead)");
      n = defaults_.normal ? *defaults_.normal : PovNormal{};
      if (const auto* item = use<NormalItem>(in.peek(), in)) {
        in.next();
        n = item->normal;
      }
      n.uv = n.ownUv = uvBlock = n.bendInWorld = true;
      n.uvLoc = t.loc();
      continue;
    }
    const PatternTypeInfo* type = nullptr;
    if (t.kind == TokenKind::Keyword && !isWord(t, "object"))  // object's list: readObjectNormal
      for (const PatternTypeInfo& info : kPatternTypes)
        if (info.pov == t.text()) type = &info;
    if (isWord(t, "object")) {
      readObjectNormal(t, in, n);
    } else if (type) {
      PatternSpec s;
      s.type = type->type;
      s.placement = n.spec.pattern.placement;
      s.noiseGenerator = 0;  // the scene's global_settings noise_generator (finishScene)
      readPatternArguments(t, in, s);
      if (s.type == PatternType::function) s.function = readPatternFunction(in);
      if (s.type == PatternType::pigment) s.pigment = readPatternPigment(in);
      if (s.type == PatternType::image) s.image = readImagePattern(in);
      n.spec.pattern = s;
      // A pattern in place of a uv-mapped one started from (a #default's) is not uv-mapped.
      if (!uvBlock) n.uv = n.ownUv = n.bendInWorld = false;
      n.spec.average.clear();
      n.spec.block = NormalBlock::none;  // a map (a block's list too) stays, as POV-Ray's
      n.average = false;
      n.patterned = true;
      // POV-Ray: an optional comma, then the optional amount (its bump_size).
      if (in.allow(",") || startsNumber(in.peek())) n.spec.depth = in.parseFloat();
    } else if (isWord(t, "bump_map")) {
      readBumpMap(t, in, n);
    } else if (isWord(t, "bump_size")) {
      n.spec.depth = in.parseFloat();
      if (n.bump) n.bump->depth = n.spec.depth;
    } else if (n.spec.block == NormalBlock::brick &&
               (isWord(t, "brick_size") || isWord(t, "mortar"))) {
      if (isWord(t, "mortar")) {
        n.spec.brick.mortar = in.parseFloat();
      } else {
        const Vec3 size = toVec3(in.parseVector());
        if (!(size.x > 0 && size.y > 0 && size.z > 0))
          in.error(t, "the brick's size must be positive in x, y and z");
        n.spec.brick.size = size;
      }
    } else if (isWord(t, "accuracy")) {
      const double accuracy = in.parseFloat();
      if (!(accuracy > 0.0 && std::isfinite(accuracy)))
        in.error(t, "a normal's accuracy must be a positive number, not " + formatNumber(accuracy));
      n.spec.accuracy = accuracy;
    } else if (!readBlockNormal(t, in, n) && !readNormalMapKeyword(t, in, n) &&
               !readTransform(t, in, n.transform) &&
               !readWarp(t, in, &n.spec.pattern.placement, n.transform) &&
               !readPatternModifier(t, in, &n.spec.pattern, &n.spec.pattern.placement)) {
      if (inEntry) skipEntryRest(t, in);
      else if (!refusePattern(t, in)) unreadInBlock(t, in);
      return n;
    }
  }
}

PovFinish SceneReader::readFinish(TokenStream& in, const PovFinish& start) {
  PovFinish f = start;
  in.expect("{");
  if (const auto* item = use<FinishItem>(in.peek(), in)) {
    in.next();
    f = item->finish;
  }
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) return f;
    const std::string_view w = t.kind == TokenKind::Keyword ? t.text() : "";
    if (isWord(in.peek(), "albedo")) {
      const Token albedo = in.next();
      unreadInBlock(albedo, in);
      return f;
    }
    if (w == "ambient") {
      f.ambient = readColour(in).rgb;
    } else if (w == "emission") {
      f.emission = readColour(in).rgb;
    } else if (w == "diffuse") {
      f.diffuse = in.parseFloat();
      if (in.allow(",")) {
        in.parseFloat();
        warn(in, t.loc(), "the diffuse of the back side is not imported (Lucent lights the front)");
      }
    } else if (w == "brilliance") {
      f.brilliance = in.parseFloat();
    } else if (w == "phong") {
      f.phong = in.parseFloat();
    } else if (w == "phong_size") {
      f.phongSize = in.parseFloat();
    } else if (w == "specular") {
      f.specular = in.parseFloat();
    } else if (w == "roughness") {
      f.roughness = in.parseFloat();
    } else if (w == "metallic") {
      f.metallic = startsNumber(in.peek()) ? in.parseFloat() : 1.0;
    } else if (w == "reflection") {
      if (in.peek().is("{")) {
        in.next();
        readReflection(in, f.reflection);
      } else {
        f.reflection.min = f.reflection.max = readColour(in).rgb;
      }
    } else if (w == "reflection_exponent") {
      f.reflection.exponent = in.parseFloat();
    } else if (w == "conserve_energy") {
      f.conserveEnergy = optionalBool(in);
    } else if (w == "irid") {
      in.expect("{");
      f.irid = in.parseFloat();
      for (;;) {
        const Token k = in.next();
        if (k.is("}")) break;
        if (isWord(k, "thickness")) f.iridThickness = in.parseFloat();
        else if (isWord(k, "turbulence")) f.iridTurbulence = in.parseFloat();
        else in.error(k, "unexpected " + k.describe() + " in irid");
      }
    } else if (w == "crand") {
      f.crand = in.parseFloat();
    } else if (w == "ior") {
      f.ior = in.parseFloat();
    } else if (w == "refraction") {
      readRefraction(t, in);
    } else {
      unreadInBlock(t, in);
      return f;
    }
  }
}

// POV-Ray 3.0's `refraction R` (finish or interior): once needed to turn refraction on,
// in 3.7 a factor on the light seen through the object that shadows do not take.
void SceneReader::readRefraction(const Token& t, TokenStream& in) {
  const double r = in.parseFloat();
  if (r == 1.0)
    warn(in, t.loc(),
         "'refraction 1' is not needed to turn refraction on (read and ignored, as POV-Ray "
         "reads it)");
  else
    keepError(in, t.loc(),
              "'refraction " + formatNumber(r) +
                  "' (a factor on the light seen through the object, not on its shadow) is "
                  "not supported by Lucent; POV-Ray attenuates with interior { fade_distance "
                  "fade_power }");
}

// `reflection { [MIN,] MAX fresnel falloff F exponent F metallic [F] }` (the '{' read).
void SceneReader::readReflection(TokenStream& in, PovReflection& r) {
  const Color first = readColour(in).rgb;
  r.min = r.max = first;
  const bool two = in.allow(",");
  if (two) r.max = readColour(in).rgb;
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) {
      // One colour with fresnel is the maximum over a minimum of 0, as POV-Ray reads it.
      if (r.fresnel && !two) r.min = Color(0.0f);
      return;
    }
    if (isWord(t, "fresnel")) r.fresnel = optionalBool(in);
    else if (isWord(t, "falloff")) r.falloff = in.parseFloat();
    else if (isWord(t, "exponent")) r.exponent = in.parseFloat();
    else if (isWord(t, "metallic")) r.metallic = startsNumber(in.peek()) ? in.parseFloat() : 1.0;
    else in.error(t, "unexpected " + t.describe() + " in reflection");
  }
}

PovTexture SceneReader::readTexture(TokenStream& in, const PovTexture& start) {
  in.expect("{");
  return readTextureBody(in, start, "}");
}

PovTexture SceneReader::readTextureBody(TokenStream& in, const PovTexture& start,
                                        std::string_view closing) {
  PovTexture tex = start;
  if (const auto* item = use<TextureItem>(in.peek(), in)) {
    tex = item->texture;
    // Named after a plain identifier only: an array element's text is the array's name.
    const Token& id = in.next();
    tex.name = id.element ? std::string() : std::string(id.text());
  }
  if (!tex.mapped()) readTextureIdentifiers(in, tex);
  bool first = true;
  for (;;) {
    const Token t = in.next();
    if (t.is(closing)) return tex;
    const bool atStart = first;
    first = false;
    tex.name.clear();  // changed: no longer the declared texture itself
    PovTransform m;    // a transform moves the pigment and normal written before it
    // A map's pattern takes the modifiers written after it.
    if (tex.mapped() &&
        (readWarp(t, in, placementOf(tex.mapPattern.pattern), tex.mapPattern.transform) ||
         readPigmentModifier(t, in, tex.mapPattern)))
      continue;
    // Each block continues the texture's own (POV-Ray's Parse_Texture).
    if (isWord(t, "uv_mapping")) {
      if (!atStart) in.error(t, "'uv_mapping' must come first in a texture, as POV-Ray reads it");
      readUvTexture(t, in, tex, closing);
      return tex;
    }
    if (isWord(t, "material_map")) {
      readMaterialMap(t, in, tex);
      continue;
    }
    if (isWord(t, "pigment")) tex.pigment = readPigment(in, tex.pigment);
    else if (isWord(t, "normal")) tex.normal = readNormal(in, tex.normal ? &*tex.normal : nullptr);
    else if (isWord(t, "finish")) tex.finish = readFinish(in, tex.finish);
    else if (readTransform(t, in, m)) tex.transform(m);
    else if (readOldNormal(t, in, tex)) continue;
    else {
      if (isTexturePattern(t)) {
        if (readTextureMap(t, in, tex)) continue;
        return tex;
      }
      unreadInBlock(t, in);
      return tex;
    }
  }
}

// `texture { PIGMENT_ID NORMAL_ID FINISH_ID ... }`: POV-Ray 3.7's Parse_Texture still takes
// the identifiers of a plain texture's parts written bare before its blocks (POV-Ray 1's
// form), each replacing that part, with a warning that they belong in their blocks.
void SceneReader::readTextureIdentifiers(TokenStream& in, PovTexture& tex) {
  for (;;) {
    const Token& t = in.peek();
    std::string_view block;
    if (const auto* p = use<PigmentItem>(t, in)) {
      tex.pigment = p->pigment;
      block = "pigment";
    } else if (const auto* n = use<NormalItem>(t, in)) {
      tex.normal = n->normal;
      block = "normal";
    } else if (const auto* f = use<FinishItem>(t, in)) {
      tex.finish = f->finish;
      block = "finish";
    } else {
      return;
    }
    const Token id = in.next();
    tex.name.clear();
    warn(in, id.loc(),
         "found " + std::string(block) + " identifier '" + std::string(id.text()) +
             "' that should be in a '" + std::string(block) + "' statement (read as " +
             std::string(block) + " { " + std::string(id.text()) + " }, as POV-Ray reads it)");
  }
}

// `texture { uv_mapping BODY }`: POV-Ray reads the rest of the block as a new texture (from
// the #default) that the outer one evaluates at (u, v, 0): its pigment, or its map with the
// entries, placed by the transforms written in it. What came before is dropped.
void SceneReader::readUvTexture(const Token& t, TokenStream& in, PovTexture& tex,
                                std::string_view closing) {
  if (!tex.below.empty())
    keepError(in, t.loc(),
              "a uv-mapped texture cannot be layered (POV-Ray: \"Cannot layer over a "
              "patterned texture\")");
  tex = readTextureBody(in, defaultTexture(), closing);
  mapAtUv(tex, false);
}

// A texture read at (u, v, 0): its map's pattern (with the entries) or its pigment and normal,
// placed by the transforms they hold; a pigment or normal uv-mapped itself keeps its own (the
// later ones are its outer's, which its uv_mapping ignores). `bendInWorld`: an object's
// uv_mapping, whose textures POV-Ray shades at (u, v, 0) without a texture of its own around
// them (the world normal is bent); a texture's uv_mapping bends the normal in the space of
// the transforms after the texture.
void SceneReader::mapAtUv(PovTexture& tex, bool bendInWorld) {
  tex.moved = true;
  if (tex.mapped()) {
    tex.mapPattern.uv = true;
    tex.mapPattern.uvTransform = tex.mapPattern.transform;
    return;
  }
  if (!tex.pigment.uv) tex.pigment.uvTransform = tex.pigment.transform;
  tex.pigment.uv = true;
  if (!tex.normal) return;
  PovNormal& n = *tex.normal;
  if (!n.ownUv) n.uvTransform = n.transform;
  n.uv = true;
  n.bendInWorld = bendInWorld;
}

namespace {

// POV-Ray 3.1's layers: a filter in a layer over another acts as a transmit (POV-Ray keeps
// this for scenes of #version 3.1 and older, its Convert_Filter_To_Transmit): every
// colour's filter joins its transmit.
void filterToTransmit(FilterTransmit& ft) {
  ft.transmit += ft.filter;
  ft.filter = 0.0f;
}

void filterToTransmit(PovPigment& p) {
  p.transmit += p.filter;
  p.filter = 0.0f;
  for (PovColorMapEntry& e : p.map) {
    e.transmit += e.filter;
    e.filter = 0.0f;
  }
  if (auto* t = std::get_if<PatternTexture>(&p.pattern))
    for (ColorMapEntry& e : t->map.entries) filterToTransmit(e.ft);
  if (auto* c = std::get_if<CheckerTexture>(&p.pattern)) {
    filterToTransmit(c->ft1);
    filterToTransmit(c->ft2);
  }
  if (auto* h = std::get_if<HexagonTexture>(&p.pattern))
    for (FilterTransmit& ft : h->spec.ft) filterToTransmit(ft);
  if (auto* b = std::get_if<BrickTexture>(&p.pattern)) {
    filterToTransmit(b->spec.ft1);
    filterToTransmit(b->spec.ft2);
  }
}

}  // namespace

PovTexture SceneReader::layerOver(PovTexture under, PovTexture top, const SourceLoc& at,
                                  TokenStream& in) {
  if (under.mapped() || top.mapped())
    keepError(in, at,
              "a pattern of textures cannot be layered (POV-Ray: \"Cannot layer over a "
              "patterned texture\")");
  if (in.languageVersion() <= 3.1) {
    filterToTransmit(top.pigment);
    for (PovTexture& layer : top.below) filterToTransmit(layer.pigment);
  }
  return layered(std::move(under), std::move(top));
}

// `PATTERN texture_map { [v T] ... }` (T a texture's body or a declared texture), or a block
// pattern's list of textures: `checker texture { A } texture { B }` (hexagon: three).
bool SceneReader::readTextureMap(const Token& t, TokenStream& in, PovTexture& tex) {
  if (!tex.below.empty()) {
    refuseInBlock(t, in,
                  "a pattern of textures over a layered texture; Lucent's material maps are "
                  "not layers");
    return false;
  }
  PovPigment pattern;
  pattern.transform = tex.mapPattern.transform;
  const std::string_view w = t.text();
  const bool block = w == "checker" || w == "hexagon" || w == "brick";
  if (w == "tiles") {
    readTiles(t, in, tex);
    pattern.pattern = CheckerTexture{};
  } else if (w == "object") {
    pattern.pattern = objectPatternTexture(readObjectPatternObject(t, in), pattern.pattern);
    tex.mapEntries.clear();
    for (int cell = 0; cell < 2 && isWord(in.peek(), "texture"); ++cell) {
      in.next();
      tex.mapEntries.push_back({double(cell), readTexture(in, defaultTexture())});
      in.allow(",");
    }
    if (tex.mapEntries.size() < 2)
      keepError(in, t.loc(),
                "an object pattern of textures needs its two textures (outside, inside) in "
                "Lucent");
    in.expect("}");
  } else if (block && isWord(in.peek(), "texture")) {
    if (w == "checker") pattern.pattern = CheckerTexture{};
    else if (w == "hexagon") pattern.pattern = HexagonTexture{};
    else pattern.pattern = BrickTexture{};
    tex.mapEntries.clear();
    for (int cell = 0; cell < (w == "hexagon" ? 3 : 2) && isWord(in.peek(), "texture"); ++cell) {
      in.next();
      tex.mapEntries.push_back({double(cell), readTexture(in, defaultTexture())});
      in.allow(",");
    }
  } else if (w != "average" && (block || !readPatternKeyword(t, in, pattern))) {
    // A pattern Lucent lacks is refused as such; `tiles` and a block pattern without its
    // list of textures as a pattern of textures.
    if (block || !refusePattern(t, in))
      refuseInBlock(t, in,
                    "a pattern of textures that Lucent cannot read: it reads texture_map after a "
                    "pattern, and the texture lists of checker, hexagon and brick");
    return false;
  } else {
    // The pattern's own arguments are read; its modifiers and the map follow. An average
    // (of textures) takes only a placement, and weights in its map.
    const bool average = w == "average";
    if (average) pattern.pattern = AverageTexture{};
    tex.mapEntries.clear();
    for (;;) {
      const Token k = in.next();
      if (isWord(k, "texture_map")) {
        settlePavement(k, in, specOf(pattern.pattern));
        in.expect("{");
        for (;;) {
          const Token open = in.next();
          if (open.is("}")) break;
          if (!open.is("["))
            in.error(open, "'[' or '}' expected in a texture_map, not " + open.describe());
          const SourceLoc valueAt = in.peek().loc();
          const double at = entryValue(in, average);
          if (average && !(at > 0.0))
            keepError(in, valueAt,
                      "an average's weight must be above 0 (Lucent's averages take positive "
                      "weights)");
          tex.mapEntries.push_back({at, readTextureBody(in, defaultTexture(), "]")});
        }
        if (tex.mapEntries.empty()) in.error(k, "a texture_map needs at least one entry");
        break;
      }
      if (readWarp(k, in, placementOf(pattern.pattern), pattern.transform) ||
          readPigmentModifier(k, in, pattern))
        continue;
      PovTransform m;
      if (readTransform(k, in, m)) {
        pattern.transform = pattern.transform.then(m);
        continue;
      }
      in.error(k, "a texture_map expected after the pattern '" + std::string(w) + "', not " +
                      k.describe());
    }
  }
  tex.mapPattern = std::move(pattern);
  tex.name.clear();
  return true;
}

// `tiles { texture {..}... tile2 texture {..}... }`: POV-Ray's old checker of textures, the
// first textures (layered, as several texture blocks are) on the odd cells (its value 1),
// tile2's on the even ones (value 0, the cell [0, 1)³).
void SceneReader::readTiles(const Token& t, TokenStream& in, PovTexture& tex) {
  in.expect("{");
  auto textures = [&]() -> std::optional<PovTexture> {
    std::optional<PovTexture> all;
    while (isWord(in.peek(), "texture")) {
      const Token k = in.next();
      PovTexture one = readTexture(in, defaultTexture());
      all = all ? layerOver(std::move(*all), std::move(one), k.loc(), in) : std::move(one);
    }
    return all;
  };
  std::optional<PovTexture> first = textures();
  const Token tile2 = in.next();
  if (!isWord(tile2, "tile2"))
    in.error(tile2, "'tile2' expected in tiles, not " + tile2.describe());
  std::optional<PovTexture> second = textures();
  in.expect("}");
  if (!first) in.error(t, "the first texture is missing from tiles (POV-Ray's error)");
  if (!second) in.error(tile2, "tile2 needs a texture (POV-Ray would have none for its cells)");
  tex.mapEntries.clear();
  tex.mapEntries.push_back({0.0, std::move(*second)});
  tex.mapEntries.push_back({1.0, std::move(*first)});
}

// POV-Ray 1's normals written in the texture: `bumps 0.5`, `dents`, `ripples`, `waves`,
// `wrinkles` with their amount.
bool SceneReader::readOldNormal(const Token& t, TokenStream& in, PovTexture& tex) {
  static constexpr std::string_view kOld[] = {"bumps", "dents", "ripples", "waves", "wrinkles"};
  if (t.kind != TokenKind::Keyword ||
      std::find(std::begin(kOld), std::end(kOld), t.text()) == std::end(kOld) ||
      !startsNumber(in.peek()))
    return false;
  PovNormal n;
  for (const PatternTypeInfo& info : kPatternTypes)
    if (info.pov == t.text()) n.spec.pattern.type = info.type;
  n.spec.pattern.noiseGenerator = 0;  // the scene's global_settings noise_generator
  n.spec.depth = in.parseFloat();
  n.patterned = true;
  tex.normal = n;
  return true;
}

// A pattern keyword written directly in a texture: a texture_map's or a block pattern's
// of textures.
bool SceneReader::isTexturePattern(const Token& t) const {
  if (t.kind != TokenKind::Keyword) return false;
  const std::string_view w = t.text();
  for (const PatternTypeInfo& info : kPatternTypes)
    if (info.pov == w) return true;
  return w == "checker" || w == "hexagon" || w == "brick" || w == "tiles" || w == "average" ||
         isLackingPattern(t);
}

PovInterior SceneReader::readInterior(TokenStream& in, const PovInterior& start) {
  PovInterior i = start;
  in.expect("{");
  if (const auto* item = use<InteriorItem>(in.peek(), in)) {
    in.next();
    i = item->interior;
  }
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) return i;
    if (isWord(t, "ior")) i.ior = in.parseFloat();
    else if (isWord(t, "fade_distance")) i.fadeDistance = in.parseFloat();
    else if (isWord(t, "fade_power")) i.fadePower = in.parseFloat();
    else if (isWord(t, "fade_color") || isWord(t, "fade_colour")) i.fadeColor = readColour(in).rgb;
    else if (isWord(t, "refraction")) readRefraction(t, in);
    else if (t.kind == TokenKind::Keyword) {
      unsupported(t, in, true);
      if (startsNumber(in.peek())) in.parseFloat();  // caustics F, dispersion F
    } else in.error(t, "unexpected " + t.describe() + " in interior");
  }
}

// `material { [Identifier] texture { } interior { } }`; its transforms move its texture.
PovMaterial SceneReader::readMaterial(TokenStream& in) {
  PovMaterial m;
  in.expect("{");
  if (const auto* item = use<MaterialItem>(in.peek(), in)) {
    m = item->material;
    const Token& id = in.next();
    if (m.texture) m.texture->name = id.element ? std::string() : std::string(id.text());
  }
  int textures = 0;
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) return m;
    if (m.texture) m.texture->name.clear();
    PovTransform move;
    if (isWord(t, "texture")) {
      // A second texture is a layer over the first.
      PovTexture read = readTexture(in, defaultTexture());
      if (textures++ > 0 && m.texture)
        m.texture = layerOver(std::move(*m.texture), std::move(read), t.loc(), in);
      else m.texture = std::move(read);
    } else if (isWord(t, "interior_texture")) {
      m.interiorTexture = readTexture(in, defaultTexture());
    } else if (isWord(t, "interior")) {
      m.interior = readInterior(in, m.interior ? *m.interior : PovInterior{});
    } else if (readTransform(t, in, move)) {
      if (m.texture) m.texture->transform(move);
      if (m.interiorTexture) m.interiorTexture->transform(move);
    } else {
      unreadInBlock(t, in);
      return m;
    }
  }
}

}  // namespace lucent::sdl
