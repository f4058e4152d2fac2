#include "sphere_image.h"

#include <cmath>

namespace lucent {

std::optional<SphereImage> sphereImage(const Transform& worldFromObject, const Vec3& center,
                                       double radius) {
  if (worldFromObject.isIdentity()) return SphereImage{center, radius, 0.0};
  const Mat4& m = worldFromObject.worldFromObject();  // m[column][row]

  // The Gram matrix G = LᵀL of the linear part (column i of L is m[i]) and a bound of
  // each entry's rounding: three products and two sums, gamma(3) of the sum of the
  // products' magnitudes (pbrt-v3 §3.9.1).
  double g[3][3], gErr[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double sum = 0.0, mag = 0.0;
      for (int k = 0; k < 3; ++k) {
        sum += m[i][k] * m[j][k];
        mag += std::abs(m[i][k] * m[j][k]);
      }
      g[i][j] = sum;
      gErr[i][j] = gamma(3) * mag;
    }
  // s² is the mean of the squared column lengths (this number, taken as exact). The
  // semi-axes of the exact image are r·σᵢ, σᵢ² the eigenvalues of G, and by Weyl's
  // inequality |σᵢ² − s²| ≤ ‖G − s²I‖₂ ≤ ‖G − s²I‖_F, so |σᵢ − s| ≤ ‖G − s²I‖_F / s.
  double s2 = (g[0][0] + g[1][1] + g[2][2]) / 3.0;
  if (!(s2 > 0.0) || !std::isfinite(s2)) return std::nullopt;
  double fro2 = 0.0, eErr = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double e = g[i][j] - (i == j ? s2 : 0.0);
      fro2 += e * e;
      eErr += gErr[i][j] + (i == j ? kMachineEps * std::abs(e) : 0.0);
    }
  // ‖E_exact‖_F ≤ ‖E_computed‖_F + Σ|entry errors|; (1 + gamma(16)) covers the rounding
  // of this very bound.
  double distortion = (std::sqrt(fro2) + eErr) * (1.0 + gamma(16));
  if (!(distortion <= kMaxDistortion * s2)) return std::nullopt;

  SphereImage out;
  out.center = worldFromObject.pointToWorld(center);
  double s = std::sqrt(s2);
  out.radius = radius * s;
  // Centre: each coordinate is three products and three sums of the matrix row with
  // (center, 1), gamma(4) of their magnitudes (one rounding spare for a fused or
  // reordered evaluation); the distance is at most the sum over the axes.
  double centerErr = 0.0;
  for (int r = 0; r < 3; ++r) {
    double mag = std::abs(m[3][r]);
    for (int c = 0; c < 3; ++c) mag += std::abs(m[c][r] * center[c]);
    centerErr += gamma(4) * mag;
  }
  // Radius: the exact image lies between the spheres of radii r·σmin and r·σmax about
  // the exact centre; |r·σᵢ − r·√s²| ≤ r·distortion/√s², and the square root and the
  // product round out.radius by gamma(2) more.
  double radiusErr = radius * distortion / s + gamma(2) * out.radius;
  out.error = (centerErr + radiusErr) * (1.0 + gamma(8));
  if (!isFinite(out.center) || !(out.radius > 0.0) || !(out.radius * out.radius > 0.0) ||
      !std::isfinite(out.radius * out.radius) || !std::isfinite(out.error))
    return std::nullopt;
  return out;
}

}  // namespace lucent
