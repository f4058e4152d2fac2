// The contract's colour patterns and normal perturbations: <pattern type> with its
// <color-map>, <hexagon>, <brick> (textures of a <material>), <normal type depth> and
// <bump-map src depth>.
// Every pattern element takes the same placement attributes: transform, turbulence,
// octaves, omega, lambda, and (for value patterns) frequency, phase, wave and exponent.
#include "pattern_parser.h"

#include "element_input.h"
#include "expression.h"
#include "images/image_values_file.h"
#include "normal_map_parser.h"
#include "povray_names.h"
#include "scenegraph/image_pattern.h"
#include "scenegraph/object_pattern.h"
#include "texture_map_parser.h"
#include "texture_parser.h"
#include "warp_parser.h"

#include "scenegraph/pavement.h"

#include <cmath>

namespace lucent {

namespace {

// The names of the pattern table (scenegraph/pattern.h): every colour pattern, then (for a
// normal, which takes the slope of any colour pattern) those only a normal takes.
std::vector<std::pair<std::string_view, PatternType>> patternNames(bool colourOnly) {
  std::vector<std::pair<std::string_view, PatternType>> names;
  for (bool colour : {true, false})
    for (const PatternTypeInfo& t : kPatternTypes)
      if (t.colour == colour && (colour || !colourOnly)) names.emplace_back(t.name, t.type);
  return names;
}

const std::vector<std::pair<std::string_view, WaveShape>> kWaves{
    {"ramp", WaveShape::ramp},       {"sine", WaveShape::sine},   {"triangle", WaveShape::triangle},
    {"scallop", WaveShape::scallop}, {"cubic", WaveShape::cubic}, {"poly", WaveShape::poly}};

// The names of the projections and interpolations (POV-Ray's map_type and interpolate).
const std::vector<std::pair<std::string_view, ImageProjection>> kProjections = {
    {"uv", ImageProjection::uv},
    {"planar", ImageProjection::planar},
    {"spherical", ImageProjection::spherical},
    {"cylindrical", ImageProjection::cylindrical},
    {"torus", ImageProjection::torus}};
const std::vector<std::pair<std::string_view, ImageInterpolation>> kInterpolations = {
    {"none", ImageInterpolation::none},
    {"bilinear", ImageInterpolation::bilinear},
    {"bicubic", ImageInterpolation::bicubic},
    {"normalized", ImageInterpolation::normalized}};

const std::vector<std::string_view> kPlacementAttributes{"transform", "turbulence", "octaves",
                                                         "omega",     "lambda",     "mapping"};
const std::vector<std::string_view> kValueAttributes{"type",
                                                     "axis",
                                                     "arms",
                                                     "frequency",
                                                     "phase",
                                                     "wave",
                                                     "exponent",
                                                     "noise-generator",
                                                     "control0",
                                                     "control1",
                                                     "iterations",
                                                     "power",
                                                     "c",
                                                     "form",
                                                     "magnet-type",
                                                     "exterior",
                                                     "interior",
                                                     "agate-turb",
                                                     "sources",
                                                     "function",
                                                     "direction",
                                                     "point-at",
                                                     "slope-range",
                                                     "altitude",
                                                     "altitude-range",
                                                     "tiling",
                                                     "metric",
                                                     "offset",
                                                     "solid",
                                                     "size",
                                                     "coords",
                                                     "sides",
                                                     "tiles",
                                                     "pavement",
                                                     "exterior-corners",
                                                     "interior-corners",
                                                     "pavement-form",
                                                     "src",
                                                     "projection",
                                                     "once",
                                                     "interpolate",
                                                     "use-alpha",
                                                     "index",
                                                     "object"};

std::vector<std::string_view> joined(std::vector<std::string_view> a,
                                     const std::vector<std::string_view>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

void noChildren(ElementReader& r) {
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader(r.ctx(), r.file(), n)
        .error(r.tag() + " takes no child elements, got <" + std::string(n.name()) + ">");
  });
}

}  // namespace

void noChildrenButWarps(ElementReader& r, ImageProjection projection,
                        std::string_view alsoAllowed) {
  r.forEachChild([&](pugi::xml_node n) {
    if (!alsoAllowed.empty() && std::string_view(n.name()) == alsoAllowed) return;
    if (isWarpElement(n) && projection != ImageProjection::uv) return;  // the placement's
    ElementReader c(r.ctx(), r.file(), n);
    if (isWarpElement(n))
      c.error("a <warp> belongs to a projected " + r.tag() +
              " only: give a 'projection' (at the shape's (u,v) the shape places it)");
    else c.error(r.tag() + " takes no child elements, got <" + std::string(n.name()) + ">");
  });
}

const std::vector<std::string_view>& placementAttributes() { return kPlacementAttributes; }

