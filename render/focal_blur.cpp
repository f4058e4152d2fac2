#include "focal_blur.h"

#include "sampling.h"
#include "thin_lens.h"

#include <fmt/core.h>
#include <boost/math/distributions/chi_squared.hpp>

#include <algorithm>
#include <cmath>

namespace lucent {

namespace {

// Whether the camera focuses on a plane parallel to its image (the types whose rays all
// go forward through one image plane); the others focus on a sphere about each ray's start.
bool focusesOnPlane(CameraType type) {
  return type == CameraType::Pinhole || type == CameraType::Orthographic;
}

class FocalBlurProjection final : public Projection {
 public:
  FocalBlurProjection(std::unique_ptr<Projection> inner, const Camera& camera)
      : Projection(inner->frame(), camera, 1, 1), inner_(std::move(inner)) {
    const Camera::FocalBlur& blur = *camera.focalBlur;
    lensRadius_ = 0.5 * blur.aperture;
    const Vec3 focal = Vec3(camera.transform * Vec4(blur.focalPoint.value_or(camera.lookAt), 1.0));
    const Vec3 toFocal = focal - frame_.origin;
    plane_ = focusesOnPlane(camera.type);
    if (plane_) {
      // The image's normal: forward, or across a POV-Ray frame's right and up.
      normal_ = frame_.forward;
      if (camera.imagePlane) {
        const Vec3 n = glm::cross(frame_.toWorld(camera.imagePlane->right),
                                  frame_.toWorld(camera.imagePlane->up));
        normal_ = glm::normalize(n);
        if (glm::dot(normal_, frame_.forward) < 0.0) normal_ = -normal_;
      }
      focus_ = glm::dot(toFocal, normal_);
      if (!(focus_ > 0.0))
        throw LocatedError(blur.loc, "the focal point must lie in front of the camera (it is " +
                                         fmt::format("{:g}", -focus_) +
                                         " behind the camera's image plane)");
    } else {
      focus_ = glm::length(toFocal);
      if (!(focus_ > 0.0))
        throw LocatedError(blur.loc, "the focal point must not be the camera's position");
    }
  }

  bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const override {
    if (!inner_->generateRay(film, Vec2(0.5), ray)) return false;
    // Where the unmoved ray meets the focus surface; every ray of the lens meets it there.
    double t = focus_;
    if (plane_) {
      const double along = glm::dot(ray.d, normal_);
      if (!(along > 0.0)) return true;  // parallel to the plane: no focus, left unmoved
      t = (focus_ - glm::dot(ray.o - frame_.origin, normal_)) / along;
    }
    const Vec2 disc = lensRadius_ * concentricDisc(lens);
    const Vec3 offset = disc.x * frame_.right + disc.y * frame_.up;
    const Vec3 start = ray.o + offset;
    ray = Ray(start, glm::normalize(t * ray.d - offset), ray.tmin, ray.tmax);
    return true;
  }

 private:
  std::unique_ptr<Projection> inner_;
  double lensRadius_ = 0.0, focus_ = 1.0;
  bool plane_ = true;
  Vec3 normal_{0.0};
};

// chdtri(k, c): the value a chi-square variable of k degrees of freedom exceeds with
// probability c.
double chiSquareExceeded(double k, double c) {
  return boost::math::quantile(boost::math::complement(boost::math::chi_squared(k), c));
}

}  // namespace

std::unique_ptr<Projection> throughFocalBlurLens(std::unique_ptr<Projection> projection,
                                                 const Camera& camera) {
  return std::make_unique<FocalBlurProjection>(std::move(projection), camera);
}

FocalBlurSampler::FocalBlurSampler(const Camera::FocalBlur& blur)
    : samples_(std::max(1, blur.samples)),
      minSamples_(std::clamp(blur.minSamples, 0, samples_)),
      threshold_(samples_, 0.0) {
  if (samples_ > 1) {
    const double scale = blur.variance / chiSquareExceeded(samples_ - 1, blur.confidence);
    for (int n = 1; n <= samples_; ++n)
      threshold_[n - 1] = scale * chiSquareExceeded(n, blur.confidence);
  }
}

Color FocalBlurSampler::average(const Vec2& centre, uint64_t seed, const TraceRay& trace) const {
  const uint64_t lensSeed = mixBits(seed ^ 0x6c656e73ULL /* "lens" */);
  // A Cranley-Patterson rotation of the Halton (3, 5) points: sub-pixel offsets that are
  // well spread for every count and independent of the lens points (bases 2 and 2).
  const Vec2 shift(hashToUnit(seed, 1, 0, 0), hashToUnit(seed, 2, 0, 0));
  Vec3 sum(0.0), sumSquares(0.0);
  int n = 0;
  while (n < samples_) {
    for (int i = 0; i < 4 && n < samples_; ++i, ++n) {
      const uint64_t index = static_cast<uint64_t>(n) + 1;
      Vec2 offset = Vec2(radicalInverse(3, index), radicalInverse(5, index)) + shift;
      offset = offset - glm::floor(offset) - Vec2(0.5);
      const Vec2 lens = sobol02(static_cast<uint32_t>(n), static_cast<uint32_t>(lensSeed),
                                static_cast<uint32_t>(lensSeed >> 32));
      const Vec3 c = Vec3(trace(centre + offset, lens, n));
      sum += c;
      sumSquares += c * c;
    }
    if (n < minSamples_ || n >= samples_) continue;
    const Vec3 mean = sum / double(n);
    const Vec3 varianceOfMean = (sumSquares / double(n) - mean * mean) / double(n);
    const double limit = threshold(n);
    if (std::abs(varianceOfMean.x) < limit && std::abs(varianceOfMean.y) < limit &&
        std::abs(varianceOfMean.z) < limit)
      break;
  }
  return Color(sum / double(n));
}

}  // namespace lucent
