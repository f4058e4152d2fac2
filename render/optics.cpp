#include "optics.h"

#include <algorithm>
#include <cmath>

namespace lucent {

bool refract(const Vec3& d, const Vec3& n, double eta, Vec3& transmitted) {
  double cosI = -glm::dot(d, n);
  double k = 1.0 - eta * eta * (1.0 - cosI * cosI);
  if (k < 0.0) return false;
  transmitted = glm::normalize(eta * d + (eta * cosI - std::sqrt(k)) * n);
  return true;
}

double fresnelDielectric(double cosIncident, double n1, double n2) {
  double cosI = std::clamp(cosIncident, 0.0, 1.0);
  double sinI = std::sqrt(std::max(0.0, 1.0 - cosI * cosI));
  double sinT = n1 / n2 * sinI;
  if (sinT >= 1.0) return 1.0;
  double cosT = std::sqrt(std::max(0.0, 1.0 - sinT * sinT));
  double rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
  double rp = (n2 * cosI - n1 * cosT) / (n2 * cosI + n1 * cosT);
  return 0.5 * (rs * rs + rp * rp);
}

Color interiorFade(const Color& fadeColor, double fadeDistance, double fadePower, double distance,
                   bool shadowRay) {
  if (shadowRay && fadePower <= 0.0) return Color(1.0f);
  const double depth = distance / fadeDistance;
  auto channel = [&](float c) {
    if (fadePower >= 1000.0) {
      if (c >= 1.0f) return 1.0f;  // also avoids 0·inf
      return static_cast<float>(std::exp(-(1.0 - c) * depth));
    }
    // pow(d, 0) is 1 even for d = 0 or an infinite d: a constant (1 + c)/2, as POV-Ray's.
    return static_cast<float>(c + (1.0 - c) / (1.0 + std::pow(depth, fadePower)));
  };
  return Color(channel(fadeColor.r), channel(fadeColor.g), channel(fadeColor.b));
}

}  // namespace lucent