std::optional<Vec3> parseTurbulenceStrength(ElementReader& r) {
  const std::optional<std::string> text = r.text("turbulence");
  if (!text) return std::nullopt;
  auto list = parseNumberList(*text);
  if (!list) {
    r.attrError("turbulence", list.error);
  } else if (list->size() != 1 && list->size() != 3) {
    r.attrError("turbulence",
                "expected 1 number or 3 (x y z), got " + std::to_string(list->size()));
  } else {
    const Vec3 v = list->size() == 1 ? Vec3((*list)[0]) : Vec3((*list)[0], (*list)[1], (*list)[2]);
    if (v.x >= 0 && v.y >= 0 && v.z >= 0) return v;
    r.attrError("turbulence", "expected numbers >= 0, got '" + *text + "'");
  }
  return std::nullopt;
}

// transform (the pattern on the object, as a node's transform places it in its parent) and
// turbulence.
PatternPlacement parsePlacement(ElementReader& r) {
  PatternPlacement p;
  p.patternFromObject = glm::inverse(r.transform("transform"));
  if (auto v = parseTurbulenceStrength(r)) p.turbulence = *v;
  // POV-Ray clamps octaves to 1..10; Lucent refuses what it would change.
  p.octaves = static_cast<int>(r.integer("octaves", p.octaves, 1, 10));
  p.omega = r.number("omega", p.omega, NumberRule::positive());
  p.lambda = r.number("lambda", p.lambda, NumberRule::positive());
  static const std::vector<std::pair<std::string_view, bool>> kMappings{{"object", false},
                                                                        {"uv", true}};
  p.uv = r.choice("mapping", false, kMappings);
  parseWarps(r, p.warps);
  return p;
}

// A colour's filter and transmit, from the attributes filterN and transmitN (N "" for a
// colour map's entry, "1", "2"... for a pattern's colour list).
FilterTransmit parseFilterTransmit(ElementReader& r, const std::string& n) {
  FilterTransmit ft;
  ft.filter = static_cast<float>(r.number(("filter" + n).c_str(), 0.0));
  ft.transmit = static_cast<float>(r.number(("transmit" + n).c_str(), 0.0));
  return ft;
}

