// `#declare F = function { pattern { PATTERN modifiers } }` and f_noise3d: a pattern's value
// as a function of x, y and z. Each is made a pigment of the pattern with the map that turns
// its value v into the colour (v, v, v), so that its red is the value, and is evaluated as
// pigment functions are (read_pigment_functions.cpp). POV-Ray ignores a pattern function's
// colour map, as this does by replacing it.
#include "scene_reader.h"

namespace lucent::sdl {

namespace {

// The map from value to grey (0 to black, 1 to white, linear between).
ColorMap valueMap() {
  ColorMap map;
  map.entries = {{0.0, Color(0.0f)}, {1.0, Color(1.0f)}};
  return map;
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
  auto* t = std::get_if<PatternTexture>(&p.pattern);
  // checker, hexagon, brick, images and averages: refused where called.
  if (!t) return nullptr;
  t->pigments.clear();  // a pigment_map is ignored, as a colour map is
  t->map = valueMap();
  p.filter = p.transmit = 0.0f;
  p.color = Color(0.0f);
  item->pigment = p;
  return item;
}

}  // namespace lucent::sdl
