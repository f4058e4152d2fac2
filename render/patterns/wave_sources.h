// POV-Ray 3.7's ripples and waves: sums of circular waves from ten fixed sources
// (texture.cpp: Initialize_Waves; pattern.cpp and normal.cpp: ripples, waves).
#pragma once

#include "scenegraph/pattern.h"

namespace lucent {

// POV-Ray's global_settings number_of_waves, which the exporter keeps at its default.
constexpr int kWaveCount = 10;

// The sources (unit vectors from the vector noise at (i, 0, 0)) and, for waves, their
// relative frequencies (from POV-Ray's random generator, in [0.01, 1.01)).
struct WaveSources {
  Vec3 source[kWaveCount];
  double frequency[kWaveCount];
};

// Built once, on first use.
const WaveSources& waveSources();

// The raw pattern values, before shapeValue (which applies frequency and phase again, as
// POV-Ray does): ripples averages sin 2π(|p − s|·f + φ) over the sources, mapped to
// [0, 1]; waves weights each source by its own frequency.
double ripplesValue(const Vec3& p, double frequency, double phase);
double wavesValue(const Vec3& p, double frequency, double phase);

// The normal perturbations (normal.cpp): each source in turn pushes `normal` along p − s
// by its wave's value times `amount` over ten (the sum is not normalised).
Vec3 ripplesNormal(const Vec3& normal, const Vec3& p, double frequency, double phase,
                   double amount);
Vec3 wavesNormal(const Vec3& normal, const Vec3& p, double frequency, double phase, double amount);

}  // namespace lucent
