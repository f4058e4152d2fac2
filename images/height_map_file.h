// A height field's image read as POV-Ray 3.7 reads it (backend/support/imageutil.cpp,
// image_height_at; the parser reads a height field's image without gamma correction):
//   grey, 8 or 16 bits:  (unsigned short)(v / max * 65535), in float arithmetic (a grey PNG
//                        of up to 8 bits first through POV-Ray's grey colour map, which
//                        can lower v by one: height_map_file.cpp)
//   colour, 16 bits:     (0.297 r + 0.589 g + 0.114 b) * 65535
//   colour, 8 bits:      red is the high byte, green the low byte: (r * 256 + g) * 255
//   palette (PNG, GIF):  the palette index times 256 (its colour unused)
//   POT (a GIF named .pot, twice as wide): left index * 256 + the right half's index
// Floating-point images are refused with a message that says so.
#pragma once

#include "primitives/height_map.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace lucent {

struct HeightMapError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The largest image side read as a height field (16.7 million grid points).
constexpr int kMaxHeightFieldSide = 4096;

// The grey level, 0 to 1, POV-Ray gives the value v of a grey PNG of up to 8 bits (max
// 2^depth - 1): through its grey colour map, truncated to 8 bits (can be v - 1 over max).
float povPngGrey(long v, int max);

// Whether the file is read as a POT file: a name ending in .pot (any letter case).
bool isPotFileName(const std::string& path);

// Throws HeightMapError with the reason (the caller names the file).
std::shared_ptr<const HeightMap> readHeightMapFile(const std::string& path);

}  // namespace lucent
