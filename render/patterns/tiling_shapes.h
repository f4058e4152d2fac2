// What render/patterns/tiling.cpp and tiling_more.cpp share: the constants of the
// tilings' geometry and the folds and measures more than one tiling uses.
#pragma once

namespace lucent::tiling {

inline constexpr double kS3 = 1.7320508075688772935;    // sqrt(3)
inline constexpr double kS3h = 0.86602540378443864676;  // sqrt(3) / 2
inline constexpr double kS2 = 1.4142135623730950488;    // sqrt(2)
inline constexpr double kS2h = 0.70710678118654752440;  // sqrt(2) / 2

// v moved by whole periods into [0, period).
double wrap(double v, double period);

// The lozenge of tiling 4 in its strip, from its last fold: 1 on its edges, 0 at its centre.
double lozengeInStrip(double x, double z);

// A 2x1 rectangle's edge measure (0 on the middle of its centre line, 1 on its edges).
double rectangleEdge(double x, double z, bool alongZ);

// An equilateral triangle of side 1 of a row of them (0 <= x <= 1/2 from a vertex,
// 0 <= z <= sqrt(3)/2), `flip` its starting orientation: the orientation plus the
// distance measure, over 3 (the lower two thirds of a tiling of triangles and another
// shape).
double triangleThird(double x, double z, int flip);

// The hexagon of a hexagon-and-triangles tiling in its fold: the top third of [0, 1],
// `floor` keeping its lowest value above the triangles' band.
double hexagonThird(double x, double z, double floor);

// Tilings 16 and 17: hexagons, squares and triangles (the rhombitrihexagonal tiling);
// 17 gives each orientation of square and triangle its own band (sixths).
double hexagonsSquaresTriangles(double x, double z, bool sixBands);

// Tilings 19 to 27 (tiling_more.cpp).
double moreTilings(int number, double x, double z);

}  // namespace lucent::tiling

namespace lucent {
using tiling::hexagonsSquaresTriangles;
using tiling::moreTilings;
}  // namespace lucent
