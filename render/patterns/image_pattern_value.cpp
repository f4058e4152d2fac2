#include "image_pattern_value.h"

#include "render/image_projection.h"

#include <algorithm>

namespace lucent {

double imagePatternValue(const ImagePattern& image, const Vec3& patternPoint) {
  if (!image.values) return 0.0;
  const ImageValueGrid& grid = *image.values;
  const auto xy =
      projectToImage(image.projection, patternPoint, grid.width, grid.height, image.once);
  if (!xy) return 0.0;
  const double v = sampleImageValue(grid, *xy, image.interpolation, image.once);
  return std::clamp(v, 0.0, 1.0);
}

}  // namespace lucent
