// A closed interval of ray parameters [lo, hi]; empty when lo > hi.
#pragma once

#include "math.h"

#include <algorithm>

namespace lucent {

struct Interval {
  double lo = kInf;
  double hi = -kInf;

  constexpr Interval() = default;
  constexpr Interval(double lo_, double hi_) : lo(lo_), hi(hi_) {}

  static constexpr Interval everything() { return {-kInf, kInf}; }

  bool empty() const { return !(lo <= hi); }
  bool contains(double t) const { return lo <= t && t <= hi; }
  // Strictly inside: the open interval (lo, hi).
  bool surrounds(double t) const { return lo < t && t < hi; }
  double size() const { return hi - lo; }

  Interval intersect(const Interval& o) const { return {std::max(lo, o.lo), std::min(hi, o.hi)}; }
};

}  // namespace lucent
