#include "wave_sources.h"

#include "primitives/noise.h"
#include "scenegraph/wave_shape.h"

#include <cmath>
#include <cstdint>

namespace lucent {

namespace {

double length(const Vec3& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

struct Source {
  Vec3 toPoint;   // p − source
  double length;  // its length, 1 at the source itself (POV-Ray's guard)
};

Source fromSource(const Vec3& p, const Vec3& s) {
  Source r;
  r.toPoint = Vec3(p.x - s.x, p.y - s.y, p.z - s.z);
  r.length = length(r.toPoint);
  if (r.length == 0.0) r.length = 1.0;
  return r;
}

// POV-Ray keeps frequency and phase in single precision.
double single(double v) { return static_cast<float>(v); }

}  // namespace

const WaveSources& waveSources() {
  static const WaveSources sources = [] {
    WaveSources w;
    uint32_t state = static_cast<uint32_t>(-560851967);  // POV-Ray's seed for the waves
    for (int i = 0; i < kMaxWaveSources; ++i) {
      const Vec3 d = dnoise(Vec3(static_cast<double>(i), 0.0, 0.0));
      const double l = length(d);
      w.source[i] = l != 0.0 ? Vec3(d.x / l, d.y / l, d.z / l) : d;
      state = state * 1812433253u + 12345u;
      w.frequency[i] = static_cast<double>((state >> 16) & 0x7FFFu) * 0.000030518509476 + 0.01;
    }
    return w;
  }();
  return sources;
}

double ripplesValue(const Vec3& p, double frequency, double phase, int count) {
  const WaveSources& w = waveSources();
  const double f = single(frequency), ph = single(phase);
  double scalar = 0.0;
  for (int i = 0; i < count; ++i) {
    const Source s = fromSource(p, w.source[i]);
    scalar += cycloidal(s.length * f + ph);
  }
  return 0.5 * (1.0 + (scalar / static_cast<double>(count)));
}

double wavesValue(const Vec3& p, double frequency, double phase, int count) {
  const WaveSources& w = waveSources();
  const double f = single(frequency), ph = single(phase);
  double scalar = 0.0;
  for (int i = 0; i < count; ++i) {
    const Source s = fromSource(p, w.source[i]);
    scalar += cycloidal(s.length * f * w.frequency[i] + ph) / w.frequency[i];
  }
  return 0.2 * (2.5 + (scalar / static_cast<double>(count)));
}

namespace {

// Ripples and waves bend the normal alike; waves scale each source by its own frequency
// (multiplying and dividing by 1 for ripples leaves POV-Ray's values bit for bit).
Vec3 bendByWaveSources(const Vec3& normal, const Vec3& p, double frequency, double phase,
                       double amount, int count, bool perSourceFrequency) {
  const WaveSources& w = waveSources();
  const double f = single(frequency), ph = single(phase);
  Vec3 n = normal;
  for (int i = 0; i < count; ++i) {
    const Source s = fromSource(p, w.source[i]);
    const double fi = perSourceFrequency ? w.frequency[i] : 1.0;
    const double scalar = cycloidal(s.length * f * fi + ph) * amount / fi;
    const double k = scalar / (s.length * static_cast<double>(count));
    n.x += k * s.toPoint.x;
    n.y += k * s.toPoint.y;
    n.z += k * s.toPoint.z;
  }
  return n;
}

}  // namespace

Vec3 ripplesNormal(const Vec3& normal, const Vec3& p, double frequency, double phase, double amount,
                   int count) {
  return bendByWaveSources(normal, p, frequency, phase, amount, count, false);
}

Vec3 wavesNormal(const Vec3& normal, const Vec3& p, double frequency, double phase, double amount,
                 int count) {
  return bendByWaveSources(normal, p, frequency, phase, amount, count, true);
}

}  // namespace lucent
