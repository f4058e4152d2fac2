// `#declare F = function { pigment { P } }` called as `F(x, y, z).red` in an isosurface's or
// a function pattern's function: the calls stay in the function's Lucent text as calls of
// names (function.h, PigmentCall), and each name is bound here to P as a Lucent texture
// placed in POV-Ray's space (the function's x, y and z are POV-Ray's), with its component.
#include "scene_reader.h"

#include "lang/pigment_call.h"
#include "scenegraph/pigment_function.h"

namespace lucent::sdl {

namespace {

// A pigment as a texture of its own: a plain colour becomes a one-entry map.
Texture pigmentTexture(const PovPigment& pigment) {
  TextureMapEntry e = entryOf(pigment, 0.0);
  if (!std::holds_alternative<std::monostate>(e.texture)) return e.texture;
  PatternTexture plain;
  plain.pattern.type = PatternType::gradient;
  plain.map.entries = {{0.0, e.color.rgb, e.color.ft}};
  return plain;
}

// The component a call of f takes: a pattern function's value is the pattern's own (in
// double precision, as POV-Ray's); a block pattern's cell index is its grey's exact red.
PigmentComponent component(const FunctionValue& f, const Texture& pigment, int member) {
  const auto* pattern = std::get_if<PatternTexture>(&pigment);
  if (f.what == "a pattern function" && pattern && pattern->pigments.empty())
    return PigmentComponent::value;
  return static_cast<PigmentComponent>(member);
}

}  // namespace

std::vector<std::shared_ptr<const PigmentFunction>> SceneReader::pigmentFunctions(
    const std::vector<PigmentCall>& calls, TokenStream& in) {
  std::vector<std::shared_ptr<const PigmentFunction>> out;
  for (const PigmentCall& c : calls) {
    const auto* item = dynamic_cast<const PigmentItem*>(c.callee->pigment.get());
    if (!item) throw FunctionError(c.callee->loc, c.callee->describe() + " holds no pigment");
    reportRefused(*item, c.callee->loc, in);
    auto f = std::make_shared<PigmentFunction>();
    f->name = c.name;
    f->pigment = pigmentTexture(item->pigment);
    f->component = component(*c.callee, f->pigment, c.member);
    if (textureUsesUv(f->pigment))
      throw FunctionError(c.callee->loc, c.callee->describe() +
                                             " is uv-mapped, which Lucent cannot evaluate at a "
                                             "point in a function (a point has no (u, v))");
    if (textureHoldsImage(f->pigment))
      throw FunctionError(c.callee->loc, c.callee->describe() +
                                             " is an image pigment, which Lucent cannot "
                                             "evaluate at a point in a function");
    pigmentFunctions_.push_back(f);
    out.push_back(std::move(f));
  }
  return out;
}

// `F(x, y, z).red` (or a pattern function's `F(x, y, z)`, or a transform function's
// `F(x, y, z).x`) evaluated while the scene is read
// (a #declare, a macro's arithmetic): the pigment's colour at the point now, with the noise
// generator global_settings chose so far.
std::optional<double> SceneReader::pigmentValue(const FunctionValue& f, int member,
                                                const double* xyz) {
  // A transform function's value: the point moved, in POV-Ray's space; .x, .y, .z.
  if (const auto* t = dynamic_cast<const TransformItem*>(f.pigment.get())) {
    if (member < 0 || member > 2) return std::nullopt;
    return t->transform.point(Vec3(xyz[0], xyz[1], xyz[2]))[member];
  }
  const auto* item = dynamic_cast<const PigmentItem*>(f.pigment.get());
  if (!item || member < 0 || member > 5) return std::nullopt;
  std::shared_ptr<PigmentFunction>& p = evaluatedPigments_[&f];
  if (!p) {
    p = std::make_shared<PigmentFunction>();
    p->pigment = pigmentTexture(item->pigment);
    if (textureHoldsImage(p->pigment)) return std::nullopt;
    forEachTexturePattern(p->pigment, [&](PatternSpec& s) {
      if (s.noiseGenerator == 0) s.noiseGenerator = global_.noiseGenerator;
    });
  }
  p->component = component(f, p->pigment, member);
  return pigmentFunctionValue(*p, xyz[0], xyz[1], xyz[2]);
}

}  // namespace lucent::sdl
