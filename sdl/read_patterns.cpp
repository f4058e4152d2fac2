// Pattern pigments and their modifiers: the patterns of Lucent's table (scenegraph/pattern.h)
// with their colour maps, the block patterns checker, hexagon and brick with their colours,
// and the modifiers a pattern takes in a pigment or a normal, with POV-Ray 3.7's defaults
// (its default colour maps, pattern.cpp; its block patterns' colours).
#include "pov_space.h"
#include "read_support.h"
#include "scene_reader.h"

#include "lang/expression.h"
#include "scenegraph/pavement.h"

#include <algorithm>
#include <string>

namespace lucent::sdl {

namespace {

// POV-Ray's default colour map of a pattern pigment written without one; the patterns
// without a row here take black to white, which is Lucent's empty map.
std::vector<PovColorMapEntry> defaultColourMap(PatternType type) {
  auto rgb = [](double at, float r, float g, float b) {
    return PovColorMapEntry{at, Color(r, g, b), 0.0f, 0.0f};
  };
  switch (type) {
    case PatternType::agate:
      return {rgb(0.0, 1.0f, 1.0f, 1.0f), rgb(0.5, 0.95f, 0.75f, 0.5f), rgb(0.5, 0.9f, 0.7f, 0.5f),
              rgb(0.6, 0.9f, 0.7f, 0.4f), rgb(0.6, 1.0f, 0.7f, 0.4f),   rgb(1.0, 0.6f, 0.3f, 0.0f)};
    case PatternType::bozo:
      return {rgb(0.4, 1.0f, 1.0f, 1.0f), rgb(0.4, 0.0f, 1.0f, 0.0f), rgb(0.6, 0.0f, 1.0f, 0.0f),
              rgb(0.6, 0.0f, 0.0f, 1.0f), rgb(0.8, 0.0f, 0.0f, 1.0f), rgb(0.8, 1.0f, 0.0f, 0.0f)};
    case PatternType::mandel:  // (julia and magnet take the grey map)
      return {rgb(0.001, 0.0f, 0.0f, 0.0f), rgb(0.001, 0.0f, 1.0f, 1.0f),
              rgb(0.012, 1.0f, 1.0f, 0.0f), rgb(0.015, 1.0f, 0.0f, 1.0f),
              rgb(0.1, 0.0f, 1.0f, 1.0f)};
    case PatternType::marble:
      return {rgb(0.0, 0.9f, 0.8f, 0.8f), rgb(0.9, 0.9f, 0.08f, 0.08f), rgb(0.9, 0.0f, 0.0f, 0.0f)};
    case PatternType::radial:
      return {rgb(0.0, 0.0f, 1.0f, 1.0f), rgb(0.333, 1.0f, 1.0f, 0.0f),
              rgb(0.666, 1.0f, 0.0f, 1.0f), rgb(1.0, 0.0f, 1.0f, 1.0f)};
    case PatternType::wood:
      return {rgb(0.6, 0.666f, 0.312f, 0.2f), rgb(0.6, 0.4f, 0.1333f, 0.066f)};
    default:
      return {};
  }
}

// POV-Ray's patterns Lucent does not have (as pigments or normals).
constexpr std::string_view kPatternsLucentLacks[] = {"aoi",       "cubic",  "density_file",
                                                     "potential", "square", "triangular"};

const PatternTypeInfo* patternType(const Token& t) {
  if (t.kind != TokenKind::Keyword) return nullptr;
  for (const PatternTypeInfo& info : kPatternTypes)
    if (info.pov == t.text()) return &info;
  return nullptr;
}

PovColorMapEntry entryOf(double at, const PovColour& c) {
  return {at, c.rgb, c.filter, c.transmit};
}

std::string lucentPatternNames() {
  std::string names;
  for (const PatternTypeInfo& info : kPatternTypes) {
    if (!info.colour) continue;
    names += (names.empty() ? "" : ", ") + std::string(info.pov);
  }
  return names + ", checker, hexagon, brick";
}

// POV-Ray keeps pavement's numbers as bytes (unsigned char).
int pavementByte(TokenStream& in) { return static_cast<int>(in.parseFloat()) & 0xff; }

// pavement's number_of_sides, number_of_tiles, pattern, exterior, interior and form (true),
// checked when its block ends (settlePavement).
bool readPavementModifier(std::string_view w, TokenStream& in, PatternSpec& s) {
  if (s.type != PatternType::pavement) return false;
  PavementParams& v = s.pavement;
  if (w == "number_of_sides") v.sides = pavementByte(in);
  else if (w == "number_of_tiles") v.tiles = pavementByte(in);
  else if (w == "pattern") v.number = pavementByte(in);
  else if (w == "exterior") v.exterior = pavementByte(in);
  else if (w == "interior") v.interior = pavementByte(in);
  else if (w == "form") v.form = pavementByte(in);
  else return false;
  return true;
}

// crackle's form <a, b, c>, metric M (a vector in old scenes: its x counts), offset O and
// solid.
void readCrackleModifier(std::string_view w, TokenStream& in, CrackleParams& c) {
  if (w == "form") c.form = toVec3(in.parseVector());
  else if (w == "metric") c.metric = in.parseVector()[0];
  else if (w == "offset") c.offset = in.parseFloat();
  else c.solid = true;
}

}  // namespace

// What follows a pattern's keyword in POV-Ray (parstxtr.cpp, Parse_Pattern), with its
// defaults: gradient's axis, the spirals' arms, the fractals' constant and iterations,
// quilted's frequency 0. The pattern is evaluated in POV-Ray's space
// (SceneReader::addMaterial), so these are kept as written.
// slope's `<dir>` or `{ [point_at] <v> [, low, high] [altitude <v> [, low, high]] }`: the
// direction and point in Lucent's world space (the normal's), the altitude in the
// pattern's (POV-Ray's) space.
void readSlope(const Token& t, TokenStream& in, SlopeParams& p) {
  p = SlopeParams{};
  if (!in.allow("{")) {
    p.direction = lucentFromPov(toVec3(in.parseVector()));
    return;
  }
  if (isWord(in.peek(), "point_at")) {
    in.next();
    p.pointAt = true;
  }
  auto range = [&](double& low, double& high) {
    in.allow(",");
    if (startsNumber(in.peek())) low = in.parseFloat();
    in.allow(",");
    if (startsNumber(in.peek())) high = in.parseFloat();
  };
  p.direction = lucentFromPov(toVec3(in.parseVector()));
  range(p.low, p.high);
  if (isWord(in.peek(), "altitude")) {
    const Token a = in.next();
    if (p.pointAt) in.error(a, "'altitude' cannot be used with 'point_at' in slope (as POV-Ray)");
    p.altitude = toVec3(in.parseVector());
    range(p.altitudeLow, p.altitudeHigh);
  }
  in.expect("}");
  if (!p.pointAt && p.direction == Vec3(0.0) && p.altitude == Vec3(0.0))
    in.error(t, "slope: zero length for both slope and altitude (POV-Ray's error)");
}

void settlePavement(const Token& end, TokenStream& in, PatternSpec* s) {
  if (!s || s->type != PatternType::pavement) return;
  PavementParams& v = s->pavement;
  v.interior %= 3;
  v.exterior %= 3;
  if (v.sides != 3 && v.sides != 4 && v.sides != 6)
    in.error(end, "number_of_sides of pavement must be 3, 4 or 6 (POV-Ray's error), got " +
                      std::to_string(v.sides));
  const int maxTiles = v.sides == 6 ? 5 : 6;
  if (v.tiles < 1 || v.tiles > maxTiles)
    in.error(end, "number_of_tiles of pavement must be between 1 and " + std::to_string(maxTiles) +
                      " (POV-Ray's error), got " + std::to_string(v.tiles));
  const int count = pavementArrangements(v.sides, v.tiles);
  if (v.number < 1 || v.number > count)
    in.error(end, "pattern value for pavement is out of range (POV-Ray's error): " +
                      std::to_string(v.tiles) + " tiles of " + std::to_string(v.sides) +
                      " sides have patterns 1 to " + std::to_string(count) + ", got " +
                      std::to_string(v.number));
  v.form %= v.sides == 4 ? 4 : 3;
}

void readPatternArguments(const Token& t, TokenStream& in, PatternSpec& s) {
  s.frequency = defaultFrequency(s.type);
  if (s.type == PatternType::slope) readSlope(t, in, s.slope);
  if (s.type == PatternType::gradient) {
    // Normalised here as the XML language's axis is (POV-Ray normalises it too): the same
    // pattern, written back by `convert` as it reads back.
    s.axis = toVec3(in.parseVector());
    if (glm::length(s.axis) > 0.0) s.axis = glm::normalize(s.axis);
  }
  if (s.type == PatternType::spiral1 || s.type == PatternType::spiral2)
    s.arms = static_cast<int>(in.parseFloat());
  if (s.type == PatternType::tiling) {
    // POV-Ray keeps the number as an unsigned char, then allows 1 to 27.
    const double n = in.parseFloat();
    s.tiling = static_cast<int>(n) & 0xff;
    if (s.tiling < 1 || s.tiling > 27)
      in.error(t,
               "Tiling number must be between 1 and 27 (POV-Ray's error), got " + formatNumber(n));
  }
  if (!isFractal(s.type)) return;
  FractalParams& f = s.fractal;
  f = FractalParams{};
  auto readC = [&] {
    const Vec3 c = toVec3(in.parseVector());
    f.cReal = c.x;
    f.cImaginary = c.y;
    in.allow(",");
  };
  if (s.type == PatternType::julia) readC();
  if (s.type == PatternType::magnet) {
    f.power = 2;  // unused: magnet takes no exponent
    const double type = in.parseFloat();
    const Token form = in.next();
    if (!isWord(form, "mandel") && !isWord(form, "julia"))
      in.error(form, "'mandel' or 'julia' expected after 'magnet " + formatNumber(type) +
                         "', not " + form.describe());
    if (static_cast<int>(type) != 1 && static_cast<int>(type) != 2)
      in.error(t, "magnet's type must be 1 or 2, got " + formatNumber(type));
    f.magnetType = static_cast<int>(type);
    f.juliaForm = isWord(form, "julia");
    if (f.juliaForm) readC();
  }
  const double iterations = in.parseFloat();
  if (!(iterations >= 0 && iterations <= 100000000))
    in.error(t, "a fractal pattern's iterations must be from 0 to 100000000, got " +
                    formatNumber(iterations));
  f.iterations = static_cast<int>(iterations);
}

// A pattern keyword, or a modifier of the pattern a pigment has; false if `t` is neither.
bool SceneReader::readPatternKeyword(const Token& t, TokenStream& in, PovPigment& p) {
  if (isWord(t, "object")) {
    readObjectPigment(t, in, p);
    return true;
  }
  if (const PatternTypeInfo* info = patternType(t); info && info->colour) {
    PatternTexture tex;
    if (const PatternPlacement* was = placementOf(p.pattern)) tex.pattern.placement = *was;
    tex.pattern.type = info->type;
    tex.pattern.noiseGenerator = 0;  // the scene's global_settings noise_generator
    readPatternArguments(t, in, tex.pattern);
    if (tex.pattern.type == PatternType::function) tex.pattern.function = readPatternFunction(in);
    if (tex.pattern.type == PatternType::pigment) tex.pattern.pigment = readPatternPigment(in);
    if (tex.pattern.type == PatternType::image) tex.pattern.image = readImagePattern(in);
    p.pattern = tex;
    p.map.clear();
    return true;
  }
  const std::string_view w = t.kind == TokenKind::Keyword ? t.text() : "";
  if (w == "image_map") {
    readImageMap(t, in, p);
    return true;
  }
  if (w == "checker" || w == "hexagon" || w == "brick") {
    // POV-Ray's colours for those not written (pattern.cpp's default maps).
    const PatternPlacement was =
        placementOf(p.pattern) ? *placementOf(p.pattern) : PatternPlacement{};
    p.map.clear();
    if (p.blockValue) {  // POV-Ray's: the cell number as it is, unless a frequency is given
      auto value = std::make_shared<PatternSpec>(*p.blockValue);
      value->frequency = 0.0;
      p.blockValue = std::move(value);
    }
    if (w == "checker") {
      CheckerTexture c;
      c.placement = was;
      p.pattern = c;
      p.map = {{0, Color(0.0f, 0.0f, 1.0f)}, {1, Color(0.0f, 1.0f, 0.0f)}};
    } else if (w == "hexagon") {
      HexagonTexture h;
      h.placement = was;
      for (int i = 0; i < 3; ++i) p.map.push_back({double(i), h.spec.colors[i]});
      p.pattern = h;
    } else {
      BrickTexture b;
      b.placement = was;
      p.map = {{0, b.spec.color1}, {1, b.spec.color2}};
      p.pattern = b;
    }
    p.mapLoc = t.loc();
    for (size_t i = 0; i < p.map.size(); ++i) {
      const Token& next = in.peek();
      auto isListEntry = [](const Token& k) {
        return isWord(k, "pigment") || isWord(k, "texture") || isWord(k, "normal");
      };
      if (isWord(next, "pigment") && i == 0) {
        // POV-Ray's list of pigments instead of the colours.
        readBlockPigments(in, p, p.map.size());
        return true;
      }
      if (isListEntry(next)) {
        const Token list = in.next();
        keepError(in, list.loc(),
                  "'" + std::string(list.text()) + "' is not supported by Lucent (lists of " +
                      std::string(list.text()) + "s in block patterns; " + std::string(w) +
                      " takes colours or pigments in Lucent)");
        // The list's entries skipped, each a block; the pigment's own '}' is left to it.
        for (;;) {
          in.expect("{");
          skipToClose(in, 1);
          in.allow(",");
          if (!isListEntry(in.peek())) break;
          in.next();
        }
        return true;
      }
      if (!isColourStart(next)) break;
      p.map[i] = entryOf(double(i), readColour(in));
      in.allow(",");
    }
    return true;
  }
  if (w == "color_map" || w == "colour_map") {
    if (const PatternSpec* s = specOf(p.pattern); s && s->type == PatternType::object)
      in.error(t,
               "a color_map cannot be used with an object pattern (POV-Ray's rule: its "
               "colours are its list of two)");
    // POV-Ray's Parse_Pattern refuses it on block patterns, image maps and averages.
    if (p.block() || std::holds_alternative<ImageTexture>(p.pattern) ||
        std::holds_alternative<AverageTexture>(p.pattern))
      in.error(t, "Cannot use color_map with this pattern type. (POV-Ray's error)");
    SourceLoc loc = t.loc();
    p.map = readColorMap(in, loc);
    p.mapLoc = loc;
    return true;
  }
  if (w == "quick_color" || w == "quick_colour") {
    readColour(in);  // POV-Ray's colour for quick previews: no effect on the image
    return true;
  }
  if (w == "brick_size" || w == "mortar") {
    auto* brick = std::get_if<BrickTexture>(&p.pattern);
    if (!brick) in.error(t, "'" + std::string(w) + "' is for a brick pattern");
    if (w == "brick_size") {
      const Vec3 size = toVec3(in.parseVector());
      if (!(size.x > 0 && size.y > 0 && size.z > 0))
        in.error(t, "the brick's size must be positive in x, y and z");
      brick->spec.size = size;
    } else {
      brick->spec.mortar = in.parseFloat();
    }
    return true;
  }
  return readPigmentModifier(t, in, p);
}

// A pigment's pattern modifiers; a block pattern's frequency, phase and wave go to its
// blockValue.
bool SceneReader::readPigmentModifier(const Token& t, TokenStream& in, PovPigment& p) {
  if (!p.block()) return readPatternModifier(t, in, specOf(p.pattern), placementOf(p.pattern));
  PatternSpec value = p.blockValueSpec();
  if (!readPatternModifier(t, in, &value, placementOf(p.pattern))) return false;
  p.blockValue = std::make_shared<const PatternSpec>(std::move(value));
  return true;
}

// The modifiers of a pattern (null `spec`: a block pattern, which takes none of the value's;
// null `placement`: a solid colour, which modifiers leave as it is).
bool SceneReader::readPatternModifier(const Token& t, TokenStream& in, PatternSpec* spec,
                                      PatternPlacement* placement) {
  if (t.kind != TokenKind::Keyword) return false;
  const std::string_view w = t.text();
  PatternSpec ignoredSpec;
  PatternPlacement ignoredPlacement;
  PatternSpec& s = spec ? *spec : ignoredSpec;
  PatternPlacement& place = placement ? *placement : ignoredPlacement;
  if (w == "turbulence") {
    place.turbulence = toVec3(in.parseVector());
  } else if (w == "octaves") {
    // POV-Ray clamps them to 1..10.
    place.octaves = std::clamp(static_cast<int>(in.parseFloat()), 1, 10);
  } else if (w == "omega") {
    place.omega = in.parseFloat();
  } else if (w == "lambda") {
    place.lambda = in.parseFloat();
  } else if (w == "frequency") {
    s.frequency = in.parseFloat();
  } else if (w == "phase") {
    s.phase = in.parseFloat();
  } else if (w == "ramp_wave") {
    s.wave = WaveShape::ramp;
  } else if (w == "sine_wave") {
    s.wave = WaveShape::sine;
  } else if (w == "triangle_wave") {
    s.wave = WaveShape::triangle;
  } else if (w == "scallop_wave") {
    s.wave = WaveShape::scallop;
  } else if (w == "cubic_wave") {
    s.wave = WaveShape::cubic;
  } else if (w == "poly_wave") {
    s.wave = WaveShape::poly;
    if (startsNumber(in.peek())) s.exponent = in.parseFloat();
  } else if (w == "noise_generator") {
    const double g = in.parseFloat();
    if (g < 1 || g > 3) in.error(t, "noise_generator must be 1, 2 or 3");
    s.noiseGenerator = static_cast<int>(g);
  } else if (w == "coords" || w == "size") {
    // facets' (POV-Ray: "Keyword 'coords' [or 'size'] can only be used in a facets pattern").
    if (s.type != PatternType::facets) in.error(t, "'" + std::string(w) + "' is for facets");
    (w == "size" ? s.facets.size : s.facets.coords) = in.parseFloat();
  } else if (spec && readPavementModifier(w, in, s)) {
  } else if (w == "metric" && s.type == PatternType::facets) {
    s.facets.metric = in.parseVector()[0];  // a vector for old scenes: its x counts
  } else if (w == "form" || w == "metric" || w == "offset" || w == "solid") {
    if (spec && s.type != PatternType::crackle)  // POV-Ray's Only_In
      in.error(t, "'" + std::string(w) + "' is for crackle");
    readCrackleModifier(w, in, s.crackle);
  } else if (w == "control0" || w == "control1") {
    if (s.type != PatternType::quilted) in.error(t, "'" + std::string(w) + "' is for quilted");
    (w == "control0" ? s.quilted.control0 : s.quilted.control1) = in.parseFloat();
  } else if (w == "exterior" || w == "interior") {
    readFractalColouring(t, in, s);
  } else if (w == "exponent") {
    if (s.type != PatternType::mandel && s.type != PatternType::julia)
      in.error(t, "'exponent' is for mandel and julia");
    const double power = in.parseFloat();
    s.fractal.power = static_cast<int>(power);
    // POV-Ray warns and takes 2 outside 2..33.
    if (s.fractal.power < 2 || s.fractal.power > 33) {
      warn(in, t.loc(),
           "the fractal exponent " + formatNumber(power) + " is outside 2..33; POV-Ray uses 2");
      s.fractal.power = 2;
    }
  } else if (w == "agate_turb") {
    s.agateTurb = in.parseFloat();
  } else {
    return false;
  }
  return true;
}

// `exterior TYPE, FACTOR` or `interior TYPE, FACTOR` of mandel, julia and magnet.
void SceneReader::readFractalColouring(const Token& t, TokenStream& in, PatternSpec& s) {
  const bool exterior = isWord(t, "exterior");
  if (!isFractal(s.type))
    in.error(t, "'" + std::string(t.text()) + "' is for mandel, julia and magnet");
  const double type = in.parseFloat();
  in.allow(",");
  const double factor = in.parseFloat();
  const int maxType = exterior ? 8 : 6;
  const int kind = static_cast<int>(type);
  if (kind < 0 || kind > maxType)
    in.error(t, std::string(exterior ? "exterior" : "interior") + " types are 0 to " +
                    std::to_string(maxType) + ", got " + formatNumber(type));
  // POV-Ray divides by the factor and takes the iterations modulo it (crashing on 0).
  if (exterior && kind == 7 && !(factor >= 1))
    in.error(t, "exterior type 7 needs a factor >= 1, got " + formatNumber(factor));
  if (exterior && kind == 8 && !(factor > 0))
    in.error(t, "exterior type 8 needs a factor > 0, got " + formatNumber(factor));
  (exterior ? s.fractal.exterior : s.fractal.interior) = {kind, factor};
}

// `color_map { [Identifier] [at colour] ... }`, the '{' next; old maps' `[a, b color C1
// color C2]` give two entries. `loc` becomes the declared map's when it names one.
std::vector<PovColorMapEntry> SceneReader::readColorMap(TokenStream& in, SourceLoc& loc) {
  std::vector<PovColorMapEntry> map;
  in.expect("{");
  if (const auto* item = use<ColorMapItem>(in.peek(), in)) {
    in.next();
    in.expect("}");
    loc = item->loc;
    return item->map;
  }
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) break;
    if (isWord(t, "blend_mode") || isWord(t, "blend_gamma")) {
      keepError(in, t.loc(),
                "'" + std::string(t.text()) +
                    "' is not supported by Lucent (its colour maps blend linearly)");
      in.parseFloat();
      continue;
    }
    if (!t.is("[")) in.error(t, "'[' or '}' expected in a colour map, not " + t.describe());
    const double at = in.parseFloat();
    in.allow(",");
    const Token& next = in.peek();
    const Value* v = next.kind == TokenKind::Identifier ? next.value() : nullptr;
    if (next.kind == TokenKind::Number || (v && v->type == ValueType::Float)) {
      const double second = in.parseFloat();
      map.push_back(entryOf(at, readColour(in)));
      map.push_back(entryOf(second, readColour(in)));
    } else {
      map.push_back(entryOf(at, readColour(in)));
    }
    in.expect("]");
  }
  if (map.empty()) in.error(loc, "a colour map needs at least one colour");
  // POV-Ray drops an entry equal to the one before it (old maps repeat their ends).
  auto same = [](const PovColorMapEntry& a, const PovColorMapEntry& b) {
    return a.at == b.at && a.color == b.color && a.filter == b.filter && a.transmit == b.transmit;
  };
  map.erase(std::unique(map.begin(), map.end(), same), map.end());
  return map;
}

