// The curve POV-Ray 3.7 decodes an image_map's file with (its Parse_Image and the readers
// of each format), so that an imported <image gamma> gives POV-Ray's working values: by the
// image's `gamma` keyword, else by the file's format, what a PNG says of itself, the
// #version in force and whether assumed_gamma was given.
#pragma once

#include "pov_settings.h"

#include "scenegraph/gamma_curve.h"

#include <optional>
#include <string>

namespace lucent::sdl {

// `format`: POV-Ray's type keyword of the file (png, jpeg, tga, gif, ppm, pgm, tiff, bmp,
// exr, hdr) or, without one, the file's extension. `keyword`: the image's gamma, if written.
// `global`: the global settings read so far; `languageVersion`: the #version in force.
GammaCurve povImageMapGamma(const std::string& path, const std::string& format,
                            const std::optional<GammaCurve>& keyword,
                            const PovGlobalSettings& global, double languageVersion);

}  // namespace lucent::sdl
