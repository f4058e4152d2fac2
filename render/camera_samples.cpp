#include "camera_samples.h"

#include "sampling.h"

#include <algorithm>

namespace lucent {

CameraSamples::CameraSamples(const Projection& projection, const Tracer& tracer, Color background,
                             int samples)
    : projection_(projection),
      tracer_(tracer),
      cameraMedia_(tracer.mediaAt(projection.frame().origin)),
      background_(background),
      samples_(std::max(1, samples)) {}

Color CameraSamples::sample(int x, int y, int k, int count, TraceContext& context) const {
  Vec2 film = Vec2(x, y) + pixelSampleOffset(k, count);
  Ray ray;
  if (!projection_.generateRay(film, lensSample(x, y, k, count), ray)) return background_;
  PathSeed seed{static_cast<uint32_t>(x), static_cast<uint32_t>(y), static_cast<uint32_t>(k), 0};
  return tracer_.traceCamera(ray, cameraMedia_, seed, context);
}

Color CameraSamples::pixel(int x, int y, TraceContext& context) const {
  Color sum(0.0f);
  for (int k = 0; k < samples_; ++k) sum += sample(x, y, k, samples_, context);
  return sum / static_cast<float>(samples_);
}

Color CameraSamples::latticeSample(int fx, int fy, int step, TraceContext& context) const {
  const Vec2 film = Vec2(fx, fy) / static_cast<double>(step);
  Ray ray;
  // The lens centre, as one sample per pixel takes: a lattice point is one sample.
  if (!projection_.generateRay(film, Vec2(0.5, 0.5), ray)) return background_;
  // Seeded by the lattice point alone, so a sample traced by two tiles is the same sample.
  PathSeed seed{static_cast<uint32_t>(fx), static_cast<uint32_t>(fy),
                0x80000000u | static_cast<uint32_t>(step), 0};
  return tracer_.traceCamera(ray, cameraMedia_, seed, context);
}

}  // namespace lucent
