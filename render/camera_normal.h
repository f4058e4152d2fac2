// POV-Ray 3.7's camera normal (`camera { normal { ... } }`, tracepixel.cpp: CreateCameraRay):
// each primary ray's unit direction is bent as a surface normal would be, by the normal
// pattern at a point (x0, y0, 0) of the image, and normalised again. The point depends on
// the camera type, as POV-Ray's (docs/scene-language.md, "Camera normal").
#pragma once

#include "projection.h"

#include <memory>

namespace lucent {

// The point where the camera's normal is evaluated for the ray through `film` (pixels from
// the image's top left) of a width x height image, `direction` that ray's unbent unit
// direction: the image point x0 = film.x/width − 1/2, y0 = 1/2 − film.y/height for most
// types; spherical, ultra-wide-angle, cylinder and panoramic cameras scale them to their
// angles and axis length, fisheye and omnimax take the ray's angle about the view (x0) and
// from it (y0), as POV-Ray does.
Vec3 cameraNormalPoint(const Camera& camera, const CameraFrame& frame, const Vec2& film,
                       const Vec3& direction, int width, int height);

// `projection`'s rays bent by camera.normal (which must be set).
std::unique_ptr<Projection> bentByCameraNormal(std::unique_ptr<Projection> projection,
                                               const Camera& camera, int width, int height);

}  // namespace lucent
