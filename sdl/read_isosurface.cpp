// `isosurface { function { F } contained_by { box {A, B} | sphere {C, R} } threshold T
// accuracy E max_gradient G evaluate P0, P1, P2 max_trace N all_intersections open }` into Lucent's
// isosurface (docs/scene-language.md, <isosurface>). The function becomes Lucent expression text
// (function.h, functionText): its user functions inlined, the internal functions Lucent has
// formulas for written out. Lucent's space is POV-Ray's with z negated, so the text is F(x, y, -z)
// and the container's z is negated: both exact (a negation rounds nothing).
#include "read_support.h"
#include "scene_reader.h"

#include "lang/expression.h"
#include "lang/expression_field.h"

namespace lucent::sdl {

namespace {

// An isosurface's text names only x, y and z.
class NoNames final : public ExpressionNames {
 public:
  std::optional<double> number(std::string_view name, std::string& error, bool& known) override {
    known = false;
    error = "unknown name '" + std::string(name) + "'";
    return std::nullopt;
  }
  std::vector<std::string> visibleNames() override { return {}; }
};

}  // namespace

IsosurfaceContainer readContainedBy(TokenStream& in) {
  IsosurfaceContainer c;
  in.expect("{");
  const Token shape = in.next();
  in.expect("{");
  if (isWord(shape, "box")) {
    const Vec3 a = lucentFromPov(toVec3(in.parseVector()));
    in.parseComma();
    const Vec3 b = lucentFromPov(toVec3(in.parseVector()));
    c.kind = IsosurfaceContainer::Box;
    c.min = glm::min(a, b);
    c.max = glm::max(a, b);
  } else if (isWord(shape, "sphere")) {
    c.kind = IsosurfaceContainer::Sphere;
    c.center = lucentFromPov(toVec3(in.parseVector()));
    in.parseComma();
    c.radius = in.parseFloat();
  } else {
    in.error(shape, "expected box or sphere in contained_by, found " + shape.describe());
  }
  in.expect("}");
  in.expect("}");
  return c;
}

std::optional<FunctionInput> SceneReader::compiledFunction(
    const FunctionValue& f, const std::vector<std::string>& names, const char* what,
    TokenStream& in, const std::vector<std::string>& variables) {
  std::string text;
  std::vector<PigmentCall> calls;
  std::vector<std::shared_ptr<const PigmentFunction>> pigments;
  try {
    text = functionText(f, names, &calls);
    pigments = pigmentFunctions(calls, in);
  } catch (const FunctionError& e) {
    std::string m = std::string(what) + " cannot be imported: " + std::string(e.what());
    if (e.at.line > 0 && e.at.str() != f.loc.str())
      m += "\n" + e.at.str() + ": note: the cause, in the function's text";
    keepError(in, f.loc, m);
    return std::nullopt;
  }
  auto compile = [&] {
    NoNames noNames;
    ExpressionError problem;
    std::optional<FunctionText> compiled =
        compileFunction(text, variables, noNames, problem, pigments);
    if (!compiled)
      in.error(f.loc, std::string(what) + ", written as '" + text +
                          "', is not a Lucent expression: " + problem.message);
    return makeExpressionField(*compiled);
  };
  FunctionInput out;
  out.text = text;
  out.pigments = pigments;
  // A macro that makes the same function again gets the field compiled the first time: the
  // text and its variables say all of it (not so with pigments: the names of the pigments
  // it calls do not tell which pigments they are).
  if (!pigments.empty()) {
    out.field = compile();
    return out;
  }
  const std::string key = text + " | " + variables.front();
  std::shared_ptr<const ScalarField>& field = compiledFields_[key];
  if (!field) {
    try {
      field = compile();
    } catch (...) {
      compiledFields_.erase(key);
      throw;
    }
  }
  out.field = field;
  return out;
}

std::shared_ptr<const PatternFunction> SceneReader::readPatternFunction(TokenStream& in) {
  const std::shared_ptr<const FunctionValue> f = in.parseFunction(false, "");
  // A pattern is evaluated in POV-Ray's space: the names as they are.
  const auto compiled = compiledFunction(*f, {"x", "y", "z"}, "this function pattern", in);
  if (!compiled) return nullptr;
  return std::make_shared<const PatternFunction>(
      PatternFunction{compiled->text, {}, compiled->field, compiled->pigments});
}

void SceneReader::readIsosurface(PovObject& o, TokenStream& in) {
  const Token fn = in.next();
  if (!isWord(fn, "function"))
    in.error(fn, "expected 'function' first in an isosurface, found " + fn.describe());
  const std::shared_ptr<const FunctionValue> f = in.parseFunction(false, "");
  IsosurfaceSpec s;
  for (;;) {
    const Token t = in.next();
    const std::string_view w = t.kind == TokenKind::Keyword ? t.text() : "";
    if (w == "contained_by") {
      s.container = readContainedBy(in);
    } else if (w == "threshold") {
      s.threshold = in.parseFloat();
    } else if (w == "accuracy") {
      s.accuracy = in.parseFloat();
    } else if (w == "max_gradient") {
      s.maxGradient = in.parseFloat();
    } else if (w == "max_trace") {
      in.parseFloat();  // Lucent finds every crossing (POV-Ray's all_intersections)
    } else if (w == "all_intersections") {
      // Lucent's way already.
    } else if (w == "evaluate") {
      for (int i = 0; i < 3; ++i) {
        if (i > 0) in.parseComma();
        in.parseFloat();
      }
      warn(in, t.loc(),
           "'evaluate' (POV-Ray's adaptive max_gradient) is not imported: Lucent searches "
           "with max_gradient " +
               formatNumber(s.maxGradient) + " and warns after rendering if it is too low");
    } else if (w == "open") {
      s.open = true;
    } else {
      in.unget();
      break;
    }
  }
  // POV-Ray's own corrections, with its warnings.
  if (s.accuracy <= 0.0) {
    warn(in, o.loc, "isosurface 'accuracy' is not positive: 0.001 is used (as POV-Ray does)");
    s.accuracy = 0.001;
  }
  if (s.maxGradient <= 0.0) {
    warn(in, o.loc, "isosurface 'max_gradient' is not positive: 1.1 is used (as POV-Ray does)");
    s.maxGradient = 1.1;
  }
  if (s.container.kind == IsosurfaceContainer::Sphere && !(s.container.radius > 0.0))
    in.error(o.loc, "the isosurface's contained_by sphere needs a radius > 0");
  // Lucent's space is POV-Ray's with z negated.
  const auto compiled = compiledFunction(*f, {"x", "y", "(-z)"}, "this isosurface's function", in);
  if (!compiled) return;
  s.function = compiled->text;
  s.field = compiled->field;
  s.pigments = compiled->pigments;
  o.shape = s;
}

}  // namespace lucent::sdl
