#include "pixel_sampler.h"

#include "adaptive_centre_sampler.h"
#include "corner_sampler.h"
#include "fixed_sampler.h"

#include <algorithm>

namespace lucent {

namespace {

// Adaptive supersampling of centres needs a threshold and more than one sample to take.
bool adaptiveCentres(const RenderSettings& settings) {
  return settings.adaptiveMode != AdaptiveMode::Corners && settings.adaptive > 0.0 &&
         settings.samples > 1;
}

}  // namespace

std::unique_ptr<PixelSampler> makePixelSampler(const RenderSettings& settings,
                                               const CameraSamples& camera) {
  const float threshold = static_cast<float>(settings.adaptive);
  if (settings.adaptiveMode == AdaptiveMode::Corners)
    return std::make_unique<CornerSampler>(
        camera, threshold, std::clamp(settings.adaptiveDepth, 1, kMaxAdaptiveDepth));
  if (adaptiveCentres(settings))
    return std::make_unique<AdaptiveCentreSampler>(camera, settings.width, settings.height,
                                                   threshold);
  return std::make_unique<FixedSampler>(camera);
}

int samplingMargin(const RenderSettings& settings) {
  return adaptiveCentres(settings) ? AdaptiveCentreSampler::margin(settings.samples) : 0;
}

}  // namespace lucent
