// POV-Ray 3.7's solid noise (texture.cpp: Noise, DNoise), reproduced to the last bit where
// the arithmetic allows (docs/patterns-noise.md).
#pragma once

#include "primitives/math.h"

namespace lucent {

// POV-Ray's scalar noise in [0, 1] for noise_generator 1 (the original, values bunched
// around 0.5), 2 (3.7's default: the original stretched towards [0, 1] and clamped) and
// 3 (Perlin's gradient noise on a 2048-entry permutation). Any other generator behaves as
// 1, as in POV-Ray. Pure and thread-safe; the tables are built once, on first use.
double noise(const Vec3& p, int generator);

// POV-Ray's vector noise: three components, each roughly in [-1, 1]. It is the same for
// every noise generator (POV-Ray's DNoise has none).
Vec3 dnoise(const Vec3& p);

// POV-Ray's hash of an integer cell (Hash3d), 0..4095; crackle seeds its points with it.
int latticeHash(int x, int y, int z);

}  // namespace lucent
