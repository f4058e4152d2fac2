// A camera projection: turns a point of the image plane into a primary ray. One small
// class per projection type (pinhole.h, thin_lens.h, orthographic.h, fisheye.h, ...),
// all sharing the CameraFrame; makeProjection() is the one table from type to class.
#pragma once

#include "camera_frame.h"

#include "primitives/ray.h"

#include <memory>

namespace lucent {

class Projection {
 public:
  virtual ~Projection() = default;

  // film: image-plane position in pixels, x from the left edge in [0, width], y from the
  // top edge in [0, height]; pixel (i, j) covers [i, i+1] x [j, j+1] and its centre is
  // (i + 0.5, j + 0.5). lens: a point in [0,1)^2 for projections with an aperture
  // (others ignore it). Returns false where the projection has no ray (outside a fisheye's
  // image circle, between a cube map's faces): such samples get the background colour.
  // ray.d is unit length, so the camera's near/far are distances along the ray.
  virtual bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const = 0;

  // The rays a sample averages (those that exist): 1 but for a mesh camera's
  // rays-per-pixel; ray `index` of them.
  virtual int raysPerSample() const { return 1; }
  virtual bool generateRayNumber(const Vec2& film, const Vec2& lens, int /*index*/,
                                 Ray& ray) const {
    return generateRay(film, lens, ray);
  }
  // Whether every ray starts at the frame's origin or close to it, so that the solids the
  // camera stands in are those about the origin (a mesh camera's rays start anywhere).
  virtual bool fixedOrigin() const { return true; }

  const CameraFrame& frame() const { return frame_; }

 protected:
  Projection(const CameraFrame& frame, const Camera& camera, int width, int height)
      : frame_(frame), near_(camera.near), far_(camera.far), width_(width), height_(height) {}

  // A primary ray with the camera's near/far as its parameter range.
  Ray primaryRay(const Vec3& origin, const Vec3& unitDirection) const {
    return Ray(origin, unitDirection, near_, far_);
  }

  CameraFrame frame_;
  double near_, far_;
  int width_, height_;
};

// The projection for the camera's type at the given image size. Throws LocatedError for a
// camera that cannot form an image (at this size: a cube map needs whole-pixel faces).
std::unique_ptr<Projection> makeProjection(const Camera& camera, int width, int height);

}  // namespace lucent