namespace {

// An attribute only some pattern types take: an error on any other.
bool onlyFor(ElementReader& r, const char* attr, bool allowed, const char* types,
             PatternType type) {
  if (!r.has(attr) || allowed) return allowed;
  r.attrError(attr, std::string("only type ") + types + " takes '" + attr + "', not " +
                        std::string(patternTypeInfo(type).name));
  return false;
}

// Two numbers "x y" (julia's c as re im, a colouring as type factor).
std::optional<std::pair<double, double>> numberPair(ElementReader& r, const char* attr,
                                                    const char* what) {
  const std::optional<std::string> text = r.text(attr);
  if (!text) return std::nullopt;
  auto list = parseNumberList(*text);
  if (!list) r.attrError(attr, list.error);
  else if (list->size() != 2)
    r.attrError(attr, std::string("expected two numbers (") + what + "), got " +
                          std::to_string(list->size()));
  else return std::make_pair((*list)[0], (*list)[1]);
  return std::nullopt;
}

// exterior="type factor" (0..8) or interior="type factor" (0..6); types 7 and 8 divide
// by the factor and take the iterations modulo it, so they need a factor >= 1 (7) or > 0 (8).
void parseColouring(ElementReader& r, const char* attr, int maxType, FractalColouring& c) {
  const auto pair = numberPair(r, attr, "the colouring type and its factor");
  if (!pair) return;
  const auto [type, factor] = *pair;
  if (type != std::floor(type) || type < 0 || type > maxType)
    r.attrError(attr, "the type must be a whole number from 0 to " + std::to_string(maxType) +
                          ", got " + formatNumber(type));
  else if (type == 7 && !(factor >= 1))
    r.attrError(attr,
                "exterior type 7 takes the iterations modulo its factor: it needs a "
                "factor >= 1, got " +
                    formatNumber(factor));
  else if (type == 8 && !(factor > 0))
    r.attrError(attr, "exterior type 8 divides by its factor: it needs a factor > 0, got " +
                          formatNumber(factor));
  else c = {static_cast<int>(type), factor};
}

// slope's direction (or point-at), its range, and its altitude with its range.
void parseSlopeAttributes(ElementReader& r, PatternSpec& s) {
  const bool slope = s.type == PatternType::slope;
  SlopeParams& p = s.slope;
  if (slope && r.has("direction") == r.has("point-at")) {
    r.error(r.tag() +
            " type=\"slope\" needs one of 'direction' (the way the value's slope is measured "
            "against) and 'point-at' (a point to look towards)");
    return;
  }
  if (onlyFor(r, "direction", slope, "slope", s.type))
    p.direction = r.vector("direction", p.direction);
  if (onlyFor(r, "point-at", slope, "slope", s.type) && r.has("point-at")) {
    p.pointAt = true;
    p.direction = r.vector("point-at", p.direction);
  }
  if (onlyFor(r, "slope-range", slope, "slope", s.type))
    if (auto range = numberPair(r, "slope-range", "the low and the high slope")) {
      p.low = range->first;
      p.high = range->second;
    }
  if (onlyFor(r, "altitude", slope, "slope", s.type) && r.has("altitude")) {
    if (p.pointAt)
      r.attrError("altitude", "a slope with 'point-at' takes no altitude (as POV-Ray)");
    p.altitude = r.vector("altitude", p.altitude);
  }
  if (slope && r.has("altitude-range") && !r.has("altitude"))
    r.attrError("altitude-range", "'altitude-range' needs 'altitude'");
  else if (onlyFor(r, "altitude-range", slope, "slope", s.type))
    if (auto range = numberPair(r, "altitude-range", "the low and the high altitude")) {
      p.altitudeLow = range->first;
      p.altitudeHigh = range->second;
    }
  if (slope && !p.pointAt && p.direction == Vec3(0.0) && p.altitude == Vec3(0.0))
    r.attrError("direction", "the direction and the altitude cannot both be zero");
}

// facets' size, coords and metric (POV-Ray takes any numbers; a size below 1e-6 acts as 1e-6).
void parseFacetsAttributes(ElementReader& r, PatternSpec& s) {
  const bool facets = s.type == PatternType::facets;
  FacetsParams& f = s.facets;
  if (onlyFor(r, "size", facets, "facets", s.type)) f.size = r.number("size", f.size);
  if (onlyFor(r, "coords", facets, "facets", s.type)) f.coords = r.number("coords", f.coords);
  // (metric is crackle's too: checked with crackle's.)
  if (facets && r.has("metric")) f.metric = r.number("metric", f.metric);
}

// pavement's sides, tiles, arrangement and corners (POV-Ray's number_of_sides,
// number_of_tiles, pattern, exterior, interior and form), within POV-Ray's limits.
void parsePavementAttributes(ElementReader& r, PatternSpec& s) {
  const bool pavement = s.type == PatternType::pavement;
  PavementParams& v = s.pavement;
  if (onlyFor(r, "sides", pavement, "pavement", s.type)) {
    v.sides = static_cast<int>(r.integer("sides", v.sides, 3, 6));
    if (v.sides == 5)
      r.attrError("sides", "expected 3, 4 or 6 (triangles, squares or hexagons), got 5");
  }
  const int maxTiles = v.sides == 6 ? 5 : 6;
  if (onlyFor(r, "tiles", pavement, "pavement", s.type))
    v.tiles = static_cast<int>(r.integer("tiles", v.tiles, 1, maxTiles));
  if (onlyFor(r, "pavement", pavement, "pavement", s.type)) {
    v.number = static_cast<int>(r.integer("pavement", v.number, 1, 35));
    const int count = pavementArrangements(v.sides, v.tiles);
    if (count > 0 && v.number > count)
      r.attrError("pavement", "tiles of " + std::to_string(v.tiles) + " cells with " +
                                  std::to_string(v.sides) + " sides have arrangements 1 to " +
                                  std::to_string(count) + " (POV-Ray's), got " +
                                  std::to_string(v.number));
  }
  if (onlyFor(r, "exterior-corners", pavement, "pavement", s.type))
    v.exterior = static_cast<int>(r.integer("exterior-corners", v.exterior, 0, 2));
  if (onlyFor(r, "interior-corners", pavement, "pavement", s.type))
    v.interior = static_cast<int>(r.integer("interior-corners", v.interior, 0, 2));
  if (onlyFor(r, "pavement-form", pavement, "pavement", s.type))
    v.form = static_cast<int>(r.integer("pavement-form", v.form, 0, 3));
}

// image-pattern's file: resolved and its values read now (left empty where it cannot be).
void readImagePatternFile(ElementReader& r, ImagePattern& im) {
  const std::optional<std::string> src = r.text("src");
  if (!src) {
    r.error(r.tag() +
            " type=\"image-pattern\" needs 'src' (the image file whose grey levels are the "
            "values)");
    return;
  }
  FileAccess::Resolved f = r.ctx().files.resolve(*src, r.file().folder());
  if (f.path.empty()) return r.attrError("src", f.error);
  im.path = f.path.string();
  try {
    im.values =
        im.byIndex ? readImageIndexValues(im.path) : readImagePatternValues(im.path, im.useAlpha);
  } catch (const std::exception& e) {  // ImageValuesError, ImagePluginError, a library's own
    r.attrError("src", "cannot read the image '" + *src + "': " + e.what());
  }
}

// image-pattern's file, read now (its values are the pattern's), and how it is projected
// and blended; the projection is one of space's, (u,v) coming from mapping="uv".
void parseImagePatternAttributes(ElementReader& r, PatternSpec& s) {
  const bool image = s.type == PatternType::image;
  for (const char* a : {"src", "projection", "once", "interpolate", "use-alpha", "index"})
    onlyFor(r, a, image, "image-pattern", s.type);
  if (!image) return;
  ImagePattern im;
  im.byIndex = r.boolean("index", false);
  if (r.has("index") && r.element() != r.ctx().mapPatternElement)
    r.attrError("index",
                "only the image-pattern that is a <material-map>'s pattern reads its image by "
                "index (its palette index picks an entry)");
  if (im.byIndex)
    for (const char* a : {"use-alpha", "frequency", "phase", "wave", "exponent"})
      if (r.has(a))
        r.attrError(a, std::string("an image-pattern read by index takes no '") + a +
                           "': the index picks an entry, it is not a value");
  if (r.verbatim("projection") == "uv")
    r.attrError("projection",
                "an image-pattern is projected from pattern space (planar, spherical, "
                "cylindrical or torus); for the shape's (u,v) give mapping=\"uv\" with the "
                "planar projection");
  else im.projection = r.choice("projection", im.projection, kProjections);
  im.once = r.boolean("once", im.once);
  im.interpolation = r.choice("interpolate", im.interpolation, kInterpolations);
  im.useAlpha = r.boolean("use-alpha", im.useAlpha);
  readImagePatternFile(r, im);
  // An index map keeps its image even unread, so that its entries are read as its own.
  if (im.values || im.byIndex) s.image = std::make_shared<const ImagePattern>(std::move(im));
}

// object's solid: the id of a node, found (and its solid built) once every id is known.
void parseObjectAttribute(ElementReader& r, PatternSpec& s) {
  const bool object = s.type == PatternType::object;
  if (!onlyFor(r, "object", object, "object", s.type)) return;
  const std::optional<std::string> id = r.text("object");
  if (!id) {
    r.error(r.tag() +
            " type=\"object\" needs 'object' (the id of the solid whose inside is the value 1)");
    return;
  }
  auto pattern = std::make_shared<ObjectPattern>();
  pattern->id = *id;
  r.ctx().objectPatterns.push_back({pattern, r.valueLoc("object"), r.tag()});
  s.object = std::move(pattern);
}

// The modifiers of slope, facets, agate, quilted, tiling, mandel, julia, magnet, pavement,
// image-pattern and object.
void parseTypeAttributes(ElementReader& r, PatternSpec& s) {
  parseSlopeAttributes(r, s);
  parseObjectAttribute(r, s);
  parseImagePatternAttributes(r, s);
  parseFacetsAttributes(r, s);
  parsePavementAttributes(r, s);
  const bool tiling = s.type == PatternType::tiling;
  if (tiling && !r.has("tiling"))
    r.error(r.tag() + " type=\"tiling\" needs 'tiling' (which of POV-Ray's tilings, 1 to 27)");
  if (onlyFor(r, "tiling", tiling, "tiling", s.type))
    s.tiling = static_cast<int>(r.integer("tiling", s.tiling, 1, 27));
  if (onlyFor(r, "agate-turb", s.type == PatternType::agate, "agate", s.type))
    s.agateTurb = r.number("agate-turb", s.agateTurb);
  const bool waves = s.type == PatternType::ripples || s.type == PatternType::waves;
  if (onlyFor(r, "sources", waves, "ripples or waves", s.type))
    s.waveSources = static_cast<int>(r.integer("sources", s.waveSources, 1, kMaxWaveSources));
  const bool function = s.type == PatternType::function;
  if (function && !r.has("function"))
    r.error(r.tag() + " type=\"function\" needs 'function' (an expression of x, y and z)");
  if (onlyFor(r, "function", function, "function", s.type)) {
    ElementInput in(r);
    if (std::optional<FunctionInput> f = in.function("function", {"x", "y", "z"}))
      s.function = std::make_shared<const PatternFunction>(
          PatternFunction{f->text, f->constants, f->field, f->pigments});
  }
  const bool crackle = s.type == PatternType::crackle;
  if (onlyFor(r, "metric", crackle || s.type == PatternType::facets, "crackle or facets", s.type) &&
      crackle)
    s.crackle.metric = r.number("metric", s.crackle.metric);
  if (onlyFor(r, "offset", crackle, "crackle", s.type))
    s.crackle.offset = r.number("offset", s.crackle.offset);
  if (onlyFor(r, "solid", crackle, "crackle", s.type))
    s.crackle.solid = r.boolean("solid", s.crackle.solid);
  const bool quilted = s.type == PatternType::quilted;
  if (onlyFor(r, "control0", quilted, "quilted", s.type))
    s.quilted.control0 = r.number("control0", s.quilted.control0);
  if (onlyFor(r, "control1", quilted, "quilted", s.type))
    s.quilted.control1 = r.number("control1", s.quilted.control1);

  const bool fractal = isFractal(s.type), magnet = s.type == PatternType::magnet;
  FractalParams& f = s.fractal;
  if (fractal && !r.has("iterations"))
    r.error(r.tag() + " type=\"" + std::string(patternTypeInfo(s.type).name) +
            "\" needs 'iterations' (how many steps before a point counts as inside)");
  if (onlyFor(r, "iterations", fractal, "mandel, julia or magnet", s.type))
    f.iterations = static_cast<int>(r.integer("iterations", f.iterations, 0, 100000000));
  if (onlyFor(r, "power", fractal && !magnet, "mandel or julia", s.type))
    f.power = static_cast<int>(r.integer("power", f.power, 2, 33));
  if (onlyFor(r, "magnet-type", magnet, "magnet", s.type))
    f.magnetType = static_cast<int>(r.integer("magnet-type", f.magnetType, 1, 2));
  if (onlyFor(r, "form", magnet || s.type == PatternType::crackle, "crackle or magnet", s.type)) {
    if (magnet) f.juliaForm = r.choice("form", false, {{"mandel", false}, {"julia", true}});
    else s.crackle.form = r.vector("form", s.crackle.form);
  }
  const bool takesC = s.type == PatternType::julia || (magnet && f.juliaForm);
  if (takesC && !r.has("c"))
    r.error(r.tag() + (magnet ? " type=\"magnet\" form=\"julia\"" : " type=\"julia\"") +
            " needs 'c' (the constant, as its real and imaginary parts)");
  if (onlyFor(r, "c", takesC, "julia (or magnet with form=\"julia\")", s.type))
    if (auto c = numberPair(r, "c", "the real and imaginary parts")) {
      f.cReal = c->first;
      f.cImaginary = c->second;
    }
  if (onlyFor(r, "exterior", fractal, "mandel, julia or magnet", s.type))
    parseColouring(r, "exterior", 8, f.exterior);
  if (onlyFor(r, "interior", fractal, "mandel, julia or magnet", s.type))
    parseColouring(r, "interior", 6, f.interior);
}

void parseValueAttributes(ElementReader& r, PatternSpec& s) {
  s.placement = parsePlacement(r);
  s.frequency = defaultFrequency(s.type);
  parseTypeAttributes(r, s);
  if (r.has("axis")) s.axis = r.direction("axis", s.axis);
  s.arms = static_cast<int>(r.integer("arms", s.arms, 1, 1000));
  s.frequency = r.number("frequency", s.frequency);
  s.phase = r.number("phase", s.phase);
  if (r.has("wave")) s.wave = r.choice("wave", WaveShape::ramp, kWaves);
  s.exponent = r.number("exponent", s.exponent, NumberRule::positive());
  if (r.has("exponent") && s.waveShape() != WaveShape::poly)
    r.attrError("exponent", "only wave=\"poly\" takes an exponent");
  s.noiseGenerator = static_cast<int>(r.integer("noise-generator", s.noiseGenerator, 1, 3));
}

// A <pigment> child: pigment-pattern's pigment, once; an error on any other type.
void parsePigmentChild(ElementReader& r, ElementReader& c, PatternSpec& s,
                       std::optional<SourceLoc>& pigmentLoc) {
  if (s.type != PatternType::pigment) {
    c.error(r.tag() + " holds a <pigment> only with type=\"pigment-pattern\", not " +
            std::string(patternTypeInfo(s.type).name));
    return;
  }
  if (pigmentLoc) {
    c.error(r.tag() + " holds one <pigment>; the first is at " + pigmentLoc->str());
    return;
  }
  pigmentLoc = c.loc();
  s.pigment = parsePatternPigment(c);
  refuseUvMapping(c, s.pigment->texture, "a pigment-pattern's pigment, evaluated at a point,");
  // Its value is taken at a pattern point, where an image's pixels are not at hand.
  if (textureHoldsImage(s.pigment->texture))
    c.error(
        "an <image> cannot be in a pigment-pattern's <pigment> (its grey level is taken "
        "wherever the pattern is, without the image's pixels)");
}

void needsPigment(ElementReader& r, const PatternSpec& s, const std::optional<SourceLoc>& loc) {
  if (s.type == PatternType::pigment && !loc && !r.failed())
    r.error(r.tag() +
            " type=\"pigment-pattern\" needs a <pigment> (the pigment whose grey level is the "
            "value)");
}

}  // namespace

