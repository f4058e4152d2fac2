// POV-Ray 3.7's image_pattern: a pattern whose value at a point is read from an image
// projected as image_map projects it (docs/scene-language.md, "image-pattern"). The scene
// keeps the file's path and its values, read when the scene is read
// (images/image_values_file.h, which its users include), so that a pattern anywhere (a normal, a
// map's entry, a pigment-pattern's pigment) evaluates it without a renderer's help.
#pragma once

#include "texture_spec.h"

#include <memory>
#include <string>

namespace lucent {

struct ImageValueGrid;  // images/image_values_file.h: the reader's, below the scene graph

struct ImagePattern {
  std::string path;  // resolved, absolute or relative to the working directory
  ImageProjection projection = ImageProjection::planar;         // POV-Ray's map_type, default 0
  bool once = false;                                            // one copy: off it the value is 0
  ImageInterpolation interpolation = ImageInterpolation::none;  // POV-Ray's default
  bool useAlpha = false;  // POV-Ray's use_alpha: the transmit (or red) instead of the grey
  // A <material-map>'s image read by index (POV-Ray's material_map): the palette index, or
  // the red channel times 255, picks an entry (scenegraph/map_blend.h); `values` then hold
  // the red channel (images/image_values_file.h, readImageIndexValues).
  bool byIndex = false;
  std::shared_ptr<const ImageValueGrid> values;
};

}  // namespace lucent
