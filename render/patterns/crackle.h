// POV-Ray 3.7's crackle (pattern.cpp, crackle_pattern): one random point in every unit
// cube; the value combines the distances to the nearest three. And its cells, which share
// crackle's random table.
#pragma once

#include "scenegraph/pattern.h"

namespace lucent {

// form.x·d1 + form.y·d2 + form.z·d3 clamped to [0, 1], d1 ≤ d2 ≤ d3 the distances (in
// `metric`, with `offset` added) from p to the points of the 81 cubes within a 3-D
// knight's move of p's cube; with `solid`, the noise at the nearest point instead.
// Allocates nothing; the random table is built once, on first use.
double crackleValue(const Vec3& p, const CrackleParams& crackle, int generator);

// POV-Ray's cells: the random value of p's unit cube (the cube below p + 1e-10 on each
// axis), from the table crackle seeds its points with, indexed by the cube's hash.
double cellsValue(const Vec3& p);

// POV-Ray's random table (PatternRands, and WarpRands, drawn alike) at index 0..4097: a
// lattice hash plus at most 2, as crackle's and the black hole warp's seeds are.
double patternRandom(int index);

// The random points of the 81 cubes within a 3-D knight's move of p's cube (the cube below
// p - 1e-10 on each axis), in POV-Ray's order (facets takes the first nearest).
constexpr int kCrackleCubes = 81;
void crackleCubePoints(const Vec3& p, Vec3 (&points)[kCrackleCubes]);

}  // namespace lucent