Texture parsePatternTexture(ElementReader& r) {
  r.checkAttributes(joined(kValueAttributes, kPlacementAttributes));
  PatternTexture t;
  if (!r.has("type")) {
    r.error("<pattern> needs a 'type' (" + [] {
      std::string list;
      for (const auto& [n, e] : patternNames(true))
        list += (list.empty() ? "" : ", ") + std::string(n);
      return list;
    }() + ")");
  } else {
    t.pattern.type = r.choice("type", PatternType::bozo, patternNames(true));
  }
  parseValueAttributes(r, t.pattern);
  std::optional<SourceLoc> mapLoc, pigmentLoc;
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader c(r.ctx(), r.file(), n);
    const std::string_view name = n.name();
    if (isWarpElement(n)) return;  // read with the placement
    if (name == "pigment") {
      parsePigmentChild(r, c, t.pattern, pigmentLoc);
      return;
    }
    if (name == "pigment-function" && t.pattern.type == PatternType::function)
      return;  // read with the function (lang/pigment_function_parser.h)
    if (name == "pigment-function") {
      c.error(
          "<pigment-function> belongs in a <pattern type=\"function\">, whose function "
          "calls it");
      return;
    }
    if (name != "color-map" && name != "pigment-map") {
      std::string pov = povrayElementHint("pattern", n.name());
      c.error("<pattern> may hold one <color-map> or <pigment-map>, not <" + std::string(name) +
              ">" + pov);
      return;
    }
    if (mapLoc) {
      c.error("<pattern> holds one <color-map> or <pigment-map> at most; the first is at " +
              mapLoc->str());
      return;
    }
    mapLoc = c.loc();
    if (name == "color-map") t.map = parseColorMap(c);
    else t.pigments = parsePigmentMap(c);
  });
  needsPigment(r, t.pattern, pigmentLoc);
  return t;
}

