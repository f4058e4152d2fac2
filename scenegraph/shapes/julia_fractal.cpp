// <julia-fractal c="x y z t" algebra="quaternion" function="sqr" exponent="re im"
//                max-iteration="20" precision="20" slice="0 0 0 1" distance="0"/>:
// POV-Ray 3.7's julia_fractal (primitives/julia_fractal.h), with POV-Ray's defaults and its
// errors (a quaternion takes sqr and cube only; the slice may be neither zero nor without
// t). POV-Ray makes a max_iteration below 1 one and a precision below 1 one; Lucent asks
// for 1 or more of each.
#include "scenegraph/shape_type.h"

#include "primitives/julia_fractal.h"

#include <fmt/format.h>

#include <cmath>

namespace lucent {

namespace {

const std::vector<std::string_view> kAlgebras = {"quaternion", "hypercomplex"};
// In JuliaFunction's order.
const std::vector<std::string_view> kFunctions = {
    "sqr", "cube", "reciprocal", "exp",   "ln",   "sin",   "asin", "cos",   "acos",
    "tan", "atan", "sinh",       "asinh", "cosh", "acosh", "tanh", "atanh", "pwr"};

bool readFour(AttributeInput& in, const char* attr, Vec4& out) {
  if (!in.has(attr)) return true;
  auto list = in.numbers(attr);
  if (!list) return false;
  if (list->size() != 4) {
    in.attrError(attr, fmt::format("expected 4 numbers (x y z t), got {}", list->size()));
    return false;
  }
  out = Vec4((*list)[0], (*list)[1], (*list)[2], (*list)[3]);
  return true;
}

void readJulia(JuliaFractalSpec& s, AttributeInput& in) {
  s.algebra =
      static_cast<JuliaAlgebra>(in.choice("algebra", static_cast<size_t>(s.algebra), kAlgebras));
  s.function = static_cast<JuliaFunction>(
      in.choice("function", static_cast<size_t>(s.function), kFunctions));
  s.maxIteration = static_cast<int>(in.integer("max-iteration", s.maxIteration, 1, 1000000));
  // The lists after the choices and numbers (the scene writer learns those by reading).
  if (!in.has("c")) {
    in.error("<julia-fractal> needs 'c' (the Julia parameter, 4 numbers x y z t)");
    return;
  }
  if (!readFour(in, "c", s.c)) return;
  if (s.algebra == JuliaAlgebra::Quaternion && s.function != JuliaFunction::Sqr &&
      s.function != JuliaFunction::Cube) {
    in.attrError("function",
                 "a quaternion julia fractal takes 'sqr' or 'cube' only (POV-Ray's "
                 "rule); the other functions need algebra=\"hypercomplex\"");
    return;
  }
  if (in.has("exponent")) {
    if (s.function != JuliaFunction::Pwr) {
      in.attrError("exponent", "'exponent' is the power of function=\"pwr\" only");
      return;
    }
    auto list = in.numbers("exponent");
    if (!list) return;
    if (list->size() != 2) {
      in.attrError("exponent", fmt::format("expected 2 numbers (the complex power's real and "
                                           "imaginary parts), got {}",
                                           list->size()));
      return;
    }
    s.exponent = Vec2((*list)[0], (*list)[1]);
  } else if (s.function == JuliaFunction::Pwr) {
    in.attrError("function", "function=\"pwr\" needs 'exponent' (re im, POV-Ray's pwr(X, Y))");
    return;
  }
  if (!readFour(in, "slice", s.slice)) return;
  // POV-Ray's checks, before the slice is made unit.
  if (!(glm::dot(s.slice, s.slice) >= 1e-10)) {
    in.attrError("slice", "the slice vector is zero");
    return;
  }
  if (!(std::fabs(s.slice.w) >= 1e-10))
    in.attrError("slice", "the slice's t component is zero (the slice must cross the t axis)");
}

std::string four(const Vec4& v, PovShapeOut& out) {
  return fmt::format("<{}, {}, {}, {}>", out.number(v.x), out.number(v.y), out.number(v.z),
                     out.number(v.w));
}

void writeJulia(const JuliaFractalSpec& s, PovShapeOut& out) {
  out.open("julia_fractal");
  out.line(four(s.c, out));
  out.line(std::string(kAlgebras[static_cast<size_t>(s.algebra)]));
  if (s.function == JuliaFunction::Pwr)
    out.line(fmt::format("pwr({}, {})", out.number(s.exponent.x), out.number(s.exponent.y)));
  else out.line(std::string(kFunctions[static_cast<size_t>(s.function)]));
  out.line(fmt::format("max_iteration {}", s.maxIteration));
  out.line("precision " + out.number(s.precision));
  out.line("slice " + four(s.slice, out) + ", " + out.number(s.distance));
}

JuliaFractalSpec sample(Vec4 c, JuliaAlgebra a, JuliaFunction f, int n, double precision) {
  JuliaFractalSpec s;
  s.c = c;
  s.algebra = a;
  s.function = f;
  s.maxIteration = n;
  s.precision = precision;
  return s;
}

}  // namespace

template <>
ShapeEntry<JuliaFractalSpec> shapeEntry<JuliaFractalSpec>() {
  ShapeEntry<JuliaFractalSpec> e(
      "julia-fractal", "julia fractals",
      [](const JuliaFractalSpec& s) { return std::make_shared<JuliaFractal>(s); }, writeJulia);
  e.doc =
      "POV-Ray's julia_fractal: the 3-D slice of a 4-D quaternion or hypercomplex Julia set, "
      "traced as POV-Ray traces it (solid).";
  Field<JuliaFractalSpec> maxIteration =
      readByEntry<JuliaFractalSpec>("max-iteration", AttrType::Number, "20");
  maxIteration.info.schemaType = "wholeNumber";
  e.fields = {
      readByEntry<JuliaFractalSpec>("c", AttrType::NumberList, "", {}, 4)
          .doc("The Julia parameter: the 4-D point c of q → f(q) + c, x y z t."),
      readByEntry<JuliaFractalSpec>("algebra", AttrType::Choice, "quaternion", kAlgebras)
          .doc("quaternion (f is sqr or cube) | hypercomplex (any function)."),
      readByEntry<JuliaFractalSpec>("function", AttrType::Choice, "sqr", kFunctions)
          .doc("f: sqr | cube | reciprocal | exp | ln | sin | asin | cos | acos | tan | atan | "
               "sinh | asinh | cosh | acosh | tanh | atanh | pwr (with exponent). A hypercomplex "
               "cube is iterated as sqr, as in POV-Ray."),
      readByEntry<JuliaFractalSpec>("exponent", AttrType::NumberList, "", {}, 2)
          .doc("pwr's complex power, re im (POV-Ray's pwr(X, Y)); only with function=\"pwr\"."),
      std::move(maxIteration).doc("The iterations after which a point counts as in the set."),
      numberField<JuliaFractalSpec>("precision", &JuliaFractalSpec::precision,
                                    NumberRule::between(1.0, kInf, "a number of 1 or more"))
          .doc("The march's smallest step is 1 / precision (POV-Ray's precision)."),
      readByEntry<JuliaFractalSpec>("slice", AttrType::NumberList, "0 0 0 1", {}, 4)
          .doc("The normal of the 3-D slice through 4-D space, x y z t (t not 0; made unit)."),
      numberField<JuliaFractalSpec>("distance", &JuliaFractalSpec::distance)
          .doc("The slice's distance from the origin, along its normal made unit.")};
  e.fields[0].info.required = true;
  e.finish = readJulia;
  e.samples = [] {
    using A = JuliaAlgebra;
    using F = JuliaFunction;
    JuliaFractalSpec sliced = sample({-0.03, 0.5, -0.2, -0.5}, A::Quaternion, F::Sqr, 8, 60);
    sliced.slice = Vec4(0.2, 0.0, 0.3, 1.0);
    sliced.distance = 0.1;
    return std::vector<std::pair<std::string, JuliaFractalSpec>>{
        {"quaternion sqr julia",
         sample({-0.083, 0.0, -0.83, -0.025}, A::Quaternion, F::Sqr, 8, 60)},
        {"quaternion cube julia", sample({-0.03, 0.5, -0.2, -0.5}, A::Quaternion, F::Cube, 8, 60)},
        {"sliced quaternion julia", sliced},
        {"hypercomplex sqr julia", sample({0.2, 0.1, 0.59, -0.2}, A::Hypercomplex, F::Sqr, 7, 60)}};
  };
  return e;
}

}  // namespace lucent
