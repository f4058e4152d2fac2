#include "triangle_geometry.h"

namespace lucent {

SurfaceInfo triangleSurface(const Vec3* p, const Vec3* n, const Vec2* uv, double b1, double b2,
                            bool normalFollowsShading) {
  SurfaceInfo s;
  const double b0 = 1.0 - b1 - b2;
  const Vec3 w0 = b0 * p[0], w1 = b1 * p[1], w2 = b2 * p[2];
  s.p = w0 + w1 + w2;
  s.pError = gamma(7) * (glm::abs(w0) + glm::abs(w1) + glm::abs(w2));

  Vec3 ng = glm::cross(p[1] - p[0], p[2] - p[0]);
  double len = glm::length(ng);
  s.ng = len > 0.0 ? ng / len : Vec3(0.0, 1.0, 0.0);
  s.ns = s.ng;
  if (n) {
    Vec3 ns = b0 * n[0] + b1 * n[1] + b2 * n[2];
    double nl = glm::length(ns);
    if (nl > 0.0 && std::isfinite(nl)) {
      s.ns = ns / nl;
      if (glm::dot(s.ns, s.ng) < 0.0) {
        if (normalFollowsShading) s.ng = -s.ng;
        else s.ns = -s.ns;
      }
    }
  }
  if (uv) {
    s.uv = b0 * uv[0] + b1 * uv[1] + b2 * uv[2];
    s.hasUV = true;
  }
  return s;
}

}  // namespace lucent
