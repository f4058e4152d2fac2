// POV-Ray's assumed_gamma where values cross between a scene's working space and linear
// light (scenegraph/render_settings.h, WorkingGamma): the output image, which holds linear
// light, and image textures, whose texels are read as linear light.
#pragma once

#include "image.h"

#include "scenegraph/render_settings.h"

#include <string>

namespace lucent {

// A working value as linear light: x^power, or sRGB's decoding. A negative value keeps
// its sign (an EXR keeps it; 8-bit formats clamp it to 0 anyway).
double workingToLinear(const WorkingGamma& gamma, double x);
// Linear light as a working value: the inverse of workingToLinear.
double linearToWorking(const WorkingGamma& gamma, double linear);

// The whole image, in place (nothing to do for a linear working space).
void workingToLinear(const WorkingGamma& gamma, Image& image);
void linearToWorking(const WorkingGamma& gamma, Image& image);

// The curve in words ("srgb", "gamma 2.2"): what tells images decoded by different curves
// apart where they are kept.
std::string curveText(const GammaCurve& curve);

// The image's light, as an output holds it: `image` itself for a linear working space (no
// copy), else `storage` filled with its values decoded.
const Image& lightOf(const Image& image, const WorkingGamma& gamma, Image& storage);

}  // namespace lucent
