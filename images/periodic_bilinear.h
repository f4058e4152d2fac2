// Bilinear lookup of an RGB float image that repeats in both directions: the texture
// lookup of image maps. Its arithmetic is OpenImageIO 2.4's ImageBuf::interppixel_NDC with
// WrapPeriodic, step for step in single precision, so images rendered before it replaced
// that call are unchanged (tests/images/builtin_texture_read_test.cpp compares the two).
#pragma once

namespace lucent {

class PeriodicBilinear {
 public:
  // Views `rgb` (width * height RGB floats, row 0 at the top), which must outlive it.
  PeriodicBilinear(const float* rgb, int width, int height)
      : rgb_(rgb), width_(width), height_(height) {}

  // (s, t) in [0,1]^2 spans the image, t = 0 at row 0; writes three floats to rgb.
  void lookup(float s, float t, float* rgb) const;

 private:
  const float* rgb_;
  int width_, height_;
};

}  // namespace lucent
