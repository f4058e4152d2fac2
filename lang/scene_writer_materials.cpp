// The scene writer's materials, textures and patterns: the finish terms through the finish
// table, each texture kind by its element name from the kinds' table, patterns by the
// pattern table's names.
#include "attribute_probe.h"
#include "scene_writer_out.h"

#include "scenegraph/image_pattern.h"
#include "scenegraph/object_pattern.h"
#include "xml_numbers.h"

#include "scenegraph/finish_terms.h"
#include "scenegraph/map_blend.h"
#include "scenegraph/pigment_function.h"

#include <algorithm>
#include <variant>

namespace lucent {

namespace {

const char* waveName(WaveShape w) {
  static const char* names[] = {"ramp", "sine", "triangle", "scallop", "cubic", "poly"};
  return names[static_cast<int>(w)];
}

// Where a pattern element sits and how turbulence displaces it (lang/pattern_parser.cpp's
// placement attributes), written where they differ from the defaults.
void addPlacement(const PatternPlacement& p, Attributes& a) {
  const PatternPlacement d;
  if (p.patternFromObject != Mat4(1.0))
    a.emplace_back("transform", xmlMatrix(glm::inverse(p.patternFromObject)));
  if (p.turbulence != Vec3(0.0)) a.emplace_back("turbulence", xmlVector(p.turbulence));
  if (p.octaves != d.octaves) a.emplace_back("octaves", std::to_string(p.octaves));
  if (p.omega != d.omega) a.emplace_back("omega", xmlNumber(p.omega));
  if (p.lambda != d.lambda) a.emplace_back("lambda", xmlNumber(p.lambda));
  if (p.uv) a.emplace_back("mapping", "uv");
}

// A <warp> per step between the transform and the turbulence, in the order written.
void writeWarps(const PatternPlacement& p, XmlOut& out) {
  for (const PatternWarp& w : p.warps) {
    Attributes a;
    std::visit(
        [&](const auto& v) {
          using W = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<W, TransformWarp>) {
            a = {{"type", "transform"},
                 {"transform", xmlMatrix(glm::inverse(v.patternFromPrevious))}};
          } else if constexpr (std::is_same_v<W, TurbulenceWarp>) {
            a = {{"type", "turbulence"},
                 {"turbulence", xmlVector(v.strength)},
                 {"octaves", std::to_string(v.octaves)},
                 {"omega", xmlNumber(v.omega)},
                 {"lambda", xmlNumber(v.lambda)}};
          } else if constexpr (std::is_same_v<W, RepeatWarp>) {
            Vec3 d(0.0);
            d[v.axis] = v.width;
            a = {{"type", "repeat"}, {"direction", xmlVector(d)}};
            if (v.offset != Vec3(0.0)) a.emplace_back("offset", xmlVector(v.offset));
            if (v.flip[0] || v.flip[1] || v.flip[2])
              a.emplace_back("flip", xmlVector(Vec3(v.flip[0], v.flip[1], v.flip[2])));
          } else if constexpr (std::is_same_v<W, BlackHoleWarp>) {
            a = {{"type", "black-hole"},
                 {"center", xmlVector(v.center)},
                 {"radius", xmlNumber(v.radius)},
                 {"strength", xmlNumber(v.strength)},
                 {"falloff", xmlNumber(v.falloff)}};
            if (v.inverse) a.emplace_back("inverse", "true");
            if (v.repeat != Vec3(0.0)) a.emplace_back("repeat", xmlVector(v.repeat));
            if (v.turbulence != Vec3(0.0)) a.emplace_back("turbulence", xmlVector(v.turbulence));
          } else {
            a = {{"type", std::string(mappingWarpName(v.kind))}};
            if (v.kind == MappingWarpKind::planar) {
              a.emplace_back("normal", xmlVector(v.orientation));
              a.emplace_back("distance", xmlNumber(v.distance));
            } else if (v.kind != MappingWarpKind::cubic) {
              a.emplace_back("orientation", xmlVector(v.orientation));
              a.emplace_back("dist-exp", xmlNumber(v.distExp));
            }
            if (v.kind == MappingWarpKind::toroidal)
              a.emplace_back("major-radius", xmlNumber(v.majorRadius));
          }
        },
        w);
    out.open("warp", a, true);
  }
}

// out.open of a pattern element followed by its <warp>s; `empty`: nothing else follows, and
// the element is closed here when it has warps.
void openPlaced(XmlOut& out, const std::string& element, const Attributes& a, bool empty,
                const PatternPlacement& p) {
  out.open(element, a, empty && p.warps.empty());
  writeWarps(p, out);
  if (empty && !p.warps.empty()) out.close(element);
}

// The attributes <image> and <bump-map> share: a projection and its placement, once,
// interpolate (those that differ from the defaults).
const char* projectionName(ImageProjection p) {
  static const char* const kProjection[] = {"uv", "planar", "spherical", "cylindrical", "torus"};
  return kProjection[static_cast<int>(p)];
}
const char* interpolationName(ImageInterpolation i) {
  static const char* const kInterpolation[] = {"none", "bilinear", "bicubic", "normalized"};
  return kInterpolation[static_cast<int>(i)];
}

template <class Spec>
void addImageReading(const Spec& t, Attributes& a) {
  if (t.projection != ImageProjection::uv) {
    a.emplace_back("projection", projectionName(t.projection));
    addPlacement(t.placement, a);
  }
  if (t.once) a.emplace_back("once", "true");
  if (t.interpolation != ImageInterpolation::bilinear)
    a.emplace_back("interpolate", interpolationName(t.interpolation));
}

// <image>'s attributes: (u,v)'s scale, or a projection's placement; how it is read.
Attributes imageAttributes(const ImageTexture& t, const std::string& folder) {
  Attributes a{{"src", fileReference(t.path, folder)}};
  if (t.projection == ImageProjection::uv)
    a.emplace_back("scale", xmlNumber(t.scale.x) + " " + xmlNumber(t.scale.y));
  addImageReading(t, a);
  if (t.all.filter != 0.0f) a.emplace_back("filter", xmlNumber(t.all.filter));
  if (t.all.transmit != 0.0f) a.emplace_back("transmit", xmlNumber(t.all.transmit));
  if (t.useAlpha) a.emplace_back("use-alpha", "true");
  if (t.fileGamma)
    a.emplace_back("gamma", t.fileGamma->srgb ? "srgb" : xmlNumber(t.fileGamma->power));
  return a;
}

// quilted's controls and the fractals' parameters, those of the pattern's type only.
void addTypeAttributes(const PatternSpec& s, const SourceLoc& loc, Attributes& a) {
  const PatternSpec d;
  if (s.type == PatternType::function && s.function) {
    // Its names other than x, y and z would need <param>s, which a pattern cannot hold.
    if (!s.function->constants.empty())
      cannotWrite(loc, "a function pattern whose expression names parameters ('" +
                           s.function->constants.front().first + "') cannot be written yet");
    std::string text;  // '$' starts a parameter reference in an attribute: "$$" is one '$'
    for (char c : s.function->text) text += c == '$' ? std::string("$$") : std::string(1, c);
    a.emplace_back("function", text);
  }
  if (s.type == PatternType::tiling) a.emplace_back("tiling", std::to_string(s.tiling));
  if (s.type == PatternType::pavement) {  // what differs from the defaults
    const PavementParams& v = s.pavement;
    const PavementParams pd;
    const std::pair<const char*, int> values[] = {{"sides", v.sides},
                                                  {"tiles", v.tiles},
                                                  {"pavement", v.number},
                                                  {"exterior-corners", v.exterior},
                                                  {"interior-corners", v.interior},
                                                  {"pavement-form", v.form}};
    const int defaults[] = {pd.sides, pd.tiles, pd.number, pd.exterior, pd.interior, pd.form};
    for (int i = 0; i < 6; ++i)
      if (values[i].second != defaults[i])
        a.emplace_back(values[i].first, std::to_string(values[i].second));
  }
  if (s.type == PatternType::crackle) {
    if (s.crackle.metric != d.crackle.metric) a.emplace_back("metric", xmlNumber(s.crackle.metric));
    if (s.crackle.form != d.crackle.form) a.emplace_back("form", xmlVector(s.crackle.form));
    if (s.crackle.offset != d.crackle.offset) a.emplace_back("offset", xmlNumber(s.crackle.offset));
    if (s.crackle.solid) a.emplace_back("solid", "true");
  }
  if (s.type == PatternType::agate && s.agateTurb != d.agateTurb)
    a.emplace_back("agate-turb", xmlNumber(s.agateTurb));
  const bool waves = s.type == PatternType::ripples || s.type == PatternType::waves;
  if (waves && s.waveSources != d.waveSources)
    a.emplace_back("sources", std::to_string(s.waveSources));
  if (s.type == PatternType::slope) {
    const SlopeParams& p = s.slope;
    a.emplace_back(p.pointAt ? "point-at" : "direction", xmlVector(p.direction));
    if (p.low != 0.0 || p.high != 0.0)
      a.emplace_back("slope-range", xmlNumber(p.low) + " " + xmlNumber(p.high));
    if (p.altitude != Vec3(0.0)) {
      a.emplace_back("altitude", xmlVector(p.altitude));
      if (p.altitudeLow != 0.0 || p.altitudeHigh != 0.0)
        a.emplace_back("altitude-range",
                       xmlNumber(p.altitudeLow) + " " + xmlNumber(p.altitudeHigh));
    }
  }
  if (s.type == PatternType::facets) {
    const FacetsParams& f = s.facets;
    if (f.size != d.facets.size) a.emplace_back("size", xmlNumber(f.size));
    if (f.coords != d.facets.coords) a.emplace_back("coords", xmlNumber(f.coords));
    if (f.metric != d.facets.metric) a.emplace_back("metric", xmlNumber(f.metric));
  }
  if (s.type == PatternType::quilted) {
    if (s.quilted.control0 != d.quilted.control0)
      a.emplace_back("control0", xmlNumber(s.quilted.control0));
    if (s.quilted.control1 != d.quilted.control1)
      a.emplace_back("control1", xmlNumber(s.quilted.control1));
  }
  if (!isFractal(s.type)) return;
  const FractalParams& f = s.fractal;
  a.emplace_back("iterations", std::to_string(f.iterations));
  if (s.type == PatternType::magnet) {
    if (f.magnetType != d.fractal.magnetType)
      a.emplace_back("magnet-type", std::to_string(f.magnetType));
    if (f.juliaForm) a.emplace_back("form", "julia");
  } else if (f.power != d.fractal.power) {
    a.emplace_back("power", std::to_string(f.power));
  }
  if (s.type == PatternType::julia || f.juliaForm)
    a.emplace_back("c", xmlNumber(f.cReal) + " " + xmlNumber(f.cImaginary));
  auto colouring = [&](const char* name, const FractalColouring& c, const FractalColouring& def) {
    if (c.type != def.type || c.factor != def.factor)
      a.emplace_back(name, std::to_string(c.type) + " " + xmlNumber(c.factor));
  };
  colouring("exterior", f.exterior, d.fractal.exterior);
  colouring("interior", f.interior, d.fractal.interior);
}

// image-pattern's file (relative to `folder`), projection and blending, each where it
// differs from the default.
void addImagePatternAttributes(const PatternSpec& s, const std::string& folder, Attributes& a) {
  if (s.type != PatternType::image || !s.image) return;
  const ImagePattern& im = *s.image;
  const ImagePattern d;
  a.emplace_back("src", fileReference(im.path, folder));
  if (im.projection != d.projection) a.emplace_back("projection", projectionName(im.projection));
  if (im.once) a.emplace_back("once", "true");
  if (im.interpolation != d.interpolation)
    a.emplace_back("interpolate", interpolationName(im.interpolation));
  if (im.useAlpha) a.emplace_back("use-alpha", "true");
  if (im.byIndex) a.emplace_back("index", "true");
}

// The attributes of <pattern> and <normal>: the type by the pattern table's name, the
// placement and the value's modifiers, written only where they differ from the defaults.
Attributes patternAttributes(const PatternSpec& s, const SourceLoc& loc,
                             const std::string& folder) {
  const PatternSpec d;
  Attributes a{{"type", std::string(patternTypeInfo(s.type).name)}};
  addPlacement(s.placement, a);
  if (s.axis != d.axis) a.emplace_back("axis", xmlVector(s.axis));
  if (s.arms != d.arms) a.emplace_back("arms", std::to_string(s.arms));
  if (s.frequency != defaultFrequency(s.type)) a.emplace_back("frequency", xmlNumber(s.frequency));
  if (s.phase != d.phase) a.emplace_back("phase", xmlNumber(s.phase));
  if (s.wave) a.emplace_back("wave", waveName(*s.wave));
  if (s.exponent != d.exponent) a.emplace_back("exponent", xmlNumber(s.exponent));
  if (s.noiseGenerator != d.noiseGenerator)
    a.emplace_back("noise-generator", std::to_string(s.noiseGenerator));
  addTypeAttributes(s, loc, a);
  addImagePatternAttributes(s, folder, a);
  if (s.type == PatternType::object && s.object) a.emplace_back("object", s.object->id);
  return a;
}

// filterN and transmitN, written only when not 0 (a scene without them reads as before).
void addFilterTransmit(const FilterTransmit& ft, const std::string& n, Attributes& a) {
  if (ft.filter != 0.0f) a.emplace_back("filter" + n, xmlNumber(ft.filter));
  if (ft.transmit != 0.0f) a.emplace_back("transmit" + n, xmlNumber(ft.transmit));
}

// <list><entry [value="..."] color/> or <entry>TEXTURE</entry>...</list>: a map's or a
// list's entries (valueAttr "at", "weight", or "" for a block pattern's list).
void writeEntries(const std::string& list, const std::vector<TextureMapEntry>& entries,
                  const std::string& valueAttr, const SourceLoc& loc, XmlOut& out,
                  const std::string& folder) {
  if (!list.empty()) out.open(list, {}, false);
  for (const TextureMapEntry& e : entries) {
    Attributes a;
    if (!valueAttr.empty()) a.emplace_back(valueAttr, xmlNumber(e.at));
    if (std::holds_alternative<std::monostate>(e.texture)) {
      a.emplace_back("color", xmlColor(e.color.rgb));
      addFilterTransmit(e.color.ft, "", a);
      out.open("entry", a, true);
      continue;
    }
    out.open("entry", a, false);
    writeTexture(e.texture, loc, out, folder);
    out.close("entry");
  }
  if (!list.empty()) out.close(list);
}

// pigment-pattern's <pigment>: a plain colour's attributes, or one texture element.
void writePatternPigment(const PatternSpec& s, const SourceLoc& loc, XmlOut& out,
                         const std::string& folder) {
  if (s.type != PatternType::pigment || !s.pigment) return;
  const TextureMapEntry& e = *s.pigment;
  if (std::holds_alternative<std::monostate>(e.texture)) {
    Attributes a{{"color", xmlColor(e.color.rgb)}};
    addFilterTransmit(e.color.ft, "", a);
    return out.open("pigment", a, true);
  }
  out.open("pigment", {}, false);
  writeTexture(e.texture, loc, out, folder);
  out.close("pigment");
}

void writePigmentFunctions(const PatternSpec& s, const SourceLoc& loc, XmlOut& out) {
  if (!s.function) return;
  for (const auto& p : s.function->pigments) writePigmentFunction(*p, loc, out);
}

// A block pattern's element: empty with its colours, or with a <pigment-list> child and
// without the colour attributes (colorN, filterN, transmitN).
void writeBlock(const std::string& element, Attributes a, const PatternPlacement& placement,
                const std::vector<TextureMapEntry>& pigments, const SourceLoc& loc, XmlOut& out,
                const std::string& folder) {
  if (pigments.empty()) return openPlaced(out, element, a, true, placement);
  a.erase(std::remove_if(a.begin(), a.end(),
                         [](const auto& kv) {
                           const std::string& k = kv.first;
                           return k.rfind("color", 0) == 0 || k.rfind("filter", 0) == 0 ||
                                  k.rfind("transmit", 0) == 0;
                         }),
          a.end());
  openPlaced(out, element, a, false, placement);
  writeEntries("pigment-list", pigments, "", loc, out, folder);
  out.close(element);
}

void writeNormal(const NormalSpec& n, const SourceLoc& loc, XmlOut& out, const std::string& folder);

// A normal map's or a block list's entries: <entry [at]><normal/></entry>, or <entry/>.
void writeNormalEntries(const std::string& list, const NormalSpec& n, bool at, const SourceLoc& loc,
                        XmlOut& out, const std::string& folder) {
  out.open(list, {}, false);
  for (const NormalMapEntry& e : n.map) {
    Attributes a;
    if (at) a.emplace_back("at", xmlNumber(e.at));
    out.open("entry", a, e.flat);
    if (e.flat) continue;
    writeNormal(e.normal, loc, out, folder);
    out.close("entry");
  }
  out.close(list);
}

const char* blockName(NormalBlock b) {
  switch (b) {
    case NormalBlock::checker:
      return "checker";
    case NormalBlock::hexagon:
      return "hexagon";
    case NormalBlock::brick:
      return "brick";
    case NormalBlock::none:
      break;
  }
  return "";
}

// <normal type="checker|hexagon|brick"> with its <normal-list>, or its depth.
void writeBlockNormal(const NormalSpec& n, const SourceLoc& loc, XmlOut& out,
                      const std::string& folder) {
  Attributes a{{"type", blockName(n.block)}};
  addPlacement(n.pattern.placement, a);
  if (n.block == NormalBlock::brick) {
    a.emplace_back("mortar", xmlNumber(n.brick.mortar));
    a.emplace_back("size", xmlVector(n.brick.size));
  }
  if (n.map.empty()) a.emplace_back("depth", xmlNumber(n.depth));
  if (n.accuracy != NormalSpec{}.accuracy) a.emplace_back("accuracy", xmlNumber(n.accuracy));
  if (n.keepFacingAway) a.emplace_back("keep-facing-away", "true");
  if (n.bendInWorld) a.emplace_back("bend-space", "world");
  openPlaced(out, "normal", a, n.map.empty(), n.pattern.placement);
  if (n.map.empty()) return;
  writeNormalEntries("normal-list", n, false, loc, out, folder);
  out.close("normal");
}

// <normal>: a pattern's (with a <normal-map> or a <slope-map>), a block pattern's list, or
// an average of normals with its <entry weight> children.
void writeNormal(const NormalSpec& n, const SourceLoc& loc, XmlOut& out,
                 const std::string& folder) {
  if (n.block != NormalBlock::none) return writeBlockNormal(n, loc, out, folder);
  if (!n.average.empty()) {
    Attributes a{{"type", "average"}};
    addPlacement(n.pattern.placement, a);
    if (n.keepFacingAway) a.emplace_back("keep-facing-away", "true");
    if (n.bendInWorld) a.emplace_back("bend-space", "world");
    if (n.bendInWorld) a.emplace_back("bend-space", "world");
    openPlaced(out, "normal", a, false, n.pattern.placement);
    for (const WeightedNormal& e : n.average) {
      out.open("entry", {{"weight", xmlNumber(e.weight)}}, false);
      writeNormal(e.normal, loc, out, folder);
      out.close("entry");
    }
    out.close("normal");
    return;
  }
  if (n.pattern.function && !n.pattern.function->pigments.empty())
    cannotWrite(loc, "a function <normal> that calls a pigment function cannot be written yet");
  Attributes a = patternAttributes(n.pattern, loc, folder);
  if (n.map.empty()) a.emplace_back("depth", xmlNumber(n.depth));
  if (n.accuracy != NormalSpec{}.accuracy) a.emplace_back("accuracy", xmlNumber(n.accuracy));
  if (n.keepFacingAway) a.emplace_back("keep-facing-away", "true");
  if (n.bendInWorld) a.emplace_back("bend-space", "world");
  const bool children =
      !n.map.empty() || !n.slopeMap.empty() || n.pattern.type == PatternType::pigment;
  openPlaced(out, "normal", a, !children, n.pattern.placement);
  if (!children) return;
  if (n.pattern.type == PatternType::pigment) writePatternPigment(n.pattern, loc, out, folder);
  if (!n.map.empty()) writeNormalEntries("normal-map", n, true, loc, out, folder);
  if (!n.slopeMap.empty()) {
    out.open("slope-map", {}, false);
    for (const SlopeMapEntry& e : n.slopeMap)
      out.open(
          "entry",
          {{"at", xmlNumber(e.at)}, {"height", xmlNumber(e.height)}, {"slope", xmlNumber(e.slope)}},
          true);
    out.close("slope-map");
  }
  out.close("normal");
}

}  // namespace

