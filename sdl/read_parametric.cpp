// `parametric { function { X } function { Y } function { Z } <u1, v1>, <u2, v2>
// contained_by { box {A, B} | sphere {C, R} } max_gradient G accuracy E precompute D, x, y, z }`
// into Lucent's parametric (docs/scene-language.md, <parametric>), read as POV-Ray's parser
// reads it (its Parse_Parametric, taken as facts): the rectangle's corners sorted, the
// options in any order. In POV-Ray's functions u and v are other names of x and y; a
// function's z is left 0. Lucent's space is POV-Ray's with z negated, so the z function is
// negated and the container's z too: exact (a negation rounds nothing), and the search's
// bounds of −z are exactly the negated bounds of z.
#include "read_support.h"
#include "scene_reader.h"

#include "lang/expression.h"
#include "primitives/parametric.h"
#include "sdl/pov_space.h"

#include <algorithm>

namespace lucent::sdl {

namespace {

// −f: the z coordinate in Lucent's space.
class NegatedField final : public ScalarField {
 public:
  explicit NegatedField(std::shared_ptr<const ScalarField> f) : f_(std::move(f)) {}
  double value(const Vec3& p) const override { return -f_->value(p); }

 private:
  std::shared_ptr<const ScalarField> f_;
};

}  // namespace

void SceneReader::readParametric(PovObject& o, TokenStream& in) {
  ParametricSpec s;
  auto functions = std::make_shared<ParametricFunctions>();
  bool complete = true;
  static const char* const kWhat[] = {"this parametric's x function",
                                      "this parametric's y function",
                                      "this parametric's z function"};
  for (int i = 0; i < 3; ++i) {
    if (i > 0) in.parseComma();
    const Token fn = in.next();
    if (!isWord(fn, "function"))
      in.error(fn, "expected 'function' (the parametric's " + std::string(1, "xyz"[i]) +
                       " coordinate), found " + fn.describe());
    const std::shared_ptr<const FunctionValue> f = in.parseFunction(false, "");
    const auto compiled = compiledFunction(*f, {"u", "v", "0"}, kWhat[i], in, {"u", "v"});
    if (!compiled) {
      complete = false;
      continue;
    }
    if (i < 2) {
      functions->text[i] = compiled->text;
      functions->fields[i] = compiled->field;
    } else {
      functions->text[i] = "-(" + compiled->text + ")";
      functions->fields[i] = std::make_shared<NegatedField>(compiled->field);
    }
  }
  const SourceLoc rectangleAt = in.peek().loc();
  Vec2 a = parseUv(in);
  in.parseComma();
  Vec2 b = parseUv(in);
  s.uvMin = glm::min(a, b);
  s.uvMax = glm::max(a, b);
  if (!(s.uvMin.x < s.uvMax.x && s.uvMin.y < s.uvMax.y))
    in.error(rectangleAt, "the parametric's (u, v) rectangle is empty (u " +
                              formatNumber(s.uvMin.x) + " to " + formatNumber(s.uvMax.x) + ", v " +
                              formatNumber(s.uvMin.y) + " to " + formatNumber(s.uvMax.y) +
                              "): it has no surface");
  // POV-Ray's defaults: the box <-1, -1, -1>, <1, 1, 1>, max_gradient 1, accuracy 0.001.
  for (;;) {
    const Token t = in.next();
    const std::string_view w = t.kind == TokenKind::Keyword ? t.text() : "";
    if (w == "contained_by") {
      s.container = readContainedBy(in);
      if (s.container.kind == IsosurfaceContainer::Sphere && !(s.container.radius > 0.0))
        in.error(t, "the parametric's contained_by sphere needs a radius > 0");
    } else if (w == "accuracy") {
      const SourceLoc at = in.peek().loc();
      s.accuracy = in.parseFloat();
      if (!(s.accuracy > 0.0)) in.error(at, "the parametric's accuracy must be > 0");
    } else if (w == "max_gradient") {
      const SourceLoc at = in.peek().loc();
      s.maxGradient = in.parseFloat();
      if (!(s.maxGradient > 0.0)) in.error(at, "the parametric's max_gradient must be > 0");
    } else if (w == "precompute") {
      const SourceLoc at = in.peek().loc();
      const double depth = in.parseFloat();
      // POV-Ray's own error for a depth outside 1 to 20 (it truncates the float).
      if (!(depth >= 1.0 && depth < Parametric::kMaxPrecompute + 1.0))
        in.error(at,
                 "the parametric's precompute depth must be from 1 to 20 (POV-Ray's "
                 "'Precompute: invalid depth')");
      s.precomputeDepth = static_cast<int>(depth);
      // Then x, y and z, each optional, in that order, with optional commas.
      for (int i = 0; i < 3; ++i) {
        in.parseComma();
        const Token c = in.peek();
        if (c.kind == TokenKind::Keyword && c.text() == std::string(1, "xyz"[i])) {
          in.next();
          s.precompute[i] = true;
        }
      }
    } else {
      in.unget();
      break;
    }
  }
  if (!complete) return;
  s.functions = functions;
  std::string problem;
  if (!shareParametricIntervals(s, problem)) in.error(o.loc, problem);
  o.shape = s;
}

}  // namespace lucent::sdl