namespace {

// The colour (and filter and transmit) a map blends at v between its entries a and b.
PovColorMapEntry blendAt(const PovColorMapEntry& a, const PovColorMapEntry& b, double v) {
  const float w = static_cast<float>((v - a.at) / (b.at - a.at));
  PovColorMapEntry e;
  e.at = v;
  e.color = a.color + (b.color - a.color) * w;
  e.filter = a.filter + (b.filter - a.filter) * w;
  e.transmit = a.transmit + (b.transmit - a.transmit) * w;
  return e;
}

// The colour an ascending map gives value v, as POV-Ray's Search_Blend_Map and its linear
// blend: the last entry at or above the last value, the first entry at or below the first,
// else the blend of the two entries around v (the later one where v is on an entry).
PovColorMapEntry colourAt(const std::vector<PovColorMapEntry>& map, double v) {
  if (v >= map.back().at) return map.back();
  size_t c = 0;
  while (v > map[c].at) ++c;
  if (c == 0 || v == map[c].at) return map[c];
  return blendAt(map[c - 1], map[c], v);
}

}  // namespace

// A colour map whose entries are not in ascending order (woods.inc's T_Wood32), as the
// ascending map that gives every value the colour POV-Ray gives it. POV-Ray's search takes
// the last entry at or above the last entry's value; below that, the first entry whose
// value is at or above v and the one just before it in the list, blended linearly (its
// BlendMap::Search). So entry i is reached for v in (the highest value before it, its own],
// blended from entry i - 1 wherever that lies: a straight line, which two ascending
// entries at the ends of that stretch hold exactly. An ascending map is returned as it is.
std::vector<PovColorMapEntry> ascendingMap(const std::vector<PovColorMapEntry>& map) {
  if (std::is_sorted(
          map.begin(), map.end(),
          [](const PovColorMapEntry& a, const PovColorMapEntry& b) { return a.at < b.at; }))
    return map;
  const double last = map.back().at;
  std::vector<PovColorMapEntry> out;
  double highest = map.front().at;
  out.push_back(map.front());  // up to its value (or the last entry's, if that is lower)
  out.back().at = std::min(highest, last);
  for (size_t i = 1; i < map.size(); ++i) {
    const double from = highest, to = std::min(map[i].at, last);
    if (map[i].at > highest && from < to) {
      out.push_back(blendAt(map[i - 1], map[i], from));
      out.push_back(to == map[i].at ? map[i] : blendAt(map[i - 1], map[i], to));
    }
    highest = std::max(highest, map[i].at);
  }
  out.push_back(map.back());  // from the last entry's value up
  return out;
}

