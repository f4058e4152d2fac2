// The progress line: alone, or naming the frame with an ETA for the whole run.
#include "app/progress_bar.h"

#include <catch2/catch.hpp>

using namespace lucent;

TEST_CASE("progress line: one image", "[render][progress]") {
  CHECK(progressLine(0.5, 2.5e6, 10.0, std::nullopt) ==
        "rendering [###############...............]  50%  2.50 Mrays/s  ETA 0:10");
  CHECK(progressLine(0.0, 0.0, 0.0, std::nullopt) ==
        "rendering [..............................]   0%  0.00 Mrays/s  ETA ?");
}

TEST_CASE("progress line: a frame of an animation, with the whole run's ETA",
          "[render][progress][animation]") {
  // Frame 3 of 24, the 2nd of the 4 frames this run renders (--frames 2..5); the first
  // took 20 s, this one is half done after 10 s: 1.5 frames in 30 s, 2.5 frames left.
  SequencePosition p{2, 4, 3, 24, 20.0};
  CHECK(progressLine(0.5, 1e6, 10.0, p) ==
        "frame 3/24 [###############...............]  50%  1.00 Mrays/s  ETA 0:10, all 0:50");
  // The first frame not yet begun: no estimate for the run.
  SequencePosition first{1, 24, 1, 24, 0.0};
  CHECK(progressLine(0.0, 0.0, 0.0, first) ==
        "frame 1/24 [..............................]   0%  0.00 Mrays/s  ETA ?, all ?");
}
