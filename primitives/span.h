// The two answers every shape derives from its roots along the whole line: a convex solid
// is inside on one span [tIn, tOut]; an open surface is crossed at a few places. Deriving
// intersect() and crossings() from the same roots keeps them consistent by construction.
#pragma once

#include "shape.h"

#include <cstdint>

namespace lucent {

// Where the line o + t·d (t over all reals) is inside a convex solid, and through which
// parts it enters and leaves. tIn may equal tOut (a ray touching an edge or a tangent).
struct Span {
  double tIn = kInf, tOut = -kInf;
  uint32_t partIn = 0, partOut = 0;
  double b1In = 0.0, b2In = 0.0, b1Out = 0.0, b2Out = 0.0;  // payloads, if the shape wants
};

// Closest of tIn, tOut strictly inside (tmin, tmax).
bool intersectSpan(const Span& s, const Ray& ray, const Shape* shape, Hit& hit);
// Crossings over the closed [tmin, tmax]; startsInside iff tIn < tmin <= tOut, so a root
// exactly at tmin is listed rather than counted as behind, and the list always alternates.
void crossingsOfSpan(const Span& s, const Ray& ray, const Shape* shape, CrossingList& out);

// A surface point where an open (non-solid) surface meets the line.
struct SurfaceRoot {
  double t;
  uint32_t part = 0;
  double b1 = 0.0, b2 = 0.0;
};

// Closest root strictly inside (tmin, tmax).
bool intersectRoots(const SurfaceRoot* roots, int n, const Ray& ray, const Shape* shape, Hit& hit);
// Every root in [tmin, tmax], sorted, all marked entering; startsInside = false.
void crossingsOfRoots(const SurfaceRoot* roots, int n, const Ray& ray, const Shape* shape,
                      CrossingList& out);

// A solid's crossings from its sign changes along the whole line: t ascending, each
// entering or not, and whether the line is inside before the first. Lists those in
// [tmin, tmax]; startsInside is the state after the ones before tmin (so a root exactly at
// tmin is listed rather than counted as behind).
void crossingsOfLine(const double* t, const bool* entering, int n, bool insideBefore,
                     const Ray& ray, const Shape* shape, CrossingList& out);

}  // namespace lucent
