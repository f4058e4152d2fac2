#include "corner_sampling.h"

#include <cmath>

namespace lucent {

namespace {

float encoded(float x) { return std::pow(std::max(x, 0.0f), 0.4f); }  // 1 / Antialias_Gamma

}  // namespace

Color encodeForCornerTest(const Color& c) {
  return Color(encoded(c.r), encoded(c.g), encoded(c.b));
}

bool encodedDiffer(const Color& a, const Color& b, float threshold) {
  // POV-Ray also adds the difference in transmit, 0 in an image without alpha, its
  // background included (a sphere near the background colour splits in neither).
  return std::fabs(a.r - b.r) + std::fabs(a.g - b.g) + std::fabs(a.b - b.b) >= threshold;
}

bool cornersDiffer(const Color& a, const Color& b, float threshold) {
  return encodedDiffer(encodeForCornerTest(a), encodeForCornerTest(b), threshold);
}

CornerTile::CornerTile(const Image& corners, const Image& encodedCorners, int originX, int originY,
                       float threshold, int depth, int x0, int x1)
    : corners_(corners),
      encodedCorners_(encodedCorners),
      originX_(originX),
      originY_(originY),
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
  s.color = (*trace_)(baseX_ + a, baseY_ + b, *context_);
  s.encoded = encodeForCornerTest(s.color);
  s.pixel = pixelNumber_;
}

Color CornerTile::subdivide(int a, int b, int size, int level) {
  const Sample& s00 = at(a, b);
  const Sample& s02 = at(a, b + size);
  const Sample& s20 = at(a + size, b);
  const Sample& s22 = at(a + size, b + size);
  const float t = threshold_;
  if (level > 0 &&
      (encodedDiffer(s00.encoded, s02.encoded, t) || encodedDiffer(s00.encoded, s20.encoded, t) ||
       encodedDiffer(s00.encoded, s22.encoded, t) || encodedDiffer(s02.encoded, s20.encoded, t) ||
       encodedDiffer(s02.encoded, s22.encoded, t) || encodedDiffer(s20.encoded, s22.encoded, t))) {
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
  return (s00.color + s02.color + s20.color + s22.color) / 4.0f;
}

Color CornerTile::pixel(int x, int y, const LatticeTrace& trace, TraceContext& context) {
  trace_ = &trace;
  context_ = &context;
  const int n = step_;
  const size_t column = static_cast<size_t>(x - x0_);
  ++pixelNumber_;
  baseX_ = x * n;
  baseY_ = y * n;
  auto put = [&](int a, int b, const Sample& s) {
    at(a, b) = Sample{s.color, s.encoded, pixelNumber_};
  };
  auto corner = [&](int i, int j) {
    return Sample{corners_.at(i - originX_, j - originY_),
                  encodedCorners_.at(i - originX_, j - originY_), 0};
  };
  put(0, 0, corner(x, y));
  put(n, 0, corner(x + 1, y));
  put(0, n, corner(x, y + 1));
  put(n, n, corner(x + 1, y + 1));
  // The edges shared with the pixel to the left and the pixel above, where they were split.
  if (n > 1) {
    if (y == lastY_ && x == lastX_ + 1)
      for (int b = 1; b < n; ++b)
        if (right_[b].pixel) put(0, b, right_[b]);
    if (belowRow_[column] == y - 1)
      for (int a = 1; a < n; ++a)
        if (const Sample& s = below_[column * (n + 1) + a]; s.pixel) put(a, 0, s);
  }

  const Color result = subdivide(0, 0, n, depth_ - 1);

  if (n > 1) {
    auto handOn = [&](int a, int b) {
      const Sample& s = at(a, b);
      return Sample{s.color, s.encoded, have(a, b) ? 1u : 0u};
    };
    for (int b = 1; b < n; ++b) right_[b] = handOn(n, b);
    for (int a = 1; a < n; ++a) below_[column * (n + 1) + a] = handOn(a, n);
    belowRow_[column] = y;
  }
  lastX_ = x;
  lastY_ = y;
  return result;
}

}  // namespace lucent
