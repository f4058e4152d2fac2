#include "sky_color.h"

#include "texture.h"

#include "patterns/color_map.h"
#include "patterns/pattern_value.h"

#include <cmath>

namespace lucent {

Color skyColor(const Sky& sky, const Vec3& direction, const Color& background) {
  const Vec3 p = Vec3(sky.skyFromWorld * Vec4(glm::normalize(direction), 1.0));
  // One opaque pattern (every sky written before layers existed): its colour, as it was.
  if (sky.layers.size() == 1) {
    if (const auto* pattern = std::get_if<PatternTexture>(&sky.layers[0]);
        pattern && pattern->pigments.empty() && !pattern->map.seeThrough())
      return lookupColorMap(pattern->map, patternValue(pattern->pattern, p));
  }
  if (sky.layering == SkyLayering::pov36) {
    Color sum(0.0f), colours(1.0f);
    float filters = 1.0f, transmits = 1.0f, shown = 1.0f;
    for (auto layer = sky.layers.rbegin(); layer != sky.layers.rend(); ++layer) {
      const PigmentColor c = pigmentAt(*layer, p, Vec3(0.0));
      sum += c.rgb * (shown * (1.0f - c.ft.filter - c.ft.transmit));
      colours *= c.rgb;
      filters *= c.ft.filter;
      transmits *= c.ft.transmit;
      shown = std::abs(filters) + std::abs(transmits);
    }
    return background * (colours * filters + Color(transmits)) + sum;
  }
  Color sum(0.0f);
  Color through(1.0f);  // what the layers above let through
  for (auto layer = sky.layers.rbegin(); layer != sky.layers.rend(); ++layer) {
    const PigmentColor c = pigmentAt(*layer, p, Vec3(0.0));
    const float opacity = 1.0f - c.ft.filter - c.ft.transmit;
    sum += c.rgb * opacity * through;
    through *= c.rgb * c.ft.filter + Color(c.ft.transmit);
  }
  return sum + background * through;
}

}  // namespace lucent
