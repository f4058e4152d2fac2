#include "pov_patterns.h"

#include "pov_function.h"
#include "pov_image_map.h"

#include "scenegraph/image_pattern.h"
#include "scenegraph/overloaded.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>
#include <variant>

namespace lucent {

namespace {

const char* povWaveName(WaveShape w) {
  switch (w) {
    case WaveShape::ramp:
      return "ramp_wave";
    case WaveShape::sine:
      return "sine_wave";
    case WaveShape::triangle:
      return "triangle_wave";
    case WaveShape::scallop:
      return "scallop_wave";
    case WaveShape::cubic:
      return "cubic_wave";
    case WaveShape::poly:
      return "poly_wave";
  }
  return "ramp_wave";
}

}  // namespace

// The pattern keyword and what belongs to it (gradient's axis, the spirals' arms).
namespace {

// image_pattern's block: `{ FORMAT "file" map_type N once interpolate N use_alpha }`.
// POV-Ray reads its file without gamma correction, as Lucent does; a format it does not
// name is left to the file's extension.
std::string imagePatternBlock(const PatternSpec& s) {
  if (!s.image) return " { \"\" }";
  const ImagePattern& im = *s.image;
  return " { " + imageReadingSpec(im) + (im.useAlpha ? " use_alpha" : "") + " }";
}

}  // namespace

std::string imageReadingSpec(const ImagePattern& im) {
  static const int kMapType[] = {0, 0, 1, 2, 5};  // ImageProjection's order: uv, planar, ...
  static const char* const kInterpolate[] = {"", " interpolate 2", " interpolate 3",
                                             " interpolate 4"};
  const std::string format = povImageFormat(im.path);
  std::string b = (format.empty() ? "" : format + " ") +
                  povString(std::filesystem::absolute(im.path).lexically_normal().string());
  const int mapType = kMapType[static_cast<int>(im.projection)];
  if (mapType != 0) b += " map_type " + std::to_string(mapType);
  if (im.once) b += " once";
  return b + kInterpolate[static_cast<int>(im.interpolation)];
}

std::string povObjectPatternName(const ObjectPattern& o) {
  std::string name = "LucentObject_";
  for (char c : o.id) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

bool objectPatternTwoValued(const PatternSpec& s) {
  return s.frequency == 0.0 && s.waveShape() == WaveShape::ramp;
}

std::string patternKeyword(const PatternSpec& s) {
  if (s.type == PatternType::object)
    return "object { " +
           (s.object ? povObjectPatternName(*s.object) : std::string("sphere { 0, 0 }")) + " }";
  std::string k(patternTypeInfo(s.type).pov);
  if (s.type == PatternType::image) k += imagePatternBlock(s);
  if (s.type == PatternType::gradient) k += " " + povVector(s.axis);
  if (s.type == PatternType::spiral1 || s.type == PatternType::spiral2)
    k += " " + std::to_string(s.arms);
  if (s.type == PatternType::tiling) k += " " + std::to_string(s.tiling);
  if (s.type == PatternType::function) {
    std::string problem;
    const std::optional<std::string> text =
        s.function ? povFunctionText(s.function->text, s.function->constants, povNumber, problem,
                                     s.function->pigments)
                   : std::optional<std::string>("0");
    if (!text) throw std::runtime_error("a function pattern cannot be exported: " + problem);
    k += " { " + *text + " }";
  }
  if (s.type == PatternType::slope) {
    const SlopeParams& p = s.slope;
    k += std::string(" { ") + (p.pointAt ? "point_at " : "") + povVector(p.direction) + ", " +
         povNumber(p.low) + ", " + povNumber(p.high);
    if (p.altitude != Vec3(0.0))
      k += " altitude " + povVector(p.altitude) + ", " + povNumber(p.altitudeLow) + ", " +
           povNumber(p.altitudeHigh);
    k += " }";
  }
  // agate_turb always written, so that POV-Ray's default cannot drift.
  if (s.type == PatternType::agate) k += " agate_turb " + povNumber(s.agateTurb);
  const FractalParams& f = s.fractal;
  const std::string c = "<" + povNumber(f.cReal) + ", " + povNumber(f.cImaginary) + ">, ";
  if (s.type == PatternType::mandel) k += " " + std::to_string(f.iterations);
  if (s.type == PatternType::julia) k += " " + c + std::to_string(f.iterations);
  if (s.type == PatternType::magnet)
    k += " " + std::to_string(f.magnetType) + (f.juliaForm ? " julia " + c : " mandel ") +
         std::to_string(f.iterations);
  return k;
}

void writeUvMapping(const PatternPlacement& p, PovWriter& out) {
  // First in the block: the rest of it is the pattern POV-Ray evaluates at (u, v, 0).
  if (p.uv) out.line("uv_mapping");
}

namespace {

// `warp { ... }` of one step that is not a transform.
std::string povWarp(const PatternWarp& w) {
  return std::visit(
      [](const auto& v) -> std::string {
        using W = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<W, TransformWarp>) {
          return povMatrix(glm::inverse(v.patternFromPrevious));
        } else if constexpr (std::is_same_v<W, TurbulenceWarp>) {
          return "warp { turbulence " + povVector(v.strength) + " octaves " +
                 std::to_string(v.octaves) + " omega " + povNumber(v.omega) + " lambda " +
                 povNumber(v.lambda) + " }";
        } else if constexpr (std::is_same_v<W, RepeatWarp>) {
          Vec3 d(0.0);
          d[v.axis] = v.width;
          return "warp { repeat " + povVector(d) + " offset " + povVector(v.offset) + " flip " +
                 povVector(Vec3(v.flip[0], v.flip[1], v.flip[2])) + " }";
        } else if constexpr (std::is_same_v<W, BlackHoleWarp>) {
          std::string s = "warp { black_hole " + povVector(v.center) + ", " + povNumber(v.radius) +
                          " strength " + povNumber(v.strength) + " falloff " +
                          povNumber(v.falloff) + (v.inverse ? " inverse" : "");
          if (v.repeat != Vec3(0.0)) s += " repeat " + povVector(v.repeat);
          if (v.turbulence != Vec3(0.0)) s += " turbulence " + povVector(v.turbulence);
          return s + " }";
        } else {
          const std::string name(mappingWarpName(v.kind));
          if (v.kind == MappingWarpKind::planar)
            return "warp { planar " + povVector(v.orientation) + ", " + povNumber(v.distance) +
                   " }";
          if (v.kind == MappingWarpKind::cubic) return "warp { cubic }";
          std::string s = "warp { " + name + " orientation " + povVector(v.orientation) +
                          " dist_exp " + povNumber(v.distExp);
          if (v.kind == MappingWarpKind::toroidal) s += " major_radius " + povNumber(v.majorRadius);
          return s + " }";
        }
      },
      w);
}

// POV-Ray applies the transforms and warps written last first, so the steps go in their
// order and the placement's transform after them; the classic turbulence is always last.
void writeWarpSteps(const PatternPlacement& p, PovWriter& out) {
  for (const PatternWarp& w : p.warps) out.line(povWarp(w));
  if (p.patternFromObject != Mat4(1.0)) out.line(povMatrix(glm::inverse(p.patternFromObject)));
}

}  // namespace

void writePlacement(const PatternPlacement& p, PovWriter& out) {
  if (p.turbulence != Vec3(0.0)) {
    out.line("turbulence " + povVector(p.turbulence));
    out.line("octaves " + std::to_string(p.octaves) + " omega " + povNumber(p.omega) + " lambda " +
             povNumber(p.lambda));
  }
  writeWarpSteps(p, out);
}

void writeValueModifiers(const PatternSpec& s, PovWriter& out) {
  if (s.type == PatternType::crackle) {
    // Always written, so that POV-Ray's defaults cannot drift.
    const CrackleParams& c = s.crackle;
    out.line("metric " + povNumber(c.metric) + " form " + povVector(c.form) + " offset " +
             povNumber(c.offset) + (c.solid ? " solid" : ""));
  }
  if (s.type == PatternType::facets)
    out.line("size " + povNumber(s.facets.size) + " coords " + povNumber(s.facets.coords) +
             " metric " + povNumber(s.facets.metric));
  if (s.type == PatternType::pavement) {  // always written, as crackle's
    const PavementParams& v = s.pavement;
    out.line("number_of_sides " + std::to_string(v.sides) + " number_of_tiles " +
             std::to_string(v.tiles) + " pattern " + std::to_string(v.number));
    out.line("exterior " + std::to_string(v.exterior) + " interior " + std::to_string(v.interior) +
             " form " + std::to_string(v.form));
  }
  if (s.type == PatternType::quilted)
    out.line("control0 " + povNumber(s.quilted.control0) + " control1 " +
             povNumber(s.quilted.control1));
  if (isFractal(s.type)) {
    const FractalParams& f = s.fractal;
    if (s.type != PatternType::magnet) out.line("exponent " + std::to_string(f.power));
    out.line("exterior " + std::to_string(f.exterior.type) + ", " + povNumber(f.exterior.factor));
    out.line("interior " + std::to_string(f.interior.type) + ", " + povNumber(f.interior.factor));
  }
  // POV-Ray's default frequency is Lucent's (0 for quilted, 1 otherwise).
  if (s.frequency != defaultFrequency(s.type)) out.line("frequency " + povNumber(s.frequency));
  if (s.phase != 0.0) out.line("phase " + povNumber(s.phase));
  if (s.wave) {
    std::string w = povWaveName(*s.wave);
    if (*s.wave == WaveShape::poly) w += " " + povNumber(s.exponent);
    out.line(w);
  }
  // 2 is POV-Ray 3.7's global default (global_settings noise_generator).
  if (s.noiseGenerator != 2) out.line("noise_generator " + std::to_string(s.noiseGenerator));
}

namespace {

// A colour of the pattern with its own filter and transmit added to the material's.
std::string colour(const Color& c, const FilterTransmit& ft, const Vec3& scale, double filter,
                   double transmit) {
  return povRgbft(scale * Vec3(c.r, c.g, c.b), filter + ft.filter, transmit + ft.transmit);
}

// Each pigment's body (what `pigment { }` holds, and what a pigment_map's entry holds
// after its value), then the pigments as blocks.
void writeBody(const Texture& t, const Vec3& scale, double filter, double transmit, PovWriter& out);

// A map's or a list's entry: its plain colour, or its texture's body.
void writeEntryBody(const TextureMapEntry& e, const Vec3& scale, double filter, double transmit,
                    PovWriter& out) {
  if (std::holds_alternative<std::monostate>(e.texture)) {
    out.line(colour(e.color.rgb, e.color.ft, scale, filter, transmit));
    return;
  }
  // A uv-mapped entry: POV-Ray reads its body at the intersection's (u, v, 0).
  if (const PatternPlacement* p = texturePlacement(e.texture)) writeUvMapping(*p, out);
  writeBody(e.texture, scale, filter, transmit, out);
}

// `pigment_map { [at BODY] ... }`: the material's colour scale, filter and transmit go
// into each entry (the blend is linear in them, so this is the same as applying them to
// the blended colour).
void writePigmentMap(const std::vector<TextureMapEntry>& entries, const Vec3& scale, double filter,
                     double transmit, PovWriter& out) {
  out.open("pigment_map");
  for (const TextureMapEntry& e : entries) {
    out.line("[" + povNumber(e.at));
    writeEntryBody(e, scale, filter, transmit, out);
    out.line("]");
  }
  out.close();
}

// A block pattern's list: `pigment { BODY }` for each.
void writePigmentList(const std::vector<TextureMapEntry>& entries, const Vec3& scale, double filter,
                      double transmit, PovWriter& out) {
  for (const TextureMapEntry& e : entries) {
    out.open("pigment");
    writeEntryBody(e, scale, filter, transmit, out);
    out.close();
  }
}

// `object { NAME A B }`: the map's first entry outside, its last inside (POV-Ray's list of
// two; a blend of the two between them, as a two-entry map's).
void writeObjectPatternBody(const PatternTexture& t, const Vec3& scale, double filter,
                            double transmit, PovWriter& out) {
  // (A map POV-Ray's list cannot hold is reported by PovGeometry::writeObjectPatterns.)
  out.open("object");
  out.line(t.pattern.object ? povObjectPatternName(*t.pattern.object) : "sphere { 0, 0 }");
  if (!t.pigments.empty()) {
    writePigmentList({t.pigments.front(), t.pigments.back()}, scale, filter, transmit, out);
  } else if (t.map.entries.empty()) {
    out.line(colour(Color(0.0f), {}, scale, filter, transmit) + ",");
    out.line(colour(Color(1.0f), {}, scale, filter, transmit));
  } else {
    const ColorMapEntry& a = t.map.entries.front();
    const ColorMapEntry& b = t.map.entries.back();
    out.line(colour(a.color, a.ft, scale, filter, transmit) + ",");
    out.line(colour(b.color, b.ft, scale, filter, transmit));
  }
  out.close();
  writeValueModifiers(t.pattern, out);
  writePlacement(t.pattern.placement, out);
}

void writePatternBody(const PatternTexture& t, const Vec3& scale, double filter, double transmit,
                      PovWriter& out) {
  if (t.pattern.type == PatternType::object)
    return writeObjectPatternBody(t, scale, filter, transmit, out);
  writePigmentFunctions(t.pattern, out);
  writePatternKeyword(t.pattern, out);
  if (!t.pigments.empty()) {
    writePigmentMap(t.pigments, scale, filter, transmit, out);
  } else {
    out.open("color_map");
    if (t.map.entries.empty()) {
      out.line("[0 " + colour(Color(0.0f), {}, scale, filter, transmit) + "]");
      out.line("[1 " + colour(Color(1.0f), {}, scale, filter, transmit) + "]");
    } else {
      for (const ColorMapEntry& e : t.map.entries)
        out.line("[" + povNumber(e.at) + " " + colour(e.color, e.ft, scale, filter, transmit) +
                 "]");
    }
    out.close();
  }
  writeValueModifiers(t.pattern, out);
  writePlacement(t.pattern.placement, out);
}

void writeCheckerBody(const CheckerTexture& checker, const Vec3& scale, double filter,
                      double transmit, PovWriter& out) {
  // Cells of edge `scale`; the cell [0, scale)^3 has the first colour, as in Lucent.
  out.line(std::string(CheckerTexture::kind.pov));
  if (!checker.pigments.empty()) {
    writePigmentList(checker.pigments, scale, filter, transmit, out);
  } else {
    out.line(colour(checker.color1, checker.ft1, scale, filter, transmit) + ",");
    out.line(colour(checker.color2, checker.ft2, scale, filter, transmit));
  }
  // The cells scale in pattern space, which the placement then carries onto the shape.
  const PatternPlacement& p = checker.placement;
  if (checker.scale != 1.0 && p.turbulence != Vec3(0.0)) {
    // Lucent turbulates before the cells' scale; POV-Ray's classic turbulence would
    // come after it. A warp between them keeps Lucent's order (POV-Ray applies the
    // transforms and warps written last first).
    out.line("scale " + povNumber(checker.scale));
    out.line("warp { turbulence " + povVector(p.turbulence) + " octaves " +
             std::to_string(p.octaves) + " omega " + povNumber(p.omega) + " lambda " +
             povNumber(p.lambda) + " }");
    writeWarpSteps(p, out);
  } else {
    if (checker.scale != 1.0) out.line("scale " + povNumber(checker.scale));
    writePlacement(p, out);
  }
}

void writeHexagonBody(const HexagonTexture& t, const Vec3& scale, double filter, double transmit,
                      PovWriter& out) {
  out.line(std::string(HexagonTexture::kind.pov));
  if (!t.pigments.empty()) {
    writePigmentList(t.pigments, scale, filter, transmit, out);
  } else {
    for (int i = 0; i < 3; ++i)
      out.line(colour(t.spec.colors[i], t.spec.ft[i], scale, filter, transmit) +
               (i < 2 ? "," : ""));
  }
  writePlacement(t.placement, out);
}

void writeBrickBody(const BrickTexture& t, const Vec3& scale, double filter, double transmit,
                    PovWriter& out) {
  out.line(std::string(BrickTexture::kind.pov));
  if (!t.pigments.empty()) {
    writePigmentList(t.pigments, scale, filter, transmit, out);
  } else {
    out.line(colour(t.spec.color1, t.spec.ft1, scale, filter, transmit) + ",");
    out.line(colour(t.spec.color2, t.spec.ft2, scale, filter, transmit));
  }
  out.line("brick_size " + povVector(t.spec.size) + " mortar " + povNumber(t.spec.mortar));
  writePlacement(t.placement, out);
}

// `average pigment_map { [weight BODY] ... }` (the weights are the entries' `at`).
void writeAverageBody(const AverageTexture& t, const Vec3& scale, double filter, double transmit,
                      PovWriter& out) {
  out.line(std::string(AverageTexture::kind.pov));
  writePigmentMap(t.entries, scale, filter, transmit, out);
  writePlacement(t.placement, out);
}

void writeBody(const Texture& t, const Vec3& scale, double filter, double transmit,
               PovWriter& out) {
  std::visit(
      Overloaded{
          [&](std::monostate) { out.line(colour(Color(1.0f), {}, scale, filter, transmit)); },
          [&](const ImageTexture& image) {
            // POV-Ray cannot tint an image map: PovMaterials checks the scale is 1.
            writeNestedImageBody(image, filter, transmit, out);
          },
          [&](const CheckerTexture& c) { writeCheckerBody(c, scale, filter, transmit, out); },
          [&](const PatternTexture& c) { writePatternBody(c, scale, filter, transmit, out); },
          [&](const HexagonTexture& c) { writeHexagonBody(c, scale, filter, transmit, out); },
          [&](const BrickTexture& c) { writeBrickBody(c, scale, filter, transmit, out); },
          [&](const AverageTexture& c) { writeAverageBody(c, scale, filter, transmit, out); },
      },
      t);
}

}  // namespace

void writePatternKeyword(const PatternSpec& s, PovWriter& out, const std::string& after) {
  if (s.type != PatternType::pigment) return out.line(patternKeyword(s) + after);
  // Only the pigment's grey level counts: its colours as they are.
  out.open("pigment_pattern");
  if (s.pigment) writeEntryBody(*s.pigment, Vec3(1.0), 0.0, 0.0, out);
  else out.line("rgb 0");
  out.close();
  if (!after.empty()) out.line(after.front() == ' ' ? after.substr(1) : after);
}

void writePatternPigment(const PatternTexture& t, const Vec3& scale, double filter, double transmit,
                         PovWriter& out) {
  out.open("pigment");
  writeUvMapping(t.pattern.placement, out);
  writePatternBody(t, scale, filter, transmit, out);
  out.close();
}

void writeCheckerPigment(const CheckerTexture& t, const Vec3& scale, double filter, double transmit,
                         PovWriter& out) {
  out.open("pigment");
  writeUvMapping(t.placement, out);
  writeCheckerBody(t, scale, filter, transmit, out);
  out.close();
}

void writeHexagonPigment(const HexagonTexture& t, const Vec3& scale, double filter, double transmit,
                         PovWriter& out) {
  out.open("pigment");
  writeUvMapping(t.placement, out);
  writeHexagonBody(t, scale, filter, transmit, out);
  out.close();
}

void writeBrickPigment(const BrickTexture& t, const Vec3& scale, double filter, double transmit,
                       PovWriter& out) {
  out.open("pigment");
  writeUvMapping(t.placement, out);
  writeBrickBody(t, scale, filter, transmit, out);
  out.close();
}

void writeAveragePigment(const AverageTexture& t, const Vec3& scale, double filter, double transmit,
                         PovWriter& out) {
  out.open("pigment");
  writeUvMapping(t.placement, out);
  writeAverageBody(t, scale, filter, transmit, out);
  out.close();
}

namespace {

void writeNormalBody(const NormalSpec& n, PovWriter& out);

// A block pattern's `normal {..} normal {..}` list, every entry written: POV-Ray 3.7 stops
// at a list with fewer normals than cells (it reads a missing entry as the #default
// normal, and without one as nothing, which its parser then dereferences). A flat entry
// is `bumps 0`, which bends nothing.
void writeNormalList(const NormalSpec& n, PovWriter& out) {
  for (const NormalMapEntry& e : n.map) {
    out.open("normal");
    if (e.flat) out.line("bumps 0");
    else writeNormalBody(e.normal, out);
    out.close();
  }
}

// `checker|hexagon|brick normal {..} ...` with brick's size and mortar.
void writeBlockNormalBody(const NormalSpec& n, PovWriter& out) {
  const char* keyword = n.block == NormalBlock::checker   ? "checker"
                        : n.block == NormalBlock::hexagon ? "hexagon"
                                                          : "brick";
  // Without a list, POV-Ray takes the slope of the cell index, bent by the amount.
  out.line(n.map.empty() ? std::string(keyword) + " " + povNumber(n.depth) : keyword);
  if (n.map.empty()) out.line("accuracy " + povNumber(n.accuracy));
  writeNormalList(n, out);
  if (n.block == NormalBlock::brick)
    out.line("brick_size " + povVector(n.brick.size) + " mortar " + povNumber(n.brick.mortar));
  writePlacement(n.pattern.placement, out);
}

// `normal_map { [at NORMAL_BODY] ... }` and `slope_map { [at <height, slope>] ... }`.
void writeNormalMaps(const NormalSpec& n, PovWriter& out) {
  if (!n.map.empty()) {
    out.open("normal_map");
    for (const NormalMapEntry& e : n.map) {
      out.line("[" + povNumber(e.at));
      writeNormalBody(e.normal, out);
      out.line("]");
    }
    out.close();
  }
  if (!n.slopeMap.empty()) {
    out.open("slope_map");
    for (const SlopeMapEntry& e : n.slopeMap)
      out.line("[" + povNumber(e.at) + " <" + povNumber(e.height) + ", " + povNumber(e.slope) +
               ">]");
    out.close();
  }
}

// `object { NAME normal {..} normal {..} }`: the map's first entry outside, its last inside.
void writeObjectNormalBody(const NormalSpec& n, PovWriter& out) {
  out.open("object");
  out.line(n.pattern.object ? povObjectPatternName(*n.pattern.object) : "sphere { 0, 0 }");
  for (const NormalMapEntry* e : {&n.map.front(), &n.map.back()}) {
    out.open("normal");
    writeNormalBody(e->normal, out);
    out.close();
  }
  out.close();
  writeValueModifiers(n.pattern, out);
  writePlacement(n.pattern.placement, out);
}

// What `normal { }` holds (and a normal_map's entry after its weight).
void writeNormalBody(const NormalSpec& n, PovWriter& out) {
  if (n.block != NormalBlock::none) return writeBlockNormalBody(n, out);
  if (n.pattern.type == PatternType::object && !n.map.empty()) return writeObjectNormalBody(n, out);
  if (!n.average.empty()) {
    // `average normal_map { [weight NORMAL_BODY] ... }`.
    out.line("average");
    out.open("normal_map");
    for (const WeightedNormal& e : n.average) {
      out.line("[" + povNumber(e.weight));
      writeNormalBody(e.normal, out);
      out.line("]");
    }
    out.close();
    writePlacement(n.pattern.placement, out);
    return;
  }
  writePigmentFunctions(n.pattern, out);
  std::string keyword = patternKeyword(n.pattern);
  // The amount comes before agate's agate_turb.
  const std::string agate = " agate_turb " + povNumber(n.pattern.agateTurb);
  if (n.pattern.type == PatternType::agate)
    out.line(keyword.substr(0, keyword.size() - agate.size()) + " " + povNumber(n.depth) + agate);
  else writePatternKeyword(n.pattern, out, " " + povNumber(n.depth));
  // POV-Ray's slope method samples at this distance.
  out.line("accuracy " + povNumber(n.accuracy));
  writeNormalMaps(n, out);
  writeValueModifiers(n.pattern, out);
  writePlacement(n.pattern.placement, out);
}

}  // namespace

void writeNormal(const NormalSpec& n, PovWriter& out) {
  out.open("normal");
  writeUvMapping(n.pattern.placement, out);
  writeNormalBody(n, out);
  out.close();
}

void writePigmentFunctions(const std::vector<std::shared_ptr<const PigmentFunction>>& pigments,
                           PovWriter& out) {
  for (const auto& f : pigments) {
    // The pigment's own colours: the surface's scale, filter and transmit are not its.
    // POV-Ray refuses to declare a function again: another material may use the name.
    const std::string name = povPigmentFunctionName(*f);
    out.line("#ifdef (" + name + ") #undef " + name + " #end");
    out.open("#declare " + name + " = function");
    out.open("pigment");
    writeBody(f->pigment, Vec3(1.0), 0.0, 0.0, out);
    out.close();
    out.close();
  }
}

void writePigmentFunctions(const PatternSpec& s, PovWriter& out) {
  if (s.function) writePigmentFunctions(s.function->pigments, out);
}

}  // namespace lucent