// A block pattern's children: at most one <pigment-list> of `count` entries, which stand
// for its colours (whose attributes it then does not take).
std::vector<TextureMapEntry> parseBlockPigments(ElementReader& r, size_t count,
                                                const std::vector<std::string_view>& colours) {
  std::vector<TextureMapEntry> pigments;
  std::optional<SourceLoc> listLoc;
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader c(r.ctx(), r.file(), n);
    if (isWarpElement(n)) return;  // read with the placement
    if (std::string_view(n.name()) != "pigment-list") {
      c.error(r.tag() + " may hold one <pigment-list>, not <" + std::string(n.name()) + ">");
      return;
    }
    if (listLoc) {
      c.error(r.tag() + " holds one <pigment-list> at most; the first is at " + listLoc->str());
      return;
    }
    listLoc = c.loc();
    pigments = parsePigmentList(c, count);
    for (std::string_view a : colours)
      if (r.has(std::string(a).c_str()))
        r.attrError(std::string(a).c_str(),
                    "a " + r.tag() + " with a <pigment-list> takes its colours from the list");
  });
  return pigments;
}

Texture parseHexagonTexture(ElementReader& r) {
  r.checkAttributes(joined({"color1", "color2", "color3", "filter1", "filter2", "filter3",
                            "transmit1", "transmit2", "transmit3"},
                           kPlacementAttributes));
  HexagonTexture t;
  t.placement = parsePlacement(r);
  t.spec.colors[0] = r.color("color1", t.spec.colors[0]);
  t.spec.colors[1] = r.color("color2", t.spec.colors[1]);
  t.spec.colors[2] = r.color("color3", t.spec.colors[2]);
  for (int i = 0; i < 3; ++i) t.spec.ft[i] = parseFilterTransmit(r, std::to_string(i + 1));
  t.pigments = parseBlockPigments(r, 3,
                                  {"color1", "color2", "color3", "filter1", "filter2", "filter3",
                                   "transmit1", "transmit2", "transmit3"});
  return t;
}

