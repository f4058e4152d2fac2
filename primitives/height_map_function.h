// A height field's grid sampled from a function, as POV-Ray 3.7 makes the image of
// `height_field { function W, H { F } }` (parser's Make_Pattern_Image, then Compute_HField):
// the image's pixel (column i, row r) holds F(i/(W-1), r/(H-1), 0), its rows are then read
// bottom up, so the grid point (x, z) = (i, k) takes F(i/(W-1), 1 - k/(H-1), 0): the
// function's y runs against the field's z. The value v becomes the height v·65535 in single
// precision, truncated and wrapped to 16 bits as POV-Ray 3.7 stores it (values outside
// [0, 1] wrap around: heightOfFunctionValue).
#pragma once

#include "height_map.h"
#include "scalar_field.h"

#include <memory>

namespace lucent {

// The most grid points along a side (16.7 million points in all, as an image's).
constexpr int kMaxFunctionFieldSide = 4096;

// width, depth: 2 or more. Rows are sampled in parallel (f must be thread-safe, as every
// ScalarField is).
std::shared_ptr<const HeightMap> sampleHeightMap(const ScalarField& f, int width, int depth);

// The height POV-Ray stores for a function value v (the steps above).
uint16_t heightOfFunctionValue(double v);

}  // namespace lucent
