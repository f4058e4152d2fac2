// POV-Ray 3.7's focal blur (camera { aperture blur_samples focal_point confidence variance },
// tracepixel.cpp: TraceRayWithFocalBlur, JitterCameraRay), for every camera type but
// thin-lens; XML <camera><focal-blur/></camera> (docs/cameras.md, "Focal blur").
//
// Two parts: the projection that moves a ray's start on the lens disc and aims it at the
// point its unmoved ray meets the focus surface, and the sampler that averages a camera
// sample's rays until POV-Ray's confidence test says the mean is good enough.
#pragma once

#include "projection.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace lucent {

// `projection`'s rays through the lens of camera.focalBlur (which must be set): the lens
// point in [0,1)^2 maps onto the disc (concentric map); (0.5, 0.5) is its centre, the
// unmoved ray. Throws LocatedError for a focal point the camera cannot focus on.
std::unique_ptr<Projection> throughFocalBlurLens(std::unique_ptr<Projection> projection,
                                                 const Camera& camera);

// The average of one camera sample's rays under focal blur.
class FocalBlurSampler {
 public:
  explicit FocalBlurSampler(const Camera::FocalBlur& blur);

  // One ray's colour: the ray through film position `film` and lens point `lens`, traced;
  // `index` numbers the rays of the sample.
  using TraceRay = std::function<Color(const Vec2& film, const Vec2& lens, int index)>;

  // The mean of rays j = 0, 1, ... about film position `centre`: ray j at centre + its
  // offset in [-1/2, 1/2)^2 (a pixel around the centre, as POV-Ray jitters) through lens
  // point j of a scrambled (0,2)-sequence; `seed` picks the scramble (the same seed, the same
  // rays). Rays are taken in fours; after each four, once minSamples are taken, it stops
  // when every channel's variance of the mean is below the threshold for that count, and
  // in any case at `samples`.
  Color average(const Vec2& centre, uint64_t seed, const TraceRay& trace) const;

  int samples() const { return samples_; }
  // The variance of the mean below which n rays are enough (n from 1 to samples()):
  // POV-Ray's variance × chdtri(n, c) / chdtri(samples − 1, c), with chdtri(k, c) the value
  // a chi-square variable of k degrees of freedom exceeds with probability c; 0 for one ray.
  double threshold(int n) const { return threshold_[n - 1]; }

 private:
  int samples_, minSamples_;
  std::vector<double> threshold_;
};

}  // namespace lucent
