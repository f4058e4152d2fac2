#include "periodic_bilinear.h"

#include <cmath>

namespace lucent {

namespace {

// i modulo n, in [0, n).
int wrapped(int i, int n) {
  const int r = i % n;
  return r < 0 ? r + n : r;
}

}  // namespace

void PeriodicBilinear::lookup(float s, float t, float* rgb) const {
  // Pixel centres lie at half-integers: the four around (x, y), with the fractions of the
  // way from the first to the second.
  float x = s * static_cast<float>(width_) - 0.5f;
  float y = t * static_cast<float>(height_) - 0.5f;
  if (!std::isfinite(x) || !std::isfinite(y)) {
    rgb[0] = rgb[1] = rgb[2] = 0.0f;
    return;
  }
  // Beyond 2^24 a float is an integer: taking it modulo the size first (exact) keeps the
  // same pixel and keeps the conversion to int in range.
  if (std::fabs(x) >= 16777216.0f) x = std::fmod(x, static_cast<float>(width_));
  if (std::fabs(y) >= 16777216.0f) y = std::fmod(y, static_cast<float>(height_));
  const float xFloor = std::floor(x), yFloor = std::floor(y);
  const float xf = x - xFloor, yf = y - yFloor;
  const int x0 = wrapped(static_cast<int>(xFloor), width_);
  const int y0 = wrapped(static_cast<int>(yFloor), height_);
  const int x1 = wrapped(x0 + 1, width_), y1 = wrapped(y0 + 1, height_);
  const float* p00 = rgb_ + 3 * (static_cast<long>(y0) * width_ + x0);
  const float* p10 = rgb_ + 3 * (static_cast<long>(y0) * width_ + x1);
  const float* p01 = rgb_ + 3 * (static_cast<long>(y1) * width_ + x0);
  const float* p11 = rgb_ + 3 * (static_cast<long>(y1) * width_ + x1);
  const float xf1 = 1.0f - xf, yf1 = 1.0f - yf;
  for (int c = 0; c < 3; ++c)
    rgb[c] = yf1 * (p00[c] * xf1 + p10[c] * xf) + yf * (p01[c] * xf1 + p11[c] * xf);
}

}  // namespace lucent
