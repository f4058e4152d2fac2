// POV-Ray 3.7's ripples and waves: sums of circular waves from N fixed sources, N its
// global_settings number_of_waves, 10 by default (texture.cpp: Initialize_Waves;
// pattern.cpp and normal.cpp: ripples, waves).
#pragma once

#include "scenegraph/pattern.h"

namespace lucent {

// The sources (unit vectors from the vector noise at (i, 0, 0)) and, for waves, their
// relative frequencies (from POV-Ray's random generator, in [0.01, 1.01)). POV-Ray draws
// them in order from one seed, so N sources are the first N of kMaxWaveSources.
struct WaveSources {
  Vec3 source[kMaxWaveSources];
  double frequency[kMaxWaveSources];
};

// Built once, on first use.
const WaveSources& waveSources();

// The raw pattern values, before shapeValue (which applies frequency and phase again, as
// POV-Ray does): ripples averages sin 2π(|p − s|·f + φ) over the first `count` sources,
// mapped to [0, 1]; waves weights each source by its own frequency.
double ripplesValue(const Vec3& p, double frequency, double phase, int count);
double wavesValue(const Vec3& p, double frequency, double phase, int count);

// The normal perturbations (normal.cpp): each source in turn pushes `normal` along p − s
// by its wave's value times `amount` over `count` (the sum is not normalised).
Vec3 ripplesNormal(const Vec3& normal, const Vec3& p, double frequency, double phase, double amount,
                   int count);
Vec3 wavesNormal(const Vec3& normal, const Vec3& p, double frequency, double phase, double amount,
                 int count);

}  // namespace lucent
