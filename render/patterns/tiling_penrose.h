// POV-Ray 3.7's Penrose tilings, tiling 25 (P1: pentagons, stars, boats and diamonds),
// 26 (P2: kites and darts) and 27 (P3: wide and narrow rhombi), centred on the origin.
#pragma once

namespace lucent::tiling {

double penroseP1(double x, double z);
double penroseP2P3(double x, double z, bool rhombi);

}  // namespace lucent::tiling
