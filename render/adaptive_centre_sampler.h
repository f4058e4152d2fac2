// Adaptive supersampling of pixel centres: every pixel's centre first; then each pixel
// whose centre differs from one of its eight neighbours' by more than the threshold is
// refined, in stages of 6, 12, 24, ... samples up to `samples` (the stopping rule is in
// adaptive_centre_sampler.cpp). A refined pixel is the mean of the samples it took: the
// same sub-pixel positions as fixed sampling's, in the same order, so a pixel that takes
// them all equals the fixed sampler's.
//
// Whether a pixel goes on after a stage depends on its neighbours' samples, so the pixels
// of a rectangle depend on pixels up to one stage count beyond it (margin()): a rectangle
// is rendered with that margin around it, each pixel at distance d from the rectangle
// refined only through the stages that can still reach it, and equals the same pixels of
// the whole image.
#pragma once

#include "pixel_sampler.h"

namespace lucent {

class AdaptiveCentreSampler : public PixelSampler {
 public:
  // Why 6: Halton (2,3) points 1..6 fall one in each cell of the pixel's 2 x 3 grid (index
  // mod 2 picks the column, index mod 3 the row), while points 1..4 leave the quarter
  // x, y > 1/2 empty.
  static constexpr int kFirstStage = 6;

  // The stages a pixel may take with `samples` (> 1) samples, and so the margin a
  // rectangle's pixels depend on (one stage's decision reaches one pixel further).
  static int margin(int samples);

  // An image of width x height pixels; `threshold` (> 0) on the largest difference of one
  // channel of two linear colours.
  AdaptiveCentreSampler(const CameraSamples& camera, int width, int height, float threshold)
      : camera_(camera), width_(width), height_(height), threshold_(threshold) {}

  // Two passes over the rectangle and its margin: the centres, and the first stage.
  uint64_t work(const PixelRect& rect) const override;
  void render(const PixelRect& rect, PixelPasses& passes, Image& out) const override;

 private:
  const CameraSamples& camera_;
  const int width_, height_;
  const float threshold_;
};

}  // namespace lucent
