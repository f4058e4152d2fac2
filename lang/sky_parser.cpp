// <sky transform>: one <pattern> child, evaluated on ray directions (scenegraph/sky.h).
#include "element_parsers.h"
#include "pattern_parser.h"

namespace lucent {

void parseSky(ElementReader& r) {
  r.checkAttributes({"transform"});
  Scene& scene = r.ctx().scene;
  if (scene.sky) {
    r.error("a scene has one <sky> at most; the first is at " + scene.sky->loc.str());
    return;
  }
  Sky sky;
  sky.loc = r.loc();
  sky.skyFromWorld = glm::inverse(r.transform("transform"));
  bool found = false, wrongChild = false;
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader c(r.ctx(), r.file(), n);
    if (std::string_view(n.name()) != "pattern") {
      wrongChild = true;
      c.error("<sky> holds one <pattern> (with its <color-map>), not <" + std::string(n.name()) +
              ">");
      return;
    }
    if (found) {
      c.error("<sky> holds one <pattern>");
      return;
    }
    found = true;
    sky.pattern = std::get<PatternTexture>(parsePatternTexture(c));
  });
  if (!found && !wrongChild && !r.failed()) {
    r.error("<sky> needs a <pattern> child, e.g. <pattern type=\"gradient\"> with a <color-map>");
    return;
  }
  scene.sky = std::move(sky);
}

}  // namespace lucent
