#include "optics.h"

#include <algorithm>

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

}  // namespace lucent
