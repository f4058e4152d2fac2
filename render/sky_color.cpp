#include "sky_color.h"

#include "patterns/color_map.h"
#include "patterns/pattern_value.h"

namespace lucent {

Color skyColor(const Sky& sky, const Vec3& direction) {
  const Vec3 p = Vec3(sky.skyFromWorld * Vec4(glm::normalize(direction), 1.0));
  return lookupColorMap(sky.pattern.map, patternValue(sky.pattern.pattern, p));
}

}  // namespace lucent
