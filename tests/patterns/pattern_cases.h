// The cases of tests/data/patterns/make_references.sh as Lucent specs: each name here is a
// line of the script's case lists, with the same pattern, modifiers and colours.
#pragma once

#include "scenegraph/pattern.h"
#include "scenegraph/texture_spec.h"

#include <cmath>
#include <map>
#include <memory>
#include <string>

namespace lucent::test {

// POV-Ray's inverse transforms (matrices.cpp), as patternFromObject matrices.
inline Mat4 inverseScale(const Vec3& s) {
  Mat4 m(1.0);
  m[0][0] = 1.0 / s.x;
  m[1][1] = 1.0 / s.y;
  m[2][2] = 1.0 / s.z;
  return m;
}
inline Mat4 inverseTranslate(const Vec3& t) {
  Mat4 m(1.0);
  m[3] = Vec4(-t, 1.0);
  return m;
}
// The inverse of POV-Ray's `rotate <a, b, c>` (x, then y, then z; degrees).
inline Mat4 inverseRotate(const Vec3& degrees) {
  const double k = 0.01745329251994329576;  // POV-Ray's M_PI_180
  const Vec3 r = degrees * k;
  Mat4 x(1.0), y(1.0), z(1.0);
  // Written as POV-Ray's row-vector matrices, which have glm's memory layout.
  x[1][1] = x[2][2] = std::cos(r.x);
  x[1][2] = std::sin(r.x);
  x[2][1] = 0.0 - std::sin(r.x);
  y[0][0] = y[2][2] = std::cos(r.y);
  y[0][2] = 0.0 - std::sin(r.y);
  y[2][0] = std::sin(r.y);
  z[0][0] = z[1][1] = std::cos(r.z);
  z[0][1] = std::sin(r.z);
  z[1][0] = 0.0 - std::sin(r.z);
  // Row-vector forward = x·y·z; its inverse is the transpose (a rotation).
  return glm::transpose(z * y * x);
}
// `first` then `second` in POV-Ray's modifier order, both given as inverses.
inline Mat4 then(const Mat4& firstInverse, const Mat4& secondInverse) {
  return firstInverse * secondInverse;
}

inline PatternSpec spec(PatternType type) {
  PatternSpec s;
  s.type = type;
  return s;
}
inline PatternSpec generator(PatternSpec s, int g) {
  s.noiseGenerator = g;
  return s;
}
inline PatternSpec turbulent(PatternSpec s, Vec3 t, int octaves = 6, double omega = 0.5,
                             double lambda = 2.0) {
  s.placement.turbulence = t;
  s.placement.octaves = octaves;
  s.placement.omega = omega;
  s.placement.lambda = lambda;
  return s;
}
inline PatternSpec agateTurb(PatternSpec s, double turb) {
  s.agateTurb = turb;
  return s;
}
inline PatternSpec waved(PatternSpec s, WaveShape w, double exponent = 1.0) {
  s.wave = w;
  s.exponent = exponent;
  return s;
}
inline PatternSpec tuned(PatternSpec s, double frequency, double phase) {
  s.frequency = frequency;
  s.phase = phase;
  return s;
}
inline PatternSpec placed(PatternSpec s, const Mat4& patternFromObject) {
  s.placement.patternFromObject = patternFromObject;
  return s;
}
inline PatternSpec axis(PatternSpec s, Vec3 a) {
  s.axis = a;
  return s;
}
inline PatternSpec arms(PatternSpec s, int n) {
  s.arms = n;
  return s;
}
inline PatternSpec crackle(double metric, Vec3 form, double offset, bool solid = false) {
  PatternSpec s = spec(PatternType::crackle);
  s.crackle.metric = metric;
  s.crackle.form = form;
  s.crackle.offset = offset;
  s.crackle.solid = solid;
  return s;
}

inline PatternSpec quilted(double control0, double control1) {
  PatternSpec s = spec(PatternType::quilted);
  s.frequency = 0.0;  // POV-Ray's default for quilted
  s.quilted.control0 = control0;
  s.quilted.control1 = control1;
  return s;
}
// pigment_pattern of the texture `t`.
inline PatternSpec pigmentPattern(Texture t) {
  PatternSpec s = spec(PatternType::pigment);
  auto e = std::make_shared<TextureMapEntry>();
  e->texture = std::move(t);
  s.pigment = std::move(e);
  return s;
}
inline PatternTexture withMap(PatternSpec s, std::vector<ColorMapEntry> entries) {
  PatternTexture t;
  t.pattern = std::move(s);
  t.map.entries = std::move(entries);
  return t;
}

// mandel or julia (c = re + im i) with `iterations`, the exponent `power` and the
// colourings {type, factor}.
inline PatternSpec fractal(PatternType type, int iterations, int power = 2,
                           FractalColouring exterior = {1, 1.0},
                           FractalColouring interior = {0, 1.0}, double re = 0, double im = 0) {
  PatternSpec s = spec(type);
  s.fractal.iterations = iterations;
  s.fractal.power = power;
  s.fractal.exterior = exterior;
  s.fractal.interior = interior;
  s.fractal.cReal = re;
  s.fractal.cImaginary = im;
  return s;
}
inline PatternSpec julia(double re, double im, int iterations, int power = 2,
                         FractalColouring exterior = {1, 1.0},
                         FractalColouring interior = {0, 1.0}) {
  return fractal(PatternType::julia, iterations, power, exterior, interior, re, im);
}
// magnet of `type` (1 or 2), the Julia form when juliaForm (c = re + im i).
inline PatternSpec magnet(int type, bool juliaForm, int iterations,
                          FractalColouring exterior = {1, 1.0},
                          FractalColouring interior = {0, 1.0}, double re = 0, double im = 0) {
  PatternSpec s = fractal(PatternType::magnet, iterations, 2, exterior, interior, re, im);
  s.fractal.magnetType = type;
  s.fractal.juliaForm = juliaForm;
  return s;
}

// patterns.csv
inline std::map<std::string, PatternSpec> patternCases() {
  using T = PatternType;
  const Vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const Vec3 form(-1, 1, 0);
  return {
      {"gradient", axis(spec(T::gradient), Vec3(1, 2, -0.5))},
      {"onion", spec(T::onion)},
      {"radial", spec(T::radial)},
      {"spiral1", arms(spec(T::spiral1), 3)},
      {"spiral2", arms(spec(T::spiral2), 5)},
      {"wood", spec(T::wood)},
      {"marble", spec(T::marble)},
      {"agate", spec(T::agate)},
      {"granite", spec(T::granite)},
      {"bozo", spec(T::bozo)},
      {"spotted", spec(T::spotted)},
      {"leopard", spec(T::leopard)},
      {"crackle", spec(T::crackle)},
      {"wrinkles", spec(T::wrinkles)},
      {"bumps", spec(T::bumps)},
      {"dents", spec(T::dents)},
      {"ripples", spec(T::ripples)},
      {"waves", spec(T::waves)},
      {"bozo_generator1", generator(spec(T::bozo), 1)},
      {"bozo_generator3", generator(spec(T::bozo), 3)},
      {"bozo_far", spec(T::bozo)},
      {"granite_generator1", generator(spec(T::granite), 1)},
      {"granite_generator3", generator(spec(T::granite), 3)},
      {"agate_generator1", generator(spec(T::agate), 1)},
      {"wrinkles_generator1", generator(spec(T::wrinkles), 1)},
      {"dents_generator3", generator(spec(T::dents), 3)},
      {"spotted_generator1", generator(spec(T::spotted), 1)},
      {"crackle_far", spec(T::crackle)},
      {"crackle_metric1", crackle(1, x, 0)},
      {"crackle_metric3", crackle(3, Vec3(-0.5, 1.2, 0.3), 0.2)},
      {"crackle_offset", crackle(2, form, 0.5)},
      {"crackle_solid", crackle(2, form, 0, true)},
      {"crackle_solid_generator1", generator(crackle(2, form, 0, true), 1)},
      {"ripples_frequency", tuned(spec(T::ripples), 2.5, 0.3)},
      {"waves_frequency", tuned(spec(T::waves), 0.7, -0.2)},
      {"turbulence_scalar", turbulent(spec(T::bozo), Vec3(0.5))},
      {"turbulence_vector", turbulent(spec(T::bozo), Vec3(0.2, 0.6, 1.1), 3, 0.7, 2.5)},
      {"turbulence_generator3", generator(turbulent(spec(T::bozo), Vec3(0.7)), 3)},
      {"turbulence_generator1", generator(turbulent(spec(T::granite), Vec3(0.3)), 1)},
      {"turbulence_octaves_clamped", turbulent(spec(T::onion), Vec3(0.2), 12)},
      {"dnoise_x", tuned(turbulent(axis(spec(T::gradient), x), x, 1), 0, 0)},
      {"dnoise_y", tuned(turbulent(axis(spec(T::gradient), y), y, 1), 0, 0)},
      {"dnoise_z", tuned(turbulent(axis(spec(T::gradient), z), z, 1), 0, 0)},
      {"marble_turbulence", turbulent(spec(T::marble), Vec3(0.8))},
      {"marble_octaves", turbulent(spec(T::marble), Vec3(1.5, 0, 0), 9, 0.35, 3.1)},
      {"wood_turbulence", turbulent(spec(T::wood), Vec3(0.3, 0.2, 0.1))},
      {"spiral1_turbulence", turbulent(arms(spec(T::spiral1), 2), Vec3(0.4))},
      {"spiral2_turbulence", turbulent(arms(spec(T::spiral2), 4), Vec3(0.1, 0.3, 0.2), 4)},
      {"agate_octaves", turbulent(spec(T::agate), Vec3(0.0), 3, 0.6, 1.7)},
      {"agate_turbulence", turbulent(spec(T::agate), Vec3(0.3))},
      {"agate_turb", agateTurb(turbulent(spec(T::agate), Vec3(0.2)), 0.35)},
      {"onion_frequency", tuned(spec(T::onion), 3, 0.25)},
      {"gradient_negative_frequency", tuned(axis(spec(T::gradient), y), -2.5, 0.1)},
      {"bozo_frequency0", tuned(spec(T::bozo), 0, 0.5)},
      {"onion_sine", waved(spec(T::onion), WaveShape::sine)},
      {"onion_triangle", waved(spec(T::onion), WaveShape::triangle)},
      {"onion_scallop", waved(spec(T::onion), WaveShape::scallop)},
      {"onion_cubic", waved(spec(T::onion), WaveShape::cubic)},
      {"onion_poly", waved(spec(T::onion), WaveShape::poly, 2.5)},
      {"marble_ramp", waved(spec(T::marble), WaveShape::ramp)},
      {"wood_sine", tuned(waved(spec(T::wood), WaveShape::sine), 0.3, 0)},
      {"bozo_transform",
       placed(spec(T::bozo), then(inverseScale(Vec3(0.37)), inverseTranslate(Vec3(1, 2, 3))))},
      {"gradient_rotate", placed(axis(spec(T::gradient), x), inverseRotate(Vec3(0, 0, 30)))},
      {"marble_scaled_turbulence",
       placed(turbulent(spec(T::marble), Vec3(0.5)), inverseScale(Vec3(2, 0.5, 1)))},
      {"planar", spec(T::planar)},
      {"planar_sine", tuned(waved(spec(T::planar), WaveShape::sine), 2, 0)},
      {"planar_turbulence",
       placed(turbulent(spec(T::planar), Vec3(0.4)), inverseRotate(Vec3(0, 0, 30)))},
      {"quilted", quilted(1, 1)},
      {"quilted_controls", quilted(0.3, 0.8)},
      {"quilted_frequency", tuned(quilted(0, 0.5), 2, 0.1)},
      {"mandel", fractal(T::mandel, 30)},
      {"mandel_colourings", fractal(T::mandel, 20, 2, {6, 0.2}, {1, 1})},
      {"mandel3", fractal(T::mandel, 25, 3, {1, 1}, {5, 2})},
      {"mandel4", fractal(T::mandel, 25, 4, {2, 0.3}, {2, 0.7})},
      {"mandel7", fractal(T::mandel, 15, 7, {5, 3}, {3, 0.5})},
      {"mandel_placed", placed(fractal(T::mandel, 25, 2, {0, 0.3}, {6, 0.5}),
                               then(then(inverseScale(Vec3(0.5)), inverseRotate(Vec3(0, 0, 30))),
                                    inverseTranslate(Vec3(-0.5, 0, 0))))},
      {"julia", julia(0.3, 0.44, 30, 2, {1, 1}, {1, 1})},
      {"julia3", julia(-0.5, 0.5, 20, 3, {2, 4})},
      {"julia4", julia(0.2, -0.6, 20, 4, {4, 0.1}, {4, 1})},
      {"julia9", julia(0.1, 0.2, 12, 9, {5, 0.3}, {6, 0.5})},
      {"julia33", julia(0.4, 0.1, 8, 33, {3, 0.2}, {1, 1})},
      {"magnet1m", magnet(1, false, 40, {1, 1}, {1, 0.5})},
      {"magnet1j", magnet(1, true, 30, {6, 0.01}, {0, 1}, 0.4, 0.1)},
      {"magnet2m", magnet(2, false, 30, {0, 0.3}, {1, 0.4})},
      {"magnet2j", magnet(2, true, 25, {1, 1}, {0, 1}, 1.1, 0.3)},
      {"spherical", spec(T::spherical)},
      {"spherical_sine", tuned(waved(spec(T::spherical), WaveShape::sine), 3, 0.2)},
      {"cylindrical", spec(T::cylindrical)},
      {"cylindrical_turbulence",
       placed(turbulent(spec(T::cylindrical), Vec3(0.3)), inverseScale(Vec3(1, 2, 0.5)))},
      {"boxed", spec(T::boxed)},
      {"boxed_rotated",
       tuned(waved(placed(spec(T::boxed), inverseRotate(Vec3(20, 30, 0))), WaveShape::triangle), 2,
             0)},
      {"cells", spec(T::cells)},
      {"cells_placed",
       placed(spec(T::cells), then(inverseScale(Vec3(0.3)), inverseTranslate(Vec3(0.5, 0, 0))))},
      {"cells_far", spec(T::cells)},
      {"cells_turbulence", tuned(turbulent(spec(T::cells), Vec3(0.5)), 1.5, 0.1)},
      {"pigment_checker", pigmentPattern([] {
         CheckerTexture c;
         c.color1 = Color(1, 0.5, 0);
         c.color2 = Color(0, 0.2, 1);
         c.placement.patternFromObject = inverseScale(Vec3(0.5));
         return c;
       }())},
      {"pigment_gradient",
       tuned(waved(pigmentPattern(withMap(axis(spec(T::gradient), x),
                                          {{0, Color(1, 0, 0)}, {1, Color(0.2, 0.9, 0.4)}})),
                   WaveShape::sine),
             2, 0)},
      {"pigment_granite",
       placed(
           turbulent(pigmentPattern(withMap(placed(spec(T::granite), inverseScale(Vec3(0.3))), {})),
                     Vec3(0.2)),
           inverseScale(Vec3(1.5)))},
  };
}

}  // namespace lucent::test
