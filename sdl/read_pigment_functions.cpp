// `#declare F = function { pigment { P } }` called as `F(x, y, z).red` in an isosurface's or
// a function pattern's function: the calls stay in the function's Lucent text as calls of
// names (function.h, PigmentCall), and each name is bound here to P as a Lucent texture
// placed in POV-Ray's space (the function's x, y and z are POV-Ray's), with its component.
#include "scene_reader.h"

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
    f->component = static_cast<PigmentComponent>(c.member);
    f->pigment = pigmentTexture(item->pigment);
    if (textureHoldsImage(f->pigment))
      throw FunctionError(c.callee->loc, c.callee->describe() +
                                             " is an image pigment, which Lucent cannot "
                                             "evaluate at a point in a function");
    pigmentFunctions_.push_back(f);
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace lucent::sdl
