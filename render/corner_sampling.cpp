#include "corner_sampling.h"

#include <cmath>

namespace lucent {

namespace {

float encoded(float x) { return std::pow(std::max(x, 0.0f), 0.4f); }  // 1 / Antialias_Gamma

}  // namespace

bool cornersDiffer(const Color& a, const Color& b, float threshold) {
  // POV-Ray also adds the difference in transmit, 0 in an image without alpha, its
  // background included (a sphere near the background colour splits in neither).
  const float d = std::fabs(encoded(a.r) - encoded(b.r)) + std::fabs(encoded(a.g) - encoded(b.g)) +
                  std::fabs(encoded(a.b) - encoded(b.b));
  return d >= threshold;
}

CornerTile::CornerTile(const Image& corners, float threshold, int depth, int x0, int x1)
    : corners_(corners),
      threshold_(threshold),
      depth_(depth),
      step_(1 << (depth - 1)),
      x0_(x0),
      grid_(static_cast<size_t>(step_ + 1) * (step_ + 1)),
      below_(static_cast<size_t>(x1 - x0) * (step_ + 1)),
      belowRow_(static_cast<size_t>(x1 - x0), -2),
      right_(static_cast<size_t>(step_ + 1)) {}

void CornerTile::fill(int a, int b) {
  if (have(a, b)) return;
  Sample& s = at(a, b);
  s.color = (*trace_)(baseX_ + a, baseY_ + b, *stats_);
  s.pixel = pixelNumber_;
}

Color CornerTile::subdivide(int a, int b, int size, int level) {
  const Color& c00 = at(a, b).color;
  const Color& c02 = at(a, b + size).color;
  const Color& c20 = at(a + size, b).color;
  const Color& c22 = at(a + size, b + size).color;
  const float t = threshold_;
  if (level > 0 && (cornersDiffer(c00, c02, t) || cornersDiffer(c00, c20, t) ||
                    cornersDiffer(c00, c22, t) || cornersDiffer(c02, c20, t) ||
                    cornersDiffer(c02, c22, t) || cornersDiffer(c20, c22, t))) {
    const int h = size / 2;
    fill(a, b + h);
    fill(a + h, b);
    fill(a + size, b + h);
    fill(a + h, b + size);
    fill(a + h, b + h);
    // Summed in POV-Ray's order, so that equal samples give equal pixels.
    const Color q00 = subdivide(a, b, h, level - 1);
    const Color q01 = subdivide(a, b + h, h, level - 1);
    const Color q10 = subdivide(a + h, b, h, level - 1);
    const Color q11 = subdivide(a + h, b + h, h, level - 1);
    return (q00 + q01 + q10 + q11) / 4.0f;
  }
  return (c00 + c02 + c20 + c22) / 4.0f;
}

Color CornerTile::pixel(int x, int y, const LatticeTrace& trace, RayStats& stats) {
  trace_ = &trace;
  stats_ = &stats;
  const int n = step_;
  const size_t column = static_cast<size_t>(x - x0_);
  ++pixelNumber_;
  baseX_ = x * n;
  baseY_ = y * n;
  auto put = [&](int a, int b, const Color& c) { at(a, b) = Sample{c, pixelNumber_}; };
  put(0, 0, corners_.at(x, y));
  put(n, 0, corners_.at(x + 1, y));
  put(0, n, corners_.at(x, y + 1));
  put(n, n, corners_.at(x + 1, y + 1));
  // The edges shared with the pixel to the left and the pixel above, where they were split.
  if (n > 1) {
    if (y == lastY_ && x == lastX_ + 1)
      for (int b = 1; b < n; ++b)
        if (right_[b].pixel) put(0, b, right_[b].color);
    if (belowRow_[column] == y - 1)
      for (int a = 1; a < n; ++a)
        if (const Sample& s = below_[column * (n + 1) + a]; s.pixel) put(a, 0, s.color);
  }

  const Color result = subdivide(0, 0, n, depth_ - 1);

  if (n > 1) {
    for (int b = 1; b < n; ++b) right_[b] = Sample{at(n, b).color, have(n, b) ? 1u : 0u};
    for (int a = 1; a < n; ++a)
      below_[column * (n + 1) + a] = Sample{at(a, n).color, have(a, n) ? 1u : 0u};
    belowRow_[column] = y;
  }
  lastX_ = x;
  lastY_ = y;
  return result;
}

}  // namespace lucent