// An ascending map whose entries lie outside [0, 1] (stones.inc's maps end at 1.001), as
// the map of entries within [0, 1] that gives every pattern value (all lie in [0, 1]) the
// same colour: the entries beyond an end replaced by the blend at that end, or, when every
// entry is beyond it, by the colour the values take there (the nearest entry's).
std::vector<PovColorMapEntry> unitMap(const std::vector<PovColorMapEntry>& map) {
  std::vector<PovColorMapEntry> out;
  for (size_t i = 0; i < map.size(); ++i) {
    const PovColorMapEntry& e = map[i];
    if (e.at < 0.0) {
      // Kept only as the blend at 0 towards the next entry, if that one is at 0 or above.
      if (i + 1 < map.size() && map[i + 1].at > 0.0) out.push_back(blendAt(e, map[i + 1], 0.0));
      else if (i + 1 == map.size()) out.push_back({0.0, e.color, e.filter, e.transmit});
      continue;
    }
    if (e.at > 1.0) {
      if (out.empty()) out.push_back({1.0, e.color, e.filter, e.transmit});
      else if (i > 0 && map[i - 1].at < 1.0) out.push_back(blendAt(map[i - 1], e, 1.0));
      continue;
    }
    out.push_back(e);
  }
  return out;
}

namespace {

// The texture blends whole pigments (a pigment map, a block pattern's list, an average):
// it has no colours of its own.
bool textureHoldsPigments(const Texture& t) {
  if (const auto* p = std::get_if<PatternTexture>(&t)) return !p->pigments.empty();
  if (const auto* c = std::get_if<CheckerTexture>(&t)) return !c->pigments.empty();
  if (const auto* h = std::get_if<HexagonTexture>(&t)) return !h->pigments.empty();
  if (const auto* b = std::get_if<BrickTexture>(&t)) return !b->pigments.empty();
  if (const auto* a = std::get_if<AverageTexture>(&t)) return !a->entries.empty();
  return false;
}

}  // namespace