Texture parseBrickTexture(ElementReader& r) {
  r.checkAttributes(
      joined({"color1", "color2", "filter1", "filter2", "transmit1", "transmit2", "mortar", "size"},
             kPlacementAttributes));
  BrickTexture t;
  t.placement = parsePlacement(r);
  t.spec.color1 = r.color("color1", t.spec.color1);
  t.spec.color2 = r.color("color2", t.spec.color2);
  t.spec.ft1 = parseFilterTransmit(r, "1");
  t.spec.ft2 = parseFilterTransmit(r, "2");
  t.spec.mortar = r.number("mortar", t.spec.mortar, NumberRule::nonNegative());
  const Vec3 size = r.vector("size", t.spec.size);
  if (size.x <= 0 || size.y <= 0 || size.z <= 0)
    r.attrError("size", "the brick's size must be positive in x, y and z");
  else t.spec.size = size;
  t.pigments = parseBlockPigments(
      r, 2, {"color1", "color2", "filter1", "filter2", "transmit1", "transmit2"});
  return t;
}

namespace {

// Normal types whose own normal (not the slope) POV-Ray uses: a slope map leaves them as
// they are.
bool ownNormal(PatternType t) {
  return t == PatternType::bumps || t == PatternType::dents || t == PatternType::wrinkles ||
         t == PatternType::ripples || t == PatternType::waves || t == PatternType::quilted ||
         t == PatternType::facets;
}

const std::vector<std::pair<std::string_view, NormalBlock>> kNormalBlocks{
    {"checker", NormalBlock::checker},
    {"hexagon", NormalBlock::hexagon},
    {"brick", NormalBlock::brick}};

// bend-space: where a uv-mapped normal is bent, the shape's object space (the default) or the
// world.
void parseBendSpace(ElementReader& r, NormalSpec& n) {
  if (!r.has("bend-space")) return;
  n.bendInWorld = r.choice("bend-space", false, {{"object", false}, {"world", true}});
  if (n.bendInWorld && !n.pattern.placement.uv)
    r.attrError("bend-space",
                "bend-space=\"world\" is for a uv-mapped normal (mapping=\"uv\"): a normal read "
                "at the object point is bent in its pattern space, reached from the object");
}

// <normal type="checker|hexagon|brick">: the placement, brick's size and mortar, and the
// <normal-list> whose entries the cells pick, or without one a depth for the cells' slope.
NormalSpec parseBlockNormal(ElementReader& r, NormalBlock block) {
  std::vector<std::string_view> allowed =
      joined(kPlacementAttributes, {"type", "depth", "keep-facing-away", "accuracy", "bend-space"});
  if (block == NormalBlock::brick) allowed = joined(allowed, {"mortar", "size"});
  r.checkAttributes(allowed, [&](std::string_view a) -> std::string {
    if (a == "mortar" || a == "size") return "only a brick <normal> takes '" + std::string(a) + "'";
    for (std::string_view v : kValueAttributes)
      if (a == v)
        return "a " + r.verbatim("type") +
               " <normal> takes only the placement attributes, depth and keep-facing-away "
               "(each entry's <normal> has its own " +
               std::string(a) + ")";
    return "";
  });
  NormalSpec n;
  n.block = block;
  n.pattern.placement = parsePlacement(r);
  n.keepFacingAway = r.boolean("keep-facing-away", n.keepFacingAway);
  parseBendSpace(r, n);
  n.brick.mortar = r.number("mortar", n.brick.mortar, NumberRule::nonNegative());
  const Vec3 size = r.vector("size", n.brick.size);
  if (size.x <= 0 || size.y <= 0 || size.z <= 0)
    r.attrError("size", "the brick's size must be positive in x, y and z");
  else n.brick.size = size;
  const size_t count = block == NormalBlock::hexagon ? 3 : 2;
  bool listed = false;
  r.forEachChild([&](pugi::xml_node child) {
    if (isWarpElement(child)) return;  // read with the placement
    ElementReader c(r.ctx(), r.file(), child);
    if (std::string_view(child.name()) != "normal-list")
      c.error("a " + r.verbatim("type") + " <normal> holds one <normal-list>, not <" +
              std::string(child.name()) + ">");
    else if (listed) c.error("a " + r.verbatim("type") + " <normal> holds one <normal-list>");
    else n.map = parseNormalList(c, count);
    listed = true;
  });
  // Without a list, the slope of the cell index bends the normal by depth (POV-Ray's
  // `normal { brick 0.75 }`); with one, each entry has its own depth.
  if (listed && r.has("depth"))
    r.attrError("depth", "a " + r.verbatim("type") +
                             " <normal> with a <normal-list> takes no depth (each entry's "
                             "<normal> has its own)");
  n.depth = r.number("depth", n.depth);
  n.accuracy = r.number("accuracy", n.accuracy, NumberRule::positive());
  return n;
}

// A pattern <normal>'s children: one <normal-map> or one <slope-map>.
void parseNormalChildren(ElementReader& r, NormalSpec& n) {
  std::optional<SourceLoc> mapLoc, pigmentLoc;
  r.forEachChild([&](pugi::xml_node child) {
    ElementReader c(r.ctx(), r.file(), child);
    const std::string_view name = child.name();
    if (isWarpElement(child)) return;  // read with the placement
    if (name == "pigment") {           // pigment-pattern's pigment
      parsePigmentChild(r, c, n.pattern, pigmentLoc);
      return;
    }
    if (name != "normal-map" && name != "slope-map") {
      c.error("<normal> may hold one <normal-map> or <slope-map>, not <" + std::string(name) + ">");
      return;
    }
    if (mapLoc) {
      c.error("<normal> holds one <normal-map> or <slope-map> at most; the first is at " +
              mapLoc->str());
      return;
    }
    mapLoc = c.loc();
    if (name == "normal-map" && n.pattern.type == PatternType::facets) {
      c.error("a facets <normal> takes no <normal-map> (POV-Ray refuses normal_map with facets)");
    } else if (name == "normal-map") {
      if (r.has("depth"))
        r.attrError("depth",
                    "a <normal> with a <normal-map> takes no depth (each entry's <normal> has "
                    "its own)");
      n.map = parseNormalMap(c);
    } else if (ownNormal(n.pattern.type)) {
      c.error("a " + std::string(patternTypeInfo(n.pattern.type).name) +
              " <normal> bends by its own normal, not a slope, so a <slope-map> has nothing "
              "to shape (POV-Ray ignores it); give it a colour pattern's type");
    } else {
      n.slopeMap = parseSlopeMap(c);
    }
  });
  needsPigment(r, n.pattern, pigmentLoc);
  if (n.pattern.type == PatternType::object && n.map.empty() && !mapLoc && !r.failed())
    r.error(
        "<normal> type=\"object\" needs a <normal-map> (the normal outside the object at "
        "0 and inside it at 1, POV-Ray's object pattern's list of normals)");
}

}  // namespace

