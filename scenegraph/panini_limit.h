// How far from the view axis a generalized Panini camera (render/panini.h) can see: one
// rule for the parser, which refuses a wider fov at load, and for the projection, which
// frames the image, so that neither accepts what the other refuses.
//
// The plane coordinate of longitude phi is h(phi) = (d+1) sin(phi) / (d + cos(phi))
// (Sharpless, Postle, German 2010), with dh/dphi = (d+1)(1 + d cos(phi)) / (d + cos(phi))^2.
// For d <= 1, h grows without bound towards cos(phi) = -d. For d > 1 it peaks where
// cos(phi) = -1/d, at h = sqrt((d+1)/(d-1)), and then shrinks: longitudes beyond acos(-1/d)
// fold back onto the image. No direction is farther off the axis than that longitude
// (cos(angle) = cos(latitude) cos(phi)), so the limit bounds every fov-axis.
#pragma once

#include <cmath>

namespace lucent {

// The longitude (radians) the projection reaches at most: acos(-d) for d <= 1, acos(-1/d)
// for d > 1.
inline double paniniLongitudeLimit(double distance) {
  return distance > 1.0 ? std::acos(-1.0 / distance) : std::acos(-distance);
}

// Whether half a horizontal fov (radians) stays below the limit. A fov written exactly at
// the limit (240 degrees for distance 2) must be refused, as the error message says, whichever
// way the conversion to radians and acos() round (a few 1e-16): hence the margin, far above
// that rounding and far below any angle a scene states (1e-12 rad = 6e-11 degrees).
inline bool paniniHalfFovFits(double halfFov, double distance) {
  return halfFov < paniniLongitudeLimit(distance) - 1e-12;
}

}  // namespace lucent
