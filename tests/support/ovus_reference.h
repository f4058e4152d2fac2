// An independent long-double reference for the ovus (primitives/ovus.h), shared by its unit
// tests and its accuracy rows. Its parameters are POV-Ray 3.7's parser's, in the two forms
// it writes them (the bottom radius larger, or not: Parse_Ovus), not Lucent's one formula
// from the tangencies. Along a line each piece (the bottom ball, the top ball, the lemon
// between its seams) has a convex gauge, whose least value golden-section search finds and
// whose two roots about it are bisected to the last bit; the solid's span is the union of
// the pieces' spans. The gauges share no arithmetic with Lucent's (quadratic roots for the
// balls, Newton on the lemon).
#pragma once

#include "primitives/math.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace lucent::test {

struct OvusReference {
  using LD = long double;
  using LV = glm::vec<3, long double>;

  LD rb, rt;
  bool sphereOnly = false;
  LD C = 0, H = 0, V = 0, bottomSeam = 0, topSeam = 0;

  OvusReference(double bottom, double top) : rb(bottom), rt(top) {
    if (!(rt < 2 * rb)) {
      sphereOnly = true;
      return;
    }
    if (rb > rt) {
      C = 2 * rb;
      V = 2 * rt - rb - rt * rt / (2 * rb);
      H = std::sqrt(rb * rb - V * V);
      bottomSeam = -V;
      topSeam = (rb - V) * rt / (C - rt) + rb;
    } else {
      C = 2 * rt;
      V = -2 * rt + rb + 1.5L * rt * rt / rb;
      H = std::sqrt(rt * rt - (V - rb) * (V - rb));
      topSeam = 2 * rb - V;
      bottomSeam = -V * rb / (C - rb);
    }
  }

  static LD len(const LV& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

  // Each piece's convex gauge, negative inside it: 0 the bottom ball, 1 the top ball, 2 the
  // lemon between the seams.
  LD gauge(int piece, const LV& p) const {
    if (piece == 0) return len(p) - rb;
    if (piece == 1) return len(p - LV(0, rb, 0)) - rt;
    const LD rho = std::sqrt(p.x * p.x + p.z * p.z);
    const LD lemon = std::sqrt((rho + H) * (rho + H) + (p.y - V) * (p.y - V)) - C;
    return std::max({lemon, bottomSeam - p.y, p.y - topSeam});
  }
  bool active(int piece) const {
    if (piece == 0) return !sphereOnly && rb > 0;
    if (piece == 1) return rt > 0;
    return !sphereOnly && rt > 0 && H > 0 && bottomSeam < topSeam;
  }

  // POV-Ray's Inside: in the bottom ball, the top ball, or between the seams in the arc's
  // circle.
  bool inside(const LV& p) const {
    for (int k = 0; k < 3; ++k)
      if (active(k) && gauge(k, p) < 0) return true;
    return false;
  }

  // The span of the whole line o + t·d inside the solid, and the pieces it enters and
  // leaves through; false when the line misses.
  bool span(const LV& o, const LV& d, LD& tIn, LD& tOut, int& partIn, int& partOut) const {
    // The chord of a ball about everything: its ends lie outside every piece.
    const LV c(0, rb / 2, 0);
    const LD R = 3 * std::max(rb, rt) + 1;
    const LD a = d.x * d.x + d.y * d.y + d.z * d.z;
    const LV f = o - c;
    const LD tc = -(f.x * d.x + f.y * d.y + f.z * d.z) / a;
    const LV m = f + tc * d;
    const LD q = R * R - (m.x * m.x + m.y * m.y + m.z * m.z);
    if (!(q > 0)) return false;
    const LD half = std::sqrt(q / a);
    bool any = false;
    for (int k = 0; k < 3; ++k) {
      if (!active(k)) continue;
      auto g = [&](LD t) { return gauge(k, o + t * d); };
      LD lo = tc - half, hi = tc + half;
      const LD phi = 0.6180339887498948482L;
      LD x1 = hi - phi * (hi - lo), x2 = lo + phi * (hi - lo), f1 = g(x1), f2 = g(x2);
      for (int it = 0; it < 240; ++it) {
        if (f1 < f2) {
          hi = x2;
          x2 = x1;
          f2 = f1;
          x1 = hi - phi * (hi - lo);
          f1 = g(x1);
        } else {
          lo = x1;
          x1 = x2;
          f1 = f2;
          x2 = lo + phi * (hi - lo);
          f2 = g(x2);
        }
      }
      const LD tm = f1 < f2 ? x1 : x2;
      if (!(g(tm) < 0)) continue;
      const LD l = bisect(g, tc - half, tm), r = bisect(g, tc + half, tm);
      if (!any || l < tIn) {
        tIn = l;
        partIn = k;
      }
      if (!any || r > tOut) {
        tOut = r;
        partOut = k;
      }
      any = true;
    }
    return any;
  }

  // The outward normal of the piece at p.
  LV normal(int piece, const LV& p) const {
    LV n;
    if (piece == 0) {
      n = p;
    } else if (piece == 1) {
      n = p - LV(0, rb, 0);
    } else {
      const LD rho = std::sqrt(p.x * p.x + p.z * p.z);
      n = LV(p.x + p.x * H / rho, p.y - V, p.z + p.z * H / rho);
    }
    return n / len(n);
  }

 private:
  // The root of g between `out` (g > 0) and `in` (g < 0), bisected to the last bit.
  template <class G>
  static LD bisect(const G& g, LD out, LD in) {
    for (int it = 0; it < 200; ++it) {
      const LD mid = (out + in) / 2;
      if (mid == out || mid == in) break;
      (g(mid) < 0 ? in : out) = mid;
    }
    return (out + in) / 2;
  }
};

}  // namespace lucent::test
