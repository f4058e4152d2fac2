#include "coarse_passes.h"

#include <algorithm>

namespace lucent::preview {

std::vector<int> coarseSteps(int width, int height) {
  std::vector<int> steps;
  for (int step : {8, 4, 2})
    if (step < std::max(width, height)) steps.push_back(step);
  return steps;
}

bool tracedInPass(int x, int y, int step, int firstStep) {
  if (x % step != 0 || y % step != 0) return false;
  if (step >= firstStep) return true;
  const int coarser = step * 2;
  return x % coarser != 0 || y % coarser != 0;
}

int gridSize(int pixels, int step) { return (pixels + step - 1) / step; }

}  // namespace lucent::preview
