// The shadow of an adaptive area light (`adaptive="N"`, POV-Ray's `adaptive N`): an
// nu × nv grid of light samples estimated from only as many of them as its shadow edges need.
//
// A rectangle of grid points [u1, u2] × [v1, v2] traces its four corners. It is split into
// four quadrants, each estimated in the same way, when it spans more than two points along
// some axis and either it lies fewer than N levels below the whole grid or two neighbouring
// corners (not the diagonals) differ by more than 0.1, measured as POV-Ray does: the sum
// over channels of |radiance·(t_a − t_b)|, the light as it reaches the point. Its value is
// the mean of its four corners, or else of its four quadrants. An axis [i, j] splits into
// [i, ⌊m⌋] and [⌈m⌉, j], m = (i + j)/2: the halves share the middle point when j − i is even,
// and an axis of one or two points no longer splits (its quadrants repeat its points).
//
// So the weights are POV-Ray's recursive quadrant averages, not the plain average of a
// light without `adaptive`: subdivided everywhere, a 2^k + 1 axis gets the trapezoid rule's
// (1 2 2 … 2 1)/2^k and a 2^k axis the uniform 1/2^k. Each grid point is traced at most once
// per estimate.
#pragma once

#include "primitives/math.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace lucent {

class AdaptiveAreaSampler {
 public:
  // The estimate of the mean transmittance of an nu × nv grid (each >= 1). sample(a, b) is
  // the transmittance towards grid point (a, b), 0 <= a < nu, 0 <= b < nv; `forcedLevels`
  // is N; `radiance` the unshadowed light, which scales the test for differing corners.
  template <class Sample>
  Color average(int nu, int nv, int forcedLevels, const Color& radiance, Sample&& sample) {
    begin(static_cast<size_t>(nu) * static_cast<size_t>(nv));
    Grid<Sample> grid{nu, forcedLevels, radiance, sample};
    return region(grid, 0, 0, nu - 1, nv - 1, 0);
  }

 private:
  template <class Sample>
  struct Grid {
    int nu;
    int forcedLevels;
    Color radiance;
    Sample& sample;
  };

  // POV-Ray's threshold between two corners' light.
  static bool differ(const Color& radiance, const Color& a, const Color& b) {
    Color d = radiance * (a - b);
    return std::fabs(d.r) + std::fabs(d.g) + std::fabs(d.b) > 0.1f;
  }

  template <class Sample>
  Color point(Grid<Sample>& grid, int a, int b) {
    const size_t k = static_cast<size_t>(b) * static_cast<size_t>(grid.nu) + static_cast<size_t>(a);
    if (stamps_[k] != stamp_) {
      values_[k] = grid.sample(a, b);
      stamps_[k] = stamp_;
    }
    return values_[k];
  }

  template <class Sample>
  Color region(Grid<Sample>& grid, int u1, int v1, int u2, int v2, int level) {
    Color c[4] = {point(grid, u1, v1), point(grid, u2, v1), point(grid, u1, v2),
                  point(grid, u2, v2)};
    if ((u2 - u1 > 1 || v2 - v1 > 1) &&
        (level < grid.forcedLevels || differ(grid.radiance, c[0], c[1]) ||
         differ(grid.radiance, c[1], c[3]) || differ(grid.radiance, c[3], c[2]) ||
         differ(grid.radiance, c[2], c[0]))) {
      const int uLow = (u1 + u2) / 2, uHigh = (u1 + u2 + 1) / 2;  // floor and ceil of the middle
      const int vLow = (v1 + v2) / 2, vHigh = (v1 + v2 + 1) / 2;
      c[0] = region(grid, u1, v1, uLow, vLow, level + 1);
      c[1] = region(grid, uHigh, v1, u2, vLow, level + 1);
      c[2] = region(grid, u1, vHigh, uLow, v2, level + 1);
      c[3] = region(grid, uHigh, vHigh, u2, v2, level + 1);
    }
    return (c[0] + c[1] + c[2] + c[3]) * 0.25f;
  }

  // Marks every grid point untraced without clearing: a point is traced in this estimate
  // when its stamp is the current one.
  void begin(size_t points) {
    if (values_.size() < points) {
      values_.resize(points);
      stamps_.resize(points, 0);
    }
    if (++stamp_ == 0) {
      std::fill(stamps_.begin(), stamps_.end(), 0u);
      stamp_ = 1;
    }
  }

  std::vector<Color> values_;
  std::vector<uint32_t> stamps_;
  uint32_t stamp_ = 0;
};

}  // namespace lucent
