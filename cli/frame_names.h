// The file each frame of an animation is written to, made from the -o name: a run of '#'
// in the file name becomes the zero-padded frame number (f_###.exr: f_001.exr), or else
// the number goes before the extension, at least 4 digits (out.png: out0001.png). The
// number is never cut: it is padded to as many digits as the last frame needs.
#pragma once

#include <string>

namespace lucent::cli {

std::string frameOutputPath(const std::string& output, int frame, int frames);

}  // namespace lucent::cli
