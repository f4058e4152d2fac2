// The coarse passes a preview shows before the full render: every 8th pixel of every 8th
// row, then every 4th, then every 2nd, each pass tracing only the pixels the passes before
// it did not, so the passes together cost a quarter of the image (1/64 + 3/256 + 3/64...).
#pragma once

#include <vector>

namespace lucent::preview {

// The steps of the coarse passes, coarsest first: 8, 4, 2 (those below the image's size).
std::vector<int> coarseSteps(int width, int height);

// Whether pass `step` traces pixel (x, y): x and y are multiples of `step`, and the pixel
// was not traced by a coarser pass (none is coarser than `firstStep`).
bool tracedInPass(int x, int y, int step, int firstStep);

// The size of pass `step`'s grid: one value per step x step block, the last ones partial.
int gridSize(int pixels, int step);

}  // namespace lucent::preview