// The colours of a pattern pigment, from its map as written (or POV-Ray's default map),
// with their filter and transmit. A map whose every entry has one transmit and no filter
// keeps it as the pigment's (the material's constant transmission, which costs nothing
// per hit); any other filter or transmit goes with each colour (a see-through texture).
void SceneReader::resolvePigmentColours(PovPigment& p, TokenStream& in, bool nested) {
  if (!p.patterned()) return;
  if (std::holds_alternative<AverageTexture>(p.pattern) && !textureHoldsPigments(p.pattern))
    keepError(in, p.mapLoc, "'average' needs a pigment_map (the pigments it averages)");
  const int cells = std::holds_alternative<HexagonTexture>(p.pattern) ? 3 : 2;
  const bool block = std::holds_alternative<CheckerTexture>(p.pattern) ||
                     std::holds_alternative<HexagonTexture>(p.pattern) ||
                     std::holds_alternative<BrickTexture>(p.pattern);
  if (textureHoldsPigments(p.pattern) || std::holds_alternative<AverageTexture>(p.pattern)) {
    if (block && !blockValuesUnchanged(p.blockValueSpec(), cells))
      keepError(in, p.mapLoc,
                "frequency, phase or a wave on a block pattern's list of pigments is not "
                "supported by Lucent (POV-Ray blends the listed pigments by the changed cell "
                "number)");
    p.filter = p.transmit = 0.0f;  // the entries' own
    return;
  }
  const PatternSpec* spec = specOf(p.pattern);
  std::vector<PovColorMapEntry> map = p.map.empty() && spec ? defaultColourMap(spec->type) : p.map;
  p.filter = p.transmit = 0.0f;
  if (!map.empty()) {
    const PovColorMapEntry& first = map.front();
    const bool uniform = std::all_of(map.begin(), map.end(), [&](const PovColorMapEntry& e) {
      return e.filter == first.filter && e.transmit == first.transmit;
    });
    // (Not for a pigment inside a map or a list: its colours are its texture's alone.)
    if (uniform && first.filter == 0.0f && !nested) {
      p.transmit = first.transmit;
      for (PovColorMapEntry& e : map) e.transmit = 0.0f;
    }
    map = ascendingMap(map);
  }
  // A block pattern's cell i takes the colour its list or colour map gives the cell's number
  // after the frequency, phase and wave (entry i of a list; a colour map read at i).
  auto cell = [&](size_t i) {
    return colourAt(map, blockCellValue(p.blockValueSpec(), static_cast<int>(i)));
  };
  auto colour = [&](size_t i) { return cell(i).color; };
  auto ft = [&](size_t i) {
    const PovColorMapEntry e = cell(i);
    return FilterTransmit{e.filter, e.transmit};
  };
  if (auto* t = std::get_if<PatternTexture>(&p.pattern)) {
    t->map.entries.clear();
    // (A block pattern's "map" holds its colours by index, 0, 1, 2: kept as they are.)
    for (const PovColorMapEntry& e : unitMap(map))
      t->map.entries.push_back({e.at, e.color, {e.filter, e.transmit}});
  } else if (auto* c = std::get_if<CheckerTexture>(&p.pattern)) {
    c->color1 = colour(0);
    c->color2 = colour(1);
    c->ft1 = ft(0);
    c->ft2 = ft(1);
  } else if (auto* h = std::get_if<HexagonTexture>(&p.pattern)) {
    for (size_t i = 0; i < 3; ++i) {
      h->spec.colors[i] = colour(i);
      h->spec.ft[i] = ft(i);
    }
  } else if (auto* b = std::get_if<BrickTexture>(&p.pattern)) {
    b->spec.color1 = colour(0);
    b->spec.color2 = colour(1);
    b->spec.ft1 = ft(0);
    b->spec.ft2 = ft(1);
  }
}

