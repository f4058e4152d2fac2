// The weights of a sphere sweep segment's four control spheres at u in [0, 1], in long
// double, from the textbook forms of the splines (not from primitives/sphere_sweep.cpp):
// the independent reference the sweep's unit tests and accuracy rows compare against.
#pragma once

#include "primitives/sphere_sweep.h"

namespace lucent::test {

inline void sweepSplineWeights(SweepSpline spline, long double u, long double w[4]) {
  using LD = long double;
  w[0] = w[1] = w[2] = w[3] = 0;
  if (spline == SweepSpline::Linear) {
    w[0] = 1 - u;
    w[1] = u;
  } else if (spline == SweepSpline::BSpline) {
    w[0] = (1 - u) * (1 - u) * (1 - u) / 6;
    w[1] = (3 * u * u * u - 6 * u * u + 4) / 6;
    w[2] = (-3 * u * u * u + 3 * u * u + 3 * u + 1) / 6;
    w[3] = u * u * u / 6;
  } else {
    // Hermite between P1 and P2 with the tangents m1 = (P2 − P0)/2 and m2 = (P3 − P1)/2:
    // p(u) = h00·P1 + h10·m1 + h01·P2 + h11·m2 (Catmull-Rom).
    const LD h00 = 2 * u * u * u - 3 * u * u + 1, h10 = u * u * u - 2 * u * u + u,
             h01 = -2 * u * u * u + 3 * u * u, h11 = u * u * u - u * u;
    w[0] = -h10 / 2;
    w[1] = h00 - h11 / 2;
    w[2] = h01 + h10 / 2;
    w[3] = h11 / 2;
  }
}

}  // namespace lucent::test
