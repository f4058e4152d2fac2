// A four-lane pre-test of the watertight triangle test (watertight.h): which of up to four
// triangles intersectTriangle would surely reject, decided with the same double-precision
// operations as its first step, four triangles at once and without a branch per triangle.
// A mesh's leaf holds a few triangles, most of which a ray misses; the scalar test spent
// its time on their unpredictable branches. Only the lanes left in the mask need the exact
// test, which alone decides every hit.
#pragma once

#include "watertight.h"

#include <cstdint>

namespace lucent {

namespace watertight_detail {
typedef double v4d __attribute__((vector_size(32)));
typedef int64_t v4l __attribute__((vector_size(32)));
}  // namespace watertight_detail

// Bit i (i < n <= 4) is set unless triangle i (corners p[i][0..2]) surely misses the ray:
// a lane is cleared only where two of its edge functions, computed exactly as
// intersectTriangle computes them (the same roundings: the build never contracts a * b + c)
// and outside its band of doubt (where it would recompute them exactly signed), have
// opposite signs. intersectTriangle returns false for such a triangle, so testing only the
// lanes left changes no result. An invalid ray (zero direction) clears every lane.
// Inlined into the leaf loop: a call per four triangles showed in the profile.
__attribute__((always_inline)) inline int watertightCandidates(const ShearedRay& r,
                                                               const Vec3* const (*p)[3], int n) {
  using namespace watertight_detail;
  if (!r.valid || n <= 0) return 0;
  v4d x[3], y[3], z[3];
  for (int k = 0; k < 3; ++k) {
    // Unused lanes repeat triangle 0 (masked off below).
    const Vec3* q[4];
    for (int i = 0; i < 4; ++i) q[i] = p[i < n ? i : 0][k];
    x[k] = v4d{(*q[0])[r.kx], (*q[1])[r.kx], (*q[2])[r.kx], (*q[3])[r.kx]};
    y[k] = v4d{(*q[0])[r.ky], (*q[1])[r.ky], (*q[2])[r.ky], (*q[3])[r.ky]};
    z[k] = v4d{(*q[0])[r.kz], (*q[1])[r.kz], (*q[2])[r.kz], (*q[3])[r.kz]};
  }
  const v4d ox = r.o[r.kx] - v4d{}, oy = r.o[r.ky] - v4d{}, oz = r.o[r.kz] - v4d{};
  const v4d sx = r.sx - v4d{}, sy = r.sy - v4d{};
  v4d sxv[3], syv[3];
  for (int k = 0; k < 3; ++k) {
    const v4d dz = z[k] - oz;
    sxv[k] = (x[k] - ox) - sx * dz;
    syv[k] = (y[k] - oy) - sy * dz;
  }
  // edgeFunction(px, py, qx, qy): l = px·qy, r = py·qx, e = l − r, decided when
  // |e| > gamma(3)·(|l| + |r|). u: (c, b), v: (a, c), w: (b, a).
  const v4d g = gamma(3) - v4d{};
  // |x| by clearing the sign bit (no function: a 32-byte vector argument would change
  // the calling convention where the target lacks AVX).
  const v4l absMask = 0x7fffffffffffffffLL - v4l{};
  v4l neg = v4l{}, pos = v4l{};
  const int from[3] = {2, 0, 1}, to[3] = {1, 2, 0};
  for (int e = 0; e < 3; ++e) {
    const v4d l = sxv[from[e]] * syv[to[e]], rr = syv[from[e]] * sxv[to[e]];
    const v4d d = l - rr;
    const v4d absD = reinterpret_cast<v4d>(reinterpret_cast<v4l>(d) & absMask);
    const v4d absL = reinterpret_cast<v4d>(reinterpret_cast<v4l>(l) & absMask);
    const v4d absR = reinterpret_cast<v4d>(reinterpret_cast<v4l>(rr) & absMask);
    const v4l sure = absD > g * (absL + absR);
    neg |= sure & (d < 0.0);
    pos |= sure & (d > 0.0);
  }
  const v4l keep = ~(neg & pos);
#if defined(__AVX__)
  const int mask = __builtin_ia32_movmskpd256(reinterpret_cast<v4d>(keep));
#else
  int mask = 0;
  for (int i = 0; i < 4; ++i) mask |= int(keep[i] & 1) << i;
#endif
  return mask & ((1 << n) - 1);
}

}  // namespace lucent
