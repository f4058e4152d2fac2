// Limits on the numbers a scene or mesh file may give.
#pragma once

namespace lucent {

// The largest magnitude a scene or mesh file may give a number (except distances that may
// be infinite). Squares and fourth powers in the intersection code (a torus is quartic)
// stay far inside double range, so no absurd value turns into inf or NaN there.
constexpr double kMaxMagnitude = 1e30;
// ... and the smallest nonzero magnitude, for the same reason from below: a radius of 1e-320
// would square to zero.
constexpr double kMinMagnitude = 1e-30;

}  // namespace lucent