void refuseNormalUvMapping(ElementReader& r, const NormalSpec& n) {
  if (n.pattern.placement.uv)
    r.attrError("mapping",
                "mapping=\"uv\" is for a material's own normal: an entry's normal is bent at "
                "its map's pattern point in its map's space");
}

NormalSpec parseNormal(ElementReader& r) {
  const std::string type = r.verbatim("type");
  for (const auto& [name, block] : kNormalBlocks)
    if (type == name) return parseBlockNormal(r, block);
  r.checkAttributes(joined(joined(kValueAttributes, kPlacementAttributes),
                           {"depth", "keep-facing-away", "accuracy", "bend-space"}));
  NormalSpec n;
  if (type == "average") {
    // The weighted mean of its entries' normals, placed by the placement attributes.
    r.checkAttributes(joined(kPlacementAttributes, {"type", "keep-facing-away", "bend-space"}),
                      [](std::string_view a) -> std::string {
                        for (std::string_view v : kValueAttributes)
                          if (a == v || a == "depth")
                            return "an average <normal> takes only the placement attributes "
                                   "and keep-facing-away (each entry's <normal> has its own " +
                                   std::string(a) + ")";
                        return "";
                      });
    n.pattern.placement = parsePlacement(r);
    n.keepFacingAway = r.boolean("keep-facing-away", n.keepFacingAway);
    parseBendSpace(r, n);
    n.average = parseNormalAverage(r);
    return n;
  }
  if (!r.has("type"))
    r.error(
        "<normal> needs a 'type' (bumps, dents, ripples, waves, wrinkles, facets, a colour "
        "pattern, "
        "average, checker, hexagon or brick)");
  else n.pattern.type = r.choice("type", PatternType::bumps, patternNames(false));
  parseValueAttributes(r, n.pattern);
  n.depth = r.number("depth", n.depth);
  n.accuracy = r.number("accuracy", n.accuracy, NumberRule::positive());
  n.keepFacingAway = r.boolean("keep-facing-away", n.keepFacingAway);
  parseBendSpace(r, n);
  parseNormalChildren(r, n);
  return n;
}

