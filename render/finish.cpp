#include "finish.h"

#include "optics.h"

#include <algorithm>
#include <cmath>

namespace lucent {

double metallicReflectivity(double cosAngle) {
  const double x = std::abs(std::acos(std::clamp(cosAngle, -1.0, 1.0))) / (M_PI / 2.0);
  const double f = 0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903;
  return std::clamp(f, 0.0, 1.0);
}

namespace {

Color metallicTint(const Color& surface, double cosAngle) {
  const float share = static_cast<float>(1.0 - metallicReflectivity(cosAngle));
  return Color(1.0f) + share * (surface - Color(1.0f));
}

}  // namespace

Color surfaceResponse(const Material& m, const Color& kd, const ShadingPoint& at,
                      const Vec3& toLight) {
  const Vec3& n = at.n;
  const Vec3& v = at.v;
  const double nDotL = glm::dot(n, toLight);
  // pow is skipped at the default brilliance: the common case stays one multiply.
  const double diffuse = m.brilliance == 1.0 ? nDotL : std::pow(nDotL, m.brilliance);
  Color sum = kd * static_cast<float>(diffuse);
  if (maxComponent(m.specular) > 0.0f) {
    const Vec3 h = glm::normalize(toLight + v);
    const double nDotH = glm::dot(n, h);
    if (nDotH > 0.0) {
      Color ks = m.specular * static_cast<float>(std::pow(nDotH, m.shininess));
      // POV-Ray takes the metallic angle between the half vector and the light.
      if (m.metallic) ks *= metallicTint(kd, glm::dot(h, toLight));
      sum += ks;
    }
  }
  if (maxComponent(m.phong) > 0.0f) {
    const double rDotL = glm::dot(glm::reflect(-v, n), toLight);
    // POV-Ray drops a sharp highlight's far tail (below 0.0008 for sizes from 60 up).
    if (rDotL > 0.0 && (m.phongSize < 60.0 || rDotL > 0.0008)) {
      Color kp = m.phong * static_cast<float>(std::pow(rDotL, m.phongSize));
      if (m.metallic) kp *= metallicTint(kd, nDotL);
      sum += kp;
    }
  }
  return sum;
}

SecondaryRays secondaryRays(const Material& m, const ShadingPoint& at, bool solid, double n1,
                            double n2) {
  SecondaryRays rays;
  Color kr = m.reflective, kt = m.transmissive;
  if (m.fresnel && (maxComponent(kr) > 0.0f || maxComponent(kt) > 0.0f)) {
    const float f = static_cast<float>(fresnelDielectric(glm::dot(at.v, at.n), n1, n2));
    kr *= f;
    kt *= 1.0f - f;
  }
  rays.mirror = kr;
  if (maxComponent(kt) > 0.0f) {
    if (!solid || n1 == n2) {
      rays.straight = true;
      rays.transmitted = kt;
    } else if (refract(-at.v, at.n, n1 / n2, rays.refracted)) {
      rays.transmitted = kt;
    } else {
      rays.mirror += kt;  // total internal reflection: the k_t share joins the mirror ray
    }
  }
  return rays;
}

}  // namespace lucent
