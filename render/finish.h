// The light a surface sends towards the viewer from one light: diffuse with brilliance,
// the Blinn-Phong `specular` highlight, the Phong `phong` highlight and `metallic`
// (the contract's <material> and "Finish"), per unit of the light's radiance.
#pragma once

#include "scenegraph/material.h"

namespace lucent {

// n: the shading normal facing the viewer; v: towards the viewer; toLight: towards the
// light; all unit vectors, with n·toLight > 0 (a light behind the surface gives nothing,
// the caller skips it). kd: the diffuse colour times the texture.
Color surfaceResponse(const Material& m, const Color& kd, const Vec3& n, const Vec3& v,
                      const Vec3& toLight);

// POV-Ray's empirical metallic reflectivity for the angle whose cosine is `cosAngle`:
// a highlight's colour is 1 + (1 − F)·(C − 1) for the surface colour C ([DB 9/94] in its
// sources), C at normal incidence and white at grazing.
double metallicReflectivity(double cosAngle);

}  // namespace lucent