void writeNormalElement(const NormalSpec& n, const SourceLoc& loc, XmlOut& out,
                        const std::string& folder) {
  writeNormal(n, loc, out, folder);
}

void writeTexture(const Texture& texture, const SourceLoc& loc, XmlOut& out,
                  const std::string& folder) {
  std::visit(
      [&](const auto& t) {
        using T = std::decay_t<decltype(t)>;
        if constexpr (std::is_same_v<T, std::monostate>) {
          return;
        } else if constexpr (std::is_same_v<T, CheckerTexture>) {
          Attributes a{{"color1", xmlColor(t.color1)},
                       {"color2", xmlColor(t.color2)},
                       {"scale", xmlNumber(t.scale)}};
          addFilterTransmit(t.ft1, "1", a);
          addFilterTransmit(t.ft2, "2", a);
          addPlacement(t.placement, a);
          writeBlock(std::string(T::kind.element), a, t.placement, t.pigments, loc, out, folder);
        } else if constexpr (std::is_same_v<T, ImageTexture>) {
          const std::string element(T::kind.element);
          openPlaced(out, element, imageAttributes(t, folder), t.palette.empty(), t.placement);
          if (t.palette.empty()) return;
          for (const PaletteEntryFT& e : t.palette) {
            Attributes a{{"index", std::to_string(e.index)}};
            if (e.filter) a.emplace_back("filter", xmlNumber(*e.filter));
            if (e.transmit) a.emplace_back("transmit", xmlNumber(*e.transmit));
            out.open("palette", a, true);
          }
          out.close(element);
        } else if constexpr (std::is_same_v<T, PatternTexture>) {
          if (t.pigments.empty()) return writePatternTexture(t, loc, out, folder);
          openPlaced(out, "pattern", patternAttributes(t.pattern, loc, folder), false,
                     t.pattern.placement);
          writePatternPigment(t.pattern, loc, out, folder);
          writePigmentFunctions(t.pattern, loc, out);
          writeEntries("pigment-map", t.pigments, "at", loc, out, folder);
          out.close("pattern");
        } else if constexpr (std::is_same_v<T, HexagonTexture>) {
          Attributes a{{"color1", xmlColor(t.spec.colors[0])},
                       {"color2", xmlColor(t.spec.colors[1])},
                       {"color3", xmlColor(t.spec.colors[2])}};
          for (int i = 0; i < 3; ++i) addFilterTransmit(t.spec.ft[i], std::to_string(i + 1), a);
          addPlacement(t.placement, a);
          writeBlock(std::string(T::kind.element), a, t.placement, t.pigments, loc, out, folder);
        } else if constexpr (std::is_same_v<T, BrickTexture>) {
          Attributes a{{"color1", xmlColor(t.spec.color1)},
                       {"color2", xmlColor(t.spec.color2)},
                       {"mortar", xmlNumber(t.spec.mortar)},
                       {"size", xmlVector(t.spec.size)}};
          addFilterTransmit(t.spec.ft1, "1", a);
          addFilterTransmit(t.spec.ft2, "2", a);
          addPlacement(t.placement, a);
          writeBlock(std::string(T::kind.element), a, t.placement, t.pigments, loc, out, folder);
        } else if constexpr (std::is_same_v<T, AverageTexture>) {
          Attributes a;
          addPlacement(t.placement, a);
          // A material map's average holds no entries (the map's are averaged).
          const bool empty = t.entries.empty();
          openPlaced(out, std::string(T::kind.element), a, empty, t.placement);
          if (empty) return;
          writeEntries("", t.entries, "weight", loc, out, folder);
          out.close(std::string(T::kind.element));
        } else {
          // A kind added to Texture without its writer here is an error at the material
          // until it has one, never a material written without its texture.
          cannotWrite(loc,
                      "a <" + std::string(T::kind.element) + "> texture cannot be written yet");
        }
      },
      texture);
}

