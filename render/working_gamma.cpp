#include "working_gamma.h"

#include "images/srgb_decoding.h"

#include <fmt/core.h>

#include <cmath>

namespace lucent {

namespace {

// The curve on |x|, the sign kept.
template <class Curve>
double withSign(double x, Curve curve) {
  return x < 0.0 ? -curve(-x) : curve(x);
}

template <class Convert>
void eachValue(Image& image, Convert convert) {
  for (Color& c : image.pixels)
    for (int k = 0; k < 3; ++k) c[k] = static_cast<float>(convert(static_cast<double>(c[k])));
}

}  // namespace

double workingToLinear(const WorkingGamma& gamma, double x) {
  if (gamma.linear()) return x;
  if (gamma.srgb) return withSign(x, [](double v) { return srgbToLinear(v); });
  return withSign(x, [&](double v) { return std::pow(v, gamma.power); });
}

std::string curveText(const GammaCurve& curve) {
  return curve.srgb ? "srgb" : fmt::format("gamma {}", curve.power);
}

double linearToWorking(const WorkingGamma& gamma, double linear) {
  if (gamma.linear()) return linear;
  if (gamma.srgb)
    return withSign(linear, [](double v) {
      return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
    });
  return withSign(linear, [&](double v) { return std::pow(v, 1.0 / gamma.power); });
}

void workingToLinear(const WorkingGamma& gamma, Image& image) {
  if (!gamma.linear()) eachValue(image, [&](double x) { return workingToLinear(gamma, x); });
}

const Image& lightOf(const Image& image, const WorkingGamma& gamma, Image& storage) {
  if (gamma.linear()) return image;
  storage = image;
  workingToLinear(gamma, storage);
  return storage;
}

void linearToWorking(const WorkingGamma& gamma, Image& image) {
  if (!gamma.linear()) eachValue(image, [&](double x) { return linearToWorking(gamma, x); });
}

}  // namespace lucent
