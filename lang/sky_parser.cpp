// <sky transform>: colour textures evaluated on ray directions, layered (scenegraph/sky.h).
#include "element_parsers.h"
#include "texture_parser.h"

#include <algorithm>

namespace lucent {

void parseSky(ElementReader& r) {
  r.checkAttributes({"transform", "layering"});
  Scene& scene = r.ctx().scene;
  if (scene.sky) {
    r.error("a scene has one <sky> at most; the first is at " + scene.sky->loc.str());
    return;
  }
  Sky sky;
  sky.loc = r.loc();
  sky.skyFromWorld = glm::inverse(r.transform("transform"));
  sky.layering = r.choice("layering", SkyLayering::pov37,
                          {{"pov-3.7", SkyLayering::pov37}, {"pov-3.6", SkyLayering::pov36}});
  bool wrongChild = false;
  const std::vector<std::string_view> kinds = textureElements();
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader c(r.ctx(), r.file(), n);
    const std::string_view name = n.name();
    // Every colour texture but <image>, which needs a surface's (u,v).
    if (name == "image" || std::find(kinds.begin(), kinds.end(), name) == kinds.end()) {
      wrongChild = true;
      c.error(
          "<sky> holds <pattern>, <checker>, <hexagon> or <brick> layers (the last on top), "
          "not <" +
          std::string(name) + ">");
      return;
    }
    sky.layers.push_back(parseTexture(c));
    refuseUvMapping(c, sky.layers.back(), "a sky, seen at a direction,");
    if (textureHoldsImage(sky.layers.back()))
      c.error(
          "a <sky> layer cannot hold an <image> in its maps or lists (a sky's colours are "
          "taken without a material's images)");
  });
  if (sky.layers.empty() && !wrongChild && !r.failed()) {
    r.error("<sky> needs a <pattern> child, e.g. <pattern type=\"gradient\"> with a <color-map>");
    return;
  }
  scene.sky = std::move(sky);
}

}  // namespace lucent