void writePigmentFunction(const PigmentFunction& f, const SourceLoc& loc, XmlOut& out) {
  out.open("pigment-function",
           {{"name", f.name}, {"component", std::string(pigmentComponentName(f.component))}},
           false);
  writeTexture(f.pigment, loc, out, "");
  out.close("pigment-function");
}

void writePatternTexture(const PatternTexture& t, const SourceLoc& loc, XmlOut& out,
                         const std::string& folder) {
  const Attributes a = patternAttributes(t.pattern, loc, folder);
  const bool pigment = t.pattern.type == PatternType::pigment;
  const bool pigments = t.pattern.function && !t.pattern.function->pigments.empty();
  if (t.map.entries.empty() && !pigment && !pigments)
    return openPlaced(out, "pattern", a, true, t.pattern.placement);
  openPlaced(out, "pattern", a, false, t.pattern.placement);
  writePatternPigment(t.pattern, loc, out, folder);
  writePigmentFunctions(t.pattern, loc, out);
  if (t.map.entries.empty()) return out.close("pattern");
  writeColorMap(t.map, out);
  out.close("pattern");
}

void writeColorMap(const ColorMap& map, XmlOut& out) {
  out.open("color-map", {}, false);
  for (const ColorMapEntry& e : map.entries) {
    Attributes entry{{"at", xmlNumber(e.at)}, {"color", xmlColor(e.color)}};
    addFilterTransmit(e.ft, "", entry);
    out.open("entry", entry, true);
  }
  out.close("color-map");
}

