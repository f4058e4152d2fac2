// Limits of the render settings, for the scene's <render> and the command line's overrides
// alike (docs/security.md lists them).
#pragma once

namespace lucent {

// 65536 pixels a side is beyond any image format we write and keeps width*height*samples
// within 64-bit counters; 2^20 samples a pixel is far past visible convergence; the tracer
// recurses once per depth level, and 1000 levels stay far from the stack limit.
constexpr int kMaxImageSide = 65536;
constexpr int kMaxSamples = 1 << 20;
constexpr int kMaxRecursionDepth = 1000;

}  // namespace lucent
