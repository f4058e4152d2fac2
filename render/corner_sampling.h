// Adaptive anti-aliasing on pixel corners, POV-Ray's method 2 (+AM2): every pixel corner is
// traced once and shared by the (up to) four pixels that meet there; a pixel whose four
// corners agree is their mean, and a square whose corners differ is split into four, down to
// `depth` - 1 levels, each square the mean of its four quarters. Samples lie on a lattice
// of `step` = 2^(depth-1) points a pixel side; a sample is traced at most once per tile (the
// edge it shares with the pixel to its left or above is handed on), and since its colour
// depends only on its lattice point, the image never depends on tiles or threads.
#pragma once

#include "image.h"
#include "trace_context.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace lucent {

// POV-Ray's test of two samples: the sum over r, g, b of the differences of the colours
// encoded with its Antialias_Gamma 2.5 (x^(1/2.5), negatives as 0), at least `threshold`.
bool cornersDiffer(const Color& a, const Color& b, float threshold);
// The same test on colours already encoded with encodeForCornerTest.
Color encodeForCornerTest(const Color& c);
bool encodedDiffer(const Color& a, const Color& b, float threshold);

// The colour at lattice point (fx, fy): film position (fx, fy) / step.
using LatticeTrace = std::function<Color(int fx, int fy, TraceContext& context)>;

// One tile's subdivision: the pixels of columns [x0, x1), visited row by row, left to right
// (each hands its right and bottom edges on to the next). Holds the edge buffers, so a tile
// allocates once and a pixel never.
class CornerTile {
 public:
  // `corners`: the traced pixel corners of a rectangle of the image whose top-left pixel is
  // (originX, originY): corner (i, j), at film (i, j), is corners.at(i - originX, j -
  // originY); `encodedCorners`, the same encoded with encodeForCornerTest (once, not once
  // for each of the 4 pixels).
  CornerTile(const Image& corners, const Image& encodedCorners, int originX, int originY,
             float threshold, int depth, int x0, int x1);

  // Pixel (x, y), which must follow the previous one in the visiting order (a new row may
  // start anywhere inside the tile, so that a cancelled row leaves nothing stale).
  Color pixel(int x, int y, const LatticeTrace& trace, TraceContext& context);

 private:
  struct Sample {
    Color color{0.0f};
    Color encoded{0.0f};  // encodeForCornerTest(color): each sample is encoded once
    uint32_t pixel = 0;   // grid_: the pixel (numbered from 1) it belongs to; edges: 1 if traced
  };
  Sample& at(int a, int b) { return grid_[static_cast<size_t>(b) * (step_ + 1) + a]; }
  bool have(int a, int b) { return at(a, b).pixel == pixelNumber_; }
  Color subdivide(int a, int b, int size, int level);
  void fill(int a, int b);

  const Image& corners_;
  const Image& encodedCorners_;
  int originX_, originY_;
  float threshold_;
  int depth_, step_, x0_;
  // The current pixel's (step+1)^2 lattice points. An entry is valid when it carries the
  // pixel's number, so a new pixel starts without clearing the grid (which would cost
  // step^2 for every pixel, split or not).
  std::vector<Sample> grid_;
  uint32_t pixelNumber_ = 0;
  std::vector<Sample> below_;  // per tile column, step+1 each: the bottom edge of the pixel above
  std::vector<int> belowRow_;  // the row whose bottom edge below_ holds, per column
  std::vector<Sample> right_;  // the right edge of the previous pixel
  int lastX_ = -2, lastY_ = -2;
  int baseX_ = 0, baseY_ = 0;  // the current pixel's top-left lattice point
  const LatticeTrace* trace_ = nullptr;
  TraceContext* context_ = nullptr;
};

}  // namespace lucent
