// The optics of a smooth surface: mirror reflection, Snell refraction, the exact Fresnel
// reflectance of a dielectric, Beer–Lambert absorption and POV-Ray's interior fade.
#pragma once

#include "primitives/math.h"

namespace lucent {

// Mirror direction of d about the unit normal n: d − 2(d·n)n.
inline Vec3 reflect(const Vec3& d, const Vec3& n) { return d - 2.0 * glm::dot(d, n) * n; }

// POV-Ray's mirror direction about a bent shading normal n (raw: the unbent normal facing
// the viewer; all unit vectors, d the incident direction). A mirror ray that would leave
// below the surface (behind raw) is turned back: if n faces the viewer it is reflected once
// more, about raw; if n faces away it is d reflected about raw instead. With n = raw this
// is reflect(d, n).
inline Vec3 reflectAboveSurface(const Vec3& d, const Vec3& n, const Vec3& raw) {
  const Vec3 r = reflect(d, n);
  if (glm::dot(r, raw) >= 0.0) return r;
  return glm::dot(r, n) < 0.0 ? reflect(d, raw) : reflect(r, raw);
}

// Snell's law (Heckbert's form): d is the unit incident direction, n the unit normal on
// the incident side (d·n ≤ 0), eta = n1/n2 (incident over transmitted index). Writes the
// unit transmitted direction; returns false under total internal reflection.
bool refract(const Vec3& d, const Vec3& n, double eta, Vec3& transmitted);

// Unpolarised Fresnel reflectance of a smooth dielectric interface (average of the s and p
// reflectances; Hecht, "Optics", 4.6; pbrt-v3 FrDielectric). cosIncident = cos of the angle
// between the incident ray and the normal (≥ 0), n1 on the incident side, n2 beyond.
// Returns 1 under total internal reflection; ((n1−n2)/(n1+n2))² at normal incidence.
double fresnelDielectric(double cosIncident, double n1, double n2);

// Beer–Lambert: the fraction of light left after `distance` in a medium with the given
// absorption coefficient per world unit, exp(−absorption·distance) per channel.
inline Color beerLambert(const Color& absorption, double distance) {
  auto channel = [distance](float a) {
    if (a <= 0.0f) return 1.0f;  // also avoids 0·inf for a ray that never leaves
    return static_cast<float>(std::exp(-static_cast<double>(a) * distance));
  };
  return Color(channel(absorption.r), channel(absorption.g), channel(absorption.b));
}

// POV-Ray's interior fade over `distance` (infinite for a ray that never leaves), per
// channel: fadeColor + (1 − fadeColor)/(1 + (distance/fadeDistance)^fadePower), and from
// fadePower 1000 up POV-Ray's exponential exp(−(1 − fadeColor)·distance/fadeDistance).
// fadeDistance > 0. A shadow ray is not faded at fadePower 0, as POV-Ray's shadow rays.
Color interiorFade(const Color& fadeColor, double fadeDistance, double fadePower, double distance,
                   bool shadowRay);

}  // namespace lucent
