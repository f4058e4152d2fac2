// The grid of a height field as POV-Ray 3.7 stores it: one 16-bit height per image pixel,
// rows flipped so that row z = 0 is the image's bottom row (hfield.cpp, Compute_HField).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lucent {

struct HeightMap {
  int width = 0;                 // grid points along x (the image's width), >= 2
  int depth = 0;                 // grid points along z (the image's height), >= 2
  std::vector<uint16_t> values;  // width * depth, row z by column x

  uint16_t at(int x, int z) const { return values[static_cast<size_t>(z) * width + x]; }
};

}  // namespace lucent
