// Watertight ray/triangle intersection, shared by <triangle> and <mesh>.
//
// Woop, Benthin, Wald, "Watertight Ray/Triangle Intersection", JCGT 2(1), 2013: the ray is
// made the +z axis of a sheared space (a permutation and a shear computed once per ray),
// the three edge functions are 2-D determinants of the translated vertices, and since a
// shared edge gives bit-identical determinants (with opposite sign) in both triangles, a
// ray can never slip between two triangles that share an edge or a vertex. Where the
// rounding of an edge function could flip its sign we recompute it with Kahan's fma
// difference of products, whose sign is exact (Jeannerod, Louvet, Muller, "Further
// analysis of Kahan's algorithm for the accurate computation of 2×2 determinants", Math.
// Comp. 2013: relative error <= 2u), and an exact 0 is decided by a fixed infinitesimal
// move of the ray (watertight.cpp), so a ray through a shared edge or vertex hits exactly
// one of the triangles around it, never two: crossings of closed meshes alternate.
// The conservative bound on t that rejects hits indistinguishable from t = 0 is pbrt-v3's
// (§3.9.6, "Conservative ray–triangle t").
#pragma once

#include "math.h"
#include "ray.h"

namespace lucent {

// Per-ray constants of the shear (computed once per ray, reused for every triangle).
struct ShearedRay {
  Vec3 o;
  int kx = 0, ky = 1, kz = 2;
  double sx = 0.0, sy = 0.0, sz = 1.0;
  bool valid = false;  // false for a zero direction

  explicit ShearedRay(const Ray& ray);
};

struct TriangleIntersection {
  double t = 0.0;
  double b0 = 0.0, b1 = 0.0, b2 = 0.0;  // barycentric weights of p0, p1, p2
  // Sign of the determinant: +1 when the ray travels against the triangle's normal
  // (p1 − p0) × (p2 − p0) (hits the counter-clockwise side, "entering" for an outward
  // oriented closed mesh), −1 when it travels along it.
  int facing = 0;
};

// Does the whole line hit triangle (p0, p1, p2)? A hit whose |t| is within t's rounding
// bound of zero is moved just behind the origin (t = −bound), so a ray starting on the
// triangle never finds it again at a tiny positive t. Rays parallel to the plane never
// hit; callers skip zero-area triangles (isDegenerateTriangle) before asking.
// A caller that rejects every t <= tmin may pass tmin: a hit whose t cannot be told from 0
// within a bound that is at most tmin is then reported as no hit, without the exact side
// test that would only give its sign (a shadow ray meeting the triangle it starts on).
bool intersectTriangle(const ShearedRay& ray, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                       TriangleIntersection& out, double tmin = -kInf);

// Is the triangle degenerate, its area lost in rounding (|e1 × e2| <= gamma(6)·|e1|·|e2|)?
bool isDegenerateTriangle(const Vec3& p0, const Vec3& p1, const Vec3& p2);

}  // namespace lucent
