// The container of a shape found by searching along the ray (<isosurface>, <parametric>):
// a box or a sphere that bounds where the surface is sought. Shared by the two.
#pragma once

#include "isosurface.h"

namespace lucent {

// The container's box; throws std::invalid_argument, naming `shape`, for a box without
// min < max in x, y and z or a sphere without a finite centre and a radius > 0.
AABB containerBounds(const IsosurfaceContainer& c, const char* shape);

// The ray's span inside the container, t over all reals; false when it misses.
bool containerSpan(const IsosurfaceContainer& c, const Ray& ray, double& t0, double& t1);

}  // namespace lucent