bool SceneReader::isLackingPattern(const Token& t) {
  return t.kind == TokenKind::Keyword &&
         std::find(std::begin(kPatternsLucentLacks), std::end(kPatternsLucentLacks), t.text()) !=
             std::end(kPatternsLucentLacks);
}

// A pattern Lucent lacks, named in a pigment or a normal: refused, the block skipped (in
// a map's entry, `inEntry`, the caller skips the entry).
bool SceneReader::refusePattern(const Token& t, TokenStream& in, bool inEntry) {
  if (t.kind != TokenKind::Keyword) return false;
  const std::string_view w = t.text();
  auto refuseInBlock = [&](const Token& k, TokenStream& s, const std::string& why) {
    if (!inEntry) return SceneReader::refuseInBlock(k, s, why);
    keepError(s, k.loc(),
              "'" + std::string(k.text()) + "' is not supported by Lucent (" + why + ")");
  };
  if (const PatternTypeInfo* info = patternType(t); info && !info->colour) {
    refuseInBlock(t, in,
                  "as a colour pattern; Lucent's " + std::string(w) + " is a normal pattern");
    return true;
  }
  if (!isLackingPattern(t)) return false;
  refuseInBlock(t, in, "a pattern Lucent does not have; its patterns are " + lucentPatternNames());
  return true;
}

}  // namespace lucent::sdl
