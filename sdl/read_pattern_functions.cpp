// `#declare F = function { pattern { PATTERN modifiers } }` and f_noise3d: a pattern's value
// as a function of x, y and z. Each is made a pigment of the pattern with the map that turns
// its value v into the colour (v, v, v), so that its red is the value, and is evaluated as
// pigment functions are (read_pigment_functions.cpp). POV-Ray ignores a pattern function's
// colour map, as this does by replacing it. A block pattern's value is its cell's index
// (POV-Ray's Evaluate_TPat, whose frequency is 0 for them unless one is given, which shapes
// the index with the phase and wave): checker 0 or 1 (1 where the floors of x, y and z add
// to an odd number), brick 0 in the mortar and 1 in a brick, hexagon 0, 1 or 2; each is
// given here as the grey of its colours.
#include "scene_reader.h"

namespace lucent::sdl {

namespace {

// The map from value to grey (0 to black, 1 to white, linear between).
ColorMap valueMap() {
  ColorMap map;
  map.entries = {{0.0, Color(0.0f)}, {1.0, Color(1.0f)}};
  return map;
}

// A block pattern's colours made the greys of their indices as `value` shapes them (its
// pigments dropped, as a colour map is); false for other textures.
bool setIndexGreys(Texture& texture, const PatternSpec& value) {
  auto grey = [&](int i) { return Color(static_cast<float>(blockCellValue(value, i))); };
  if (auto* c = std::get_if<CheckerTexture>(&texture)) {
    c->color1 = grey(0);
    c->color2 = grey(1);
    c->ft1 = c->ft2 = {};
    c->pigments.clear();
  } else if (auto* h = std::get_if<HexagonTexture>(&texture)) {
    for (int i = 0; i < 3; ++i) {
      h->spec.colors[i] = grey(i);
      h->spec.ft[i] = {};
    }
    h->pigments.clear();
  } else if (auto* b = std::get_if<BrickTexture>(&texture)) {
    b->spec.color1 = grey(0);
    b->spec.color2 = grey(1);
    b->spec.ft1 = b->spec.ft2 = {};
    b->pigments.clear();
  } else {
    return false;
  }
  return true;
}

}  // namespace

ItemPtr SceneReader::patternPigment(TokenStream& in, bool noise) {
  auto item = std::make_shared<PigmentItem>();
  if (noise) {
    PatternTexture bozo;
    bozo.pattern.type = PatternType::bozo;
    bozo.map = valueMap();
    item->pigment.pattern = bozo;
    return item;
  }
  // What the block holds that Lucent cannot render is kept with the item, said where the
  // function is called (as a declared pigment's).
  declaring_.emplace_back();
  PovPigment p = readPigment(in, PovPigment{});
  item->refused = std::move(declaring_.back());
  declaring_.pop_back();
  p.filter = p.transmit = 0.0f;
  p.color = Color(0.0f);
  if (!setIndexGreys(p.pattern, p.blockValueSpec())) {
    auto* t = std::get_if<PatternTexture>(&p.pattern);
    // Images and averages: refused where called.
    if (!t) return nullptr;
    t->pigments.clear();  // a pigment_map is ignored, as a colour map is
    t->map = valueMap();
  }
  item->pigment = p;
  return item;
}

}  // namespace lucent::sdl
