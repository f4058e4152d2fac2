#include "pov_patterns.h"

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
std::string patternKeyword(const PatternSpec& s) {
  std::string k(patternTypeInfo(s.type).pov);
  if (s.type == PatternType::gradient) k += " " + povVector(s.axis);
  if (s.type == PatternType::spiral1 || s.type == PatternType::spiral2)
    k += " " + std::to_string(s.arms);
  // Lucent's agate uses POV-Ray's default agate_turb, written so that it cannot drift.
  if (s.type == PatternType::agate) k += " agate_turb 1";
  const FractalParams& f = s.fractal;
  const std::string c = "<" + povNumber(f.cReal) + ", " + povNumber(f.cImaginary) + ">, ";
  if (s.type == PatternType::mandel) k += " " + std::to_string(f.iterations);
  if (s.type == PatternType::julia) k += " " + c + std::to_string(f.iterations);
  if (s.type == PatternType::magnet)
    k += " " + std::to_string(f.magnetType) + (f.juliaForm ? " julia " + c : " mandel ") +
         std::to_string(f.iterations);
  return k;
}

void writePlacement(const PatternPlacement& p, PovWriter& out) {
  if (p.turbulence != Vec3(0.0)) {
    out.line("turbulence " + povVector(p.turbulence));
    out.line("octaves " + std::to_string(p.octaves) + " omega " + povNumber(p.omega) + " lambda " +
             povNumber(p.lambda));
  }
  if (p.patternFromObject != Mat4(1.0)) out.line(povMatrix(glm::inverse(p.patternFromObject)));
}

void writeValueModifiers(const PatternSpec& s, PovWriter& out) {
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

}  // namespace

void writePatternPigment(const PatternTexture& t, const Vec3& scale, double filter, double transmit,
                         PovWriter& out) {
  out.open("pigment");
  out.line(patternKeyword(t.pattern));
  out.open("color_map");
  if (t.map.entries.empty()) {
    out.line("[0 " + colour(Color(0.0f), {}, scale, filter, transmit) + "]");
    out.line("[1 " + colour(Color(1.0f), {}, scale, filter, transmit) + "]");
  } else {
    for (const ColorMapEntry& e : t.map.entries)
      out.line("[" + povNumber(e.at) + " " + colour(e.color, e.ft, scale, filter, transmit) + "]");
  }
  out.close();
  writeValueModifiers(t.pattern, out);
  writePlacement(t.pattern.placement, out);
  out.close();
}

void writeCheckerPigment(const CheckerTexture& checker, const Vec3& scale, double filter,
                         double transmit, PovWriter& out) {
  // Cells of edge `scale`; the cell [0, scale)^3 has the first colour, as in Lucent.
  out.open("pigment");
  out.line(std::string(CheckerTexture::kind.pov));
  out.line(colour(checker.color1, checker.ft1, scale, filter, transmit) + ",");
  out.line(colour(checker.color2, checker.ft2, scale, filter, transmit));
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
    if (p.patternFromObject != Mat4(1.0)) out.line(povMatrix(glm::inverse(p.patternFromObject)));
  } else {
    if (checker.scale != 1.0) out.line("scale " + povNumber(checker.scale));
    writePlacement(p, out);
  }
  out.close();
}

void writeHexagonPigment(const HexagonTexture& t, const Vec3& scale, double filter, double transmit,
                         PovWriter& out) {
  out.open("pigment");
  out.line(std::string(HexagonTexture::kind.pov));
  for (int i = 0; i < 3; ++i)
    out.line(colour(t.spec.colors[i], t.spec.ft[i], scale, filter, transmit) + (i < 2 ? "," : ""));
  writePlacement(t.placement, out);
  out.close();
}

void writeBrickPigment(const BrickTexture& t, const Vec3& scale, double filter, double transmit,
                       PovWriter& out) {
  out.open("pigment");
  out.line(std::string(BrickTexture::kind.pov));
  out.line(colour(t.spec.color1, t.spec.ft1, scale, filter, transmit) + ",");
  out.line(colour(t.spec.color2, t.spec.ft2, scale, filter, transmit));
  out.line("brick_size " + povVector(t.spec.size) + " mortar " + povNumber(t.spec.mortar));
  writePlacement(t.placement, out);
  out.close();
}

void writeNormal(const NormalSpec& n, PovWriter& out) {
  out.open("normal");
  std::string keyword = patternKeyword(n.pattern);
  const std::string agate = " agate_turb 1";
  if (keyword.size() > agate.size() &&
      keyword.compare(keyword.size() - agate.size(), agate.size(), agate) == 0)
    out.line(keyword.substr(0, keyword.size() - agate.size()) + " " + povNumber(n.depth) + agate);
  else out.line(keyword + " " + povNumber(n.depth));
  // POV-Ray's slope method samples at this distance (its default, which Lucent uses).
  out.line("accuracy 0.02");
  writeValueModifiers(n.pattern, out);
  writePlacement(n.pattern.placement, out);
  out.close();
}

}  // namespace lucent