const std::vector<std::string_view>& imageReadingAttributes() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> n{"projection", "once", "interpolate"};
    n.insert(n.end(), placementAttributes().begin(), placementAttributes().end());
    return n;
  }();
  return names;
}

void parseImageReading(ElementReader& r, ImageProjection& projection, PatternPlacement& placement,
                       bool& once, ImageInterpolation& interpolation) {
  projection = r.choice("projection", projection, kProjections);
  if (projection == ImageProjection::uv) {
    for (std::string_view a : placementAttributes())
      if (r.has(std::string(a).c_str()))
        r.attrError(std::string(a).c_str(),
                    "'" + std::string(a) + "' places a projected " + r.tag() +
                        " only: give a 'projection' (at the shape's (u,v) the shape places it)");
  } else {
    placement = parsePlacement(r);
  }
  once = r.boolean("once", once);
  interpolation = r.choice("interpolate", interpolation, kInterpolations);
}

BumpMapSpec parseBumpMap(ElementReader& r) {
  std::vector<std::string_view> attributes{"src", "depth", "keep-facing-away", "use-index"};
  attributes.insert(attributes.end(), imageReadingAttributes().begin(),
                    imageReadingAttributes().end());
  r.checkAttributes(attributes);
  BumpMapSpec b;
  b.loc = r.loc();
  parseImageReading(r, b.projection, b.placement, b.once, b.interpolation);
  if (!r.has("src")) {
    r.error("<bump-map> needs a 'src' attribute (the image file whose grey levels are the bumps)");
  } else if (auto src = r.text("src")) {
    FileAccess::Resolved f = r.ctx().files.resolve(*src, r.file().folder());
    if (f.path.empty()) r.attrError("src", f.error);
    else b.path = f.path.string();
  }
  b.useIndex = r.boolean("use-index", false);
  if (b.useIndex && !b.path.empty()) {
    try {
      b.indices = paletteIndices(b.path);
    } catch (const std::exception& e) {  // ImageValuesError, ImagePluginError, a library's own
      r.attrError("src", "cannot read the bump map's palette indices: " + std::string(e.what()));
    }
  }
  b.depth = r.number("depth", b.depth);
  b.keepFacingAway = r.boolean("keep-facing-away", b.keepFacingAway);
  noChildrenButWarps(r, b.projection);
  return b;
}

// <color-map><entry at color/>...</color-map>: at in [0, 1], never decreasing (two
// entries at one value make a sharp edge).
ColorMap parseColorMap(ElementReader& r) {
  r.checkAttributes({});
  ColorMap map;
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader e(r.ctx(), r.file(), n);
    if (std::string_view(n.name()) != "entry") {
      e.error("<color-map> holds <entry at color/> elements, not <" + std::string(n.name()) + ">");
      return;
    }
    e.checkAttributes({"at", "color", "filter", "transmit"});
    if (!e.has("at") || !e.has("color")) {
      e.error("<entry> needs 'at' (a value from 0 to 1) and 'color'");
      return;
    }
    ColorMapEntry entry;
    entry.at = e.number("at", 0.0, NumberRule::between(0.0, 1.0, "a number from 0 to 1"));
    entry.color = e.color("color", entry.color);
    entry.ft = parseFilterTransmit(e, "");
    noChildren(e);
    if (!map.entries.empty() && entry.at < map.entries.back().at) {
      e.attrError("at",
                  "the entries of a <color-map> go in increasing order of 'at'; this one is below "
                  "the one before (" +
                      formatNumber(map.entries.back().at) + ")");
      return;
    }
    map.entries.push_back(entry);
  });
  if (map.entries.empty() && !r.failed())
    r.error("<color-map> needs at least one <entry at color/>");
  return map;
}

}  // namespace lucent
