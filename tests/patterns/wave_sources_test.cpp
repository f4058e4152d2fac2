// ripples and waves with N sources (POV-Ray's global_settings number_of_waves) against
// POV-Ray 3.7's formulas written out here: the sources from the vector noise at (i, 0, 0),
// the frequencies from its random generator seeded -560851967 (texture.cpp,
// Initialize_Waves), the pattern values (pattern.cpp) and the normals (normal.cpp).
#include "render/patterns/wave_sources.h"
#include "primitives/noise.h"
#include "render/patterns/pattern_value.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

using namespace lucent;

namespace {

struct Source {
  Vec3 at;
  double frequency;
};

// POV-Ray's loop: next_rand = next_rand * 1812433253 + 12345 in 64 bits, kept as a 32-bit
// int; the frequency is ((next_rand >> 16) & 0x7FFF) * 0.000030518509476 + 0.01.
std::vector<Source> povSources(int n) {
  std::vector<Source> s;
  int32_t next = -560851967;
  for (int i = 0; i < n; ++i) {
    const Vec3 d = dnoise(Vec3(i, 0, 0));
    const double l = glm::length(d);
    next = static_cast<int32_t>(static_cast<int64_t>(next) * 1812433253LL + 12345LL);
    s.push_back({l != 0.0 ? d / l : d, ((next >> 16) & 0x7FFF) * 0.000030518509476 + 0.01});
  }
  return s;
}

// sin 2πv (POV-Ray's cycloidal).
double wave(double v) { return std::sin(2.0 * kPi * (v - std::floor(v))); }

double povRipples(const Vec3& p, double f, double phase, int n) {
  double sum = 0.0;
  for (const Source& s : povSources(n)) sum += wave(glm::length(p - s.at) * f + phase);
  return 0.5 * (1.0 + sum / n);
}

double povWaves(const Vec3& p, double f, double phase, int n) {
  double sum = 0.0;
  for (const Source& s : povSources(n))
    sum += wave(glm::length(p - s.at) * f * s.frequency + phase) / s.frequency;
  return 0.2 * (2.5 + sum / n);
}

Vec3 povWavesNormal(Vec3 normal, const Vec3& p, double f, double phase, double amount, int n,
                    bool ownFrequencies) {
  for (const Source& s : povSources(n)) {
    const Vec3 d = p - s.at;
    const double l = glm::length(d);
    const double fi = ownFrequencies ? s.frequency : 1.0;
    normal += wave(l * f * fi + phase) * amount / fi / (l * n) * d;
  }
  return normal;
}

// Frequency 1 and phase 0 applied again, as POV-Ray's Evaluate_TPat does: the value wrapped
// by fmod(v, 1.00001), a negative result into [0, 1).
double povWrapped(double v) {
  v = std::fmod(v, 1.00001);
  return v < 0.0 ? v - std::floor(v) : v;
}

const Vec3 kPoints[] = {Vec3(0.25, 0.5, -0.75), Vec3(1.5, -2, 0.125), Vec3(-3.25, 0.0625, 7),
                        Vec3(0, 0, 0)};

}  // namespace

TEST_CASE("ripples and waves sum as many sources as number_of_waves says", "[pattern][waves]") {
  for (int n : {1, 2, 3, 10, 25, kMaxWaveSources}) {
    for (const Vec3& p : kPoints) {
      INFO("sources " << n << " at " << p.x << " " << p.y << " " << p.z);
      // Frequency 2.5 and phase 0.25 are exact in single precision, as POV-Ray keeps them.
      CHECK(ripplesValue(p, 2.5, 0.25, n) == Approx(povRipples(p, 2.5, 0.25, n)).margin(1e-12));
      CHECK(wavesValue(p, 2.5, 0.25, n) == Approx(povWaves(p, 2.5, 0.25, n)).margin(1e-12));
      const Vec3 normal(0, 0, -1);
      const Vec3 r = ripplesNormal(normal, p, 2.5, 0.25, 0.375, n);
      const Vec3 w = wavesNormal(normal, p, 2.5, 0.25, 0.375, n);
      const Vec3 pr = povWavesNormal(normal, p, 2.5, 0.25, 0.375, n, false);
      const Vec3 pw = povWavesNormal(normal, p, 2.5, 0.25, 0.375, n, true);
      for (int k = 0; k < 3; ++k) {
        CHECK(r[k] == Approx(pr[k]).margin(1e-12));
        CHECK(w[k] == Approx(pw[k]).margin(1e-12));
      }
    }
  }
}

TEST_CASE("a pattern's sources reach its value", "[pattern][waves]") {
  PatternSpec one;
  one.type = PatternType::waves;
  one.waveSources = 1;
  PatternSpec ten = one;
  ten.waveSources = 10;
  const Vec3 p(0.25, 0.5, -0.75);
  const double v1 = povWrapped(povWaves(p, 1, 0, 1)), v10 = povWrapped(povWaves(p, 1, 0, 10));
  CHECK(patternValueAt(one, p) == Approx(v1).margin(1e-12));
  CHECK(patternValueAt(ten, p) == Approx(v10).margin(1e-12));
  CHECK(std::fabs(v1 - v10) > 0.01);
}