Attributes materialAttributes(const Material& m, bool layer) {
  Attributes a;
  // What the parser gives an attribute left out: diffuse is 1 under a texture.
  Material defaults;
  if (m.hasTexture()) defaults.diffuse = Color(1.0f);
  for (const FinishTerm& term : finishTerms()) {
    if (layer && term.ofInterior) continue;  // the material's
    // Each term's value, and the default's: only what differs is written.
    AttributeProbe value, byDefault;
    Material copy = m, plain = defaults;
    copy.layers.clear();  // not read by a term
    copy.mapEntries.clear();
    term.read(copy, value);
    term.read(plain, byDefault);
    if (!value.unwritable.empty())
      cannotWrite(m.loc, "the <material> attribute '" + value.unwritable.front() +
                             "' cannot be written yet");
    for (const auto& [name, text] : value.values) {
      const std::string* d = byDefault.find(name);
      if (!d || *d != text) a.emplace_back(name, text);
    }
  }
  return a;
}

void writeMaterialChildren(const Material& m, XmlOut& out, const std::string& folder) {
  if (m.mapped()) {
    // The map's pattern, then each entry's surface as an inline material.
    out.open("material-map", {}, false);
    writeTexture(m.mapPattern, m.loc, out, folder);
    for (const MaterialMapEntry& e : m.mapEntries) {
      Attributes at;  // an index map's entries are numbered by their order
      if (!mapIndexImage(m)) at.emplace_back(mapAverages(m) ? "weight" : "at", xmlNumber(e.at));
      out.open("entry", at, false);
      XmlOut children;
      children.depth = out.depth + 1;
      writeMaterialChildren(e.material, children, folder);
      out.open("material", materialAttributes(e.material, true), children.text.empty());
      if (!children.text.empty()) {
        out.text += children.text;
        out.close("material");
      }
      out.close("entry");
    }
    out.close("material-map");
    return;
  }
  writeTexture(m.texture, m.loc, out, folder);
  if (m.normal) writeNormal(*m.normal, m.loc, out, folder);
  if (m.bumpMap) {
    Attributes a{{"src", fileReference(m.bumpMap->path, folder)},
                 {"depth", xmlNumber(m.bumpMap->depth)}};
    addImageReading(*m.bumpMap, a);
    if (m.bumpMap->keepFacingAway) a.emplace_back("keep-facing-away", "true");
    if (m.bumpMap->useIndex) a.emplace_back("use-index", "true");
    openPlaced(out, "bump-map", a, true, m.bumpMap->placement);
  }
  // The layers over it, bottom first, each with its own surface terms and children.
  for (const Material& layer : m.layers) {
    XmlOut children;
    children.depth = out.depth + 1;
    writeMaterialChildren(layer, children, folder);
    out.open("layer", materialAttributes(layer, true), children.text.empty());
    if (children.text.empty()) continue;
    out.text += children.text;
    out.close("layer");
  }
}

}  // namespace lucent
