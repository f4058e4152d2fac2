#include "camera_samples.h"

#include "sampling.h"

#include <algorithm>

namespace lucent {

CameraSamples::CameraSamples(const Projection& projection, const Tracer& tracer, Color background,
                             int samples, const Camera::FocalBlur* focalBlur)
    : projection_(projection),
      tracer_(tracer),
      cameraMedia_(tracer.mediaAt(projection.frame().origin)),
      background_(background),
      samples_(std::max(1, samples)) {
  if (focalBlur) focalBlur_.emplace(*focalBlur);
}

Color CameraSamples::trace(const Vec2& film, const Vec2& lens, uint32_t x, uint32_t y,
                           uint32_t sample, TraceContext& context) const {
  const int rays = projection_.raysPerSample();
  if (rays == 1 && projection_.fixedOrigin()) {
    Ray ray;
    if (!projection_.generateRay(film, lens, ray)) return background_;
    PathSeed seed{x, y, sample, 0};
    return tracer_.traceCamera(ray, cameraMedia_, seed, context);
  }
  // A mesh camera's sample: the mean of its rays that exist (POV-Ray's), each in the solids
  // about its own start; the background when none does.
  Color sum(0.0f);
  int traced = 0;
  for (int k = 0; k < rays; ++k) {
    Ray ray;
    if (!projection_.generateRayNumber(film, lens, k, ray)) continue;
    PathSeed seed{x, y, sample ^ (static_cast<uint32_t>(k) * 0x9e3779b9u), 0};
    sum += tracer_.traceCamera(ray, tracer_.mediaAt(ray.o), seed, context);
    ++traced;
  }
  return traced > 0 ? sum / static_cast<float>(traced) : background_;
}

Color CameraSamples::sampleAt(const Vec2& film, const Vec2& lens, uint32_t x, uint32_t y,
                              uint32_t sample, TraceContext& context) const {
  if (!focalBlur_) return trace(film, lens, x, y, sample, context);
  // The lens rays of one sample share its seed; each ray's own paths are told apart by
  // its index.
  const uint64_t seed = mixBits((uint64_t(x) << 32 | y) ^ mixBits(sample));
  return focalBlur_->average(film, seed, [&](const Vec2& f, const Vec2& l, int index) {
    return trace(f, l, x, y, sample ^ (static_cast<uint32_t>(index + 1) * 0x9e3779b9u), context);
  });
}

Color CameraSamples::sample(int x, int y, int k, int count, TraceContext& context) const {
  Vec2 film = Vec2(x, y) + pixelSampleOffset(k, count);
  return sampleAt(film, lensSample(x, y, k, count), static_cast<uint32_t>(x),
                  static_cast<uint32_t>(y), static_cast<uint32_t>(k), context);
}

Color CameraSamples::pixel(int x, int y, TraceContext& context) const {
  Color sum(0.0f);
  for (int k = 0; k < samples_; ++k) sum += sample(x, y, k, samples_, context);
  return sum / static_cast<float>(samples_);
}

Color CameraSamples::latticeSample(int fx, int fy, int step, TraceContext& context) const {
  const Vec2 film = Vec2(fx, fy) / static_cast<double>(step);
  // The lens centre, as one sample per pixel takes: a lattice point is one sample. Seeded
  // by the lattice point alone, so a sample traced by two tiles is the same sample.
  return sampleAt(film, Vec2(0.5, 0.5), static_cast<uint32_t>(fx), static_cast<uint32_t>(fy),
                  0x80000000u | static_cast<uint32_t>(step), context);
}

}  // namespace lucent
