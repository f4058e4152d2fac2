// Root finding in long double for the accuracy references: the extremum of a function on
// an interval and a root bracketed by a sign change, each to the last bit.
#pragma once

#include "accuracy_harness.h"

#include <cmath>

namespace lucent::accuracy {

// The minimum (sign 1) or maximum (sign −1) of g on [a, b] by golden-section search, to long
// double precision within `iterations` steps.
template <class G>
LD goldenExtremum(const G& g, LD a, LD b, int sign, int iterations) {
  const LD k = (std::sqrt(5.0L) - 1) / 2;
  LD x1 = b - k * (b - a), x2 = a + k * (b - a);
  LD f1 = sign * g(x1), f2 = sign * g(x2);
  for (int i = 0; i < iterations && x1 < x2; ++i) {
    if (f1 < f2) {
      b = x2, x2 = x1, f2 = f1;
      x1 = b - k * (b - a);
      f1 = sign * g(x1);
    } else {
      a = x1, x1 = x2, f1 = f2;
      x2 = a + k * (b - a);
      f2 = sign * g(x2);
    }
  }
  return f1 < f2 ? x1 : x2;
}

// A root of g in [a, b], where g(a) = ga and g changes sign, by bisection to the last bit.
template <class G>
LD bisectRoot(const G& g, LD a, LD b, LD ga) {
  for (int i = 0; i < 200; ++i) {
    LD m = (a + b) / 2;
    if (m == a || m == b) break;
    LD gm = g(m);
    if (gm == 0) return m;
    if ((gm < 0) == (ga < 0)) {
      a = m;
      ga = gm;
    } else {
      b = m;
    }
  }
  return (a + b) / 2;
}

}  // namespace lucent::accuracy
