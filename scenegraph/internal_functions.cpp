#include "internal_functions.h"

#include <cctype>
#include <cmath>

namespace lucent {

namespace {

// POV-Ray's min and max macros (the first when equal or unordered).
double povMax(double a, double b) { return a > b ? a : b; }
double povMin(double a, double b) { return a < b ? a : b; }
// Several shapes clamp their field to [-10, 10].
double clampField(double v) { return povMin(10.0, povMax(v, -10.0)); }
#define LUCENT_CLAMP_TEXT(r) "min(10, max(" r ", -10))"

double sphere(const double* p) {
  return -p[3] + std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
}
double radius(const double* p) { return std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]); }
double theta(const double* p) { return std::atan2(p[0], p[2]); }
double phi(const double* p) { return std::atan2(std::sqrt(p[0] * p[0] + p[2] * p[2]), p[1]); }

// One axis of f_rounded_box: how far outside the slab of half-width s - r the point is.
double boxAxis(double c, double r, double s) {
  const double hi = s - r, lo = r - s;
  const double above = c < hi ? 0 : c - hi;
  const double below = c > lo ? 0 : lo - c;
  return povMax(below, above);
}
double roundedBox(const double* p) {
  const double x = boxAxis(p[0], p[3], p[4]), y = boxAxis(p[1], p[3], p[5]),
               z = boxAxis(p[2], p[3], p[6]);
  return -p[3] + std::sqrt(x * x + y * y + z * z) - 1e-6;
}
#define LUCENT_BOX_AXIS(c, s)                                                                \
  "max((" c " > ($3 - " s ") ? 0 : (($3 - " s ") - " c ")), (" c " < (" s " - $3) ? 0 : (" c \
  " - (" s " - $3))))"

double superellipsoid(const double* p) {
  const double e = 2 / p[3], n = 1 / p[4];
  return 1 -
         std::pow(std::pow(std::pow(std::fabs(p[0]), e) + std::pow(std::fabs(p[1]), e), p[3] * n) +
                      std::pow(std::fabs(p[2]), 2 * n),
                  p[4] * .5);
}
double torus(const double* p) {
  const double r = std::sqrt(p[0] * p[0] + p[2] * p[2]) - p[3];
  return -p[4] + std::sqrt(r * r + p[1] * p[1]);
}
double torus2(const double* p) {
  const double x2 = p[0] * p[0], y2 = p[1] * p[1], z2 = p[2] * p[2];
  const double ph = p[4] * p[4], th = p[5] * p[5];
  const double r =
      -(x2 * x2 + y2 * y2 + z2 * z2 + 2 * x2 * y2 + 2 * x2 * z2 + 2 * y2 * z2 - 2 * (ph + th) * x2 +
        2 * (ph - th) * y2 - 2 * (ph + th) * z2 + (ph - th) * (ph - th));
  return clampField(p[3] * r);
}
// f_helix1: p[3] helices of frequency p[4] about y, tubes of radius p[5] about the circle
// of radius p[6], their cross-section squashed along the helix by p[7]: a circle when
// p[8] = 1, else a superellipse of exponent 2/p[8] (a square at 0) turned by p[9] degrees.
// POV-Ray's angle steps: atan2 with x nudged off the axis, fmod by 2pi and one turn added
// below 0 (the floored modulo of the text form).
constexpr double kPovPi = 3.1415926535897932384626;
constexpr double kPovTwoPi = 6.283185307179586476925286766559;
constexpr double kPovPi180 = 0.01745329251994329576;
double helix1(const double* p) {
  const double r = std::sqrt(p[0] * p[0] + p[2] * p[2]);
  double th = std::atan2(p[2], (p[0] == 0 && p[2] == 0) ? 0.000001 : p[0]);
  th = std::fmod(th * p[3] + p[1] * p[4] * p[3], kPovTwoPi);
  if (th < 0) th += kPovTwoPi;
  double z = (th - kPovPi) / p[7] / (p[4] * p[3]);
  double x = r - p[6];
  double r2;
  if (p[8] == 1) {
    r2 = std::sqrt(x * x + z * z);
  } else {
    if (p[9] != 0) {
      const double c = std::cos(p[9] * kPovPi180), s = std::sin(p[9] * kPovPi180);
      const double x2 = x * c - z * s;
      z = x * s + z * c;
      x = x2;
    }
    if (p[8] != 0) {
      const double e = 2. / p[8];
      r2 = std::pow(std::pow(std::fabs(x), e) + std::pow(std::fabs(z), e), p[8] * .5);
    } else {
      r2 = povMax(std::fabs(x), std::fabs(z));
    }
  }
  return -p[5] + povMin(p[6] + r, r2);
}
// The same as text: the angle 0 on the axis (atan2 of ±0 and 1e-6), the turn by p[9]
// taken whatever it is (by 0 it changes nothing).
#define LUCENT_HELIX_Z                                                                      \
  "((((((($0 == 0) && ($2 == 0)) ? 0 : atan2($2, $0))*$3 + $1*$4*$3) % 6.283185307179586) " \
  "- 3.141592653589793)/$7/($4*$3))"
#define LUCENT_HELIX_X "(sqrt($0*$0 + $2*$2) - $6)"
#define LUCENT_HELIX_COS "cos($9*0.017453292519943295)"
#define LUCENT_HELIX_SIN "sin($9*0.017453292519943295)"
#define LUCENT_HELIX_XR \
  "(" LUCENT_HELIX_X "*" LUCENT_HELIX_COS " - (" LUCENT_HELIX_Z ")*" LUCENT_HELIX_SIN ")"
#define LUCENT_HELIX_ZR \
  "(" LUCENT_HELIX_X "*" LUCENT_HELIX_SIN " + (" LUCENT_HELIX_Z ")*" LUCENT_HELIX_COS ")"
const char* const helix1Formula =
    "(-$5 + min($6 + sqrt($0*$0 + $2*$2), ($8 == 1 ? sqrt(" LUCENT_HELIX_X "*" LUCENT_HELIX_X
    " + (" LUCENT_HELIX_Z ")*(" LUCENT_HELIX_Z ")) : ($8 != 0 ? pow(pow(abs(" LUCENT_HELIX_XR
    "), 2/$8) + pow(abs(" LUCENT_HELIX_ZR "), 2/$8), $8*0.5) : max(abs(" LUCENT_HELIX_XR
    "), abs(" LUCENT_HELIX_ZR "))))))";
#undef LUCENT_HELIX_Z
#undef LUCENT_HELIX_X
#undef LUCENT_HELIX_COS
#undef LUCENT_HELIX_SIN
#undef LUCENT_HELIX_XR
#undef LUCENT_HELIX_ZR

double ellipsoid(const double* p) {
  return std::sqrt(p[0] * p[0] * p[3] * p[3] + p[1] * p[1] * p[4] * p[4] +
                   p[2] * p[2] * p[5] * p[5]);
}
double paraboloid(const double* p) {
  return clampField(p[3] * -(p[0] * p[0] - p[1] + p[2] * p[2]));
}
double torusGumdrop(const double* p) {
  const double x2 = p[0] * p[0], y2 = p[1] * p[1], z2 = p[2] * p[2];
  const double r =
      -(4 * (x2 * x2 + (y2 + z2) * (y2 + z2)) + 17 * x2 * (y2 + z2) - 20 * (x2 + y2 + z2) + 17);
  return clampField(p[3] * r);
}
double umbrella(const double* p) { return clampField(p[3] * -(p[0] * p[0] - p[1] * p[2] * p[2])); }
double witchOfAgnesi(const double* p) {
  return clampField(p[3] * -(p[4] * (p[1] - 1) + (p[0] * p[0] + p[2] * p[2]) * p[1]));
}

// The clamped polynomial surfaces: each formula written once, as the expression `r` of
// POV-Ray's min(10, max(P0*r, -10)), compiled here as C++ and kept as text (#r) for
// Lucent's expressions, where its words become the arguments (internalText). X, Y, Z are
// the point, X2, Y2, Z2 their squares, P0, P1... the function's own parameters.
#define X p[0]
#define Y p[1]
#define Z p[2]
#define X2 (p[0] * p[0])
#define Y2 (p[1] * p[1])
#define Z2 (p[2] * p[2])
#define P0 p[3]
#define P1 p[4]
#define P2 p[5]
#define P3 p[6]
#define LUCENT_CLAMPED(fn, r)                                 \
  double fn(const double* p) { return clampField(P0 * (r)); } \
  const char* const fn##Formula = "min(10, max(P0*(" #r "), -10))";
LUCENT_CLAMPED(bicorn, (Y2 * (P1 * P1 - (X2 + Z2)) -
                        (X2 + Z2 + 2 * P1 * Y - P1 * P1) * (X2 + Z2 + 2 * P1 * Y - P1 * P1)))
LUCENT_CLAMPED(bifolia, -((X2 + Y * Y + Z2) * (X2 + Y * Y + Z2) - P1 * (X2 + Z2) * Y))
LUCENT_CLAMPED(crossedTrough, (X * X * Z * Z - Y))
LUCENT_CLAMPED(cubicSaddle, -(X* X* X - Y * Y * Y - Z))
LUCENT_CLAMPED(cushion, (Z2 * X2 - Z2 * Z2 - 2 * Z * X2 + 2 * Z2 * Z + X2 - Z2 -
                         (X2 - Z) * (X2 - Z) - Y2 * Y2 - 2 * X2 * Y2 - Y2 * Z2 + 2 * Y2 * Z + Y2))
LUCENT_CLAMPED(devilsCurve, -(X2* X2 + 2 * X2 * Z2 - 0.36 * X2 - Y2 * Y2 + 0.25 * Y2 + Z2 * Z2))
LUCENT_CLAMPED(glob, (0.5 * X2 * X2 * X + 0.5 * X2 * X2 - (Y * Y + Z * Z)))
LUCENT_CLAMPED(heart, -((2 * X2 + Y2 + Z2 - 1) * (2 * X2 + Y2 + Z2 - 1) * (2 * X2 + Y2 + Z2 - 1) -
                        0.1 * X2 * Z2 * Z - Y2 * Z2 * Z))
LUCENT_CLAMPED(huntSurface, -(4 * (X2 + Y2 + Z2 - 13) * (X2 + Y2 + Z2 - 13) * (X2 + Y2 + Z2 - 13) +
                              27 * (3 * X2 + Y2 - 4 * Z2 - 12) * (3 * X2 + Y2 - 4 * Z2 - 12)))
LUCENT_CLAMPED(hyperbolicTorus,
               -(X2* X2 + 2 * X2 * Y2 - 2 * X2 * Z2 - 2 * (P1 * P1 + P2 * P2) * X2 + Y2 * Y2 -
                 2 * Y2 * Z2 + 2 * (P1 * P1 - P2 * P2) * Y2 + Z2 * Z2 +
                 2 * (P1 * P1 + P2 * P2) * Z2 + (P1 * P1 - P2 * P2) * (P1 * P1 - P2 * P2)))
LUCENT_CLAMPED(kampyleOfEudoxus, -((Y * Y + Z * Z) - P2 * P2 * X2 * X2 + P2 * P2 * P1 * P1 * X2))
LUCENT_CLAMPED(kleinBottle,
               -((X2 + Y2 + Z2 + 2 * Y - 1) *
                     ((X2 + Y2 + Z2 - 2 * Y - 1) * (X2 + Y2 + Z2 - 2 * Y - 1) - 8 * Z2) +
                 16 * X * Z * (X2 + Y2 + Z2 - 2 * Y - 1)))
LUCENT_CLAMPED(kummerSurfaceV1,
               -(X2* X2 + Y2 * Y2 + Z2 * Z2 - X2 - Y2 - Z2 - X2 * Y2 - X2 * Z2 - Y2 * Z2 + 1))
LUCENT_CLAMPED(kummerSurfaceV2, -(X2* X2 + Y2 * Y2 + Z2 * Z2 + P1 * (X2 + Y2 + Z2) +
                                  P2 * (X2 * Y2 + X2 * Z2 + Y2 * Z2) + P3 * X * Y * Z - 1))
LUCENT_CLAMPED(lemniscateOfGerono, -(X2* X2 - X2 + Y2 + Z2))
LUCENT_CLAMPED(mitre, -(4 * X2 * (X2 + Y2 + Z2) - Y2 * (1 - Y2 - Z2)))
LUCENT_CLAMPED(nodalCubic, -(Y* Y* Y + Z * Z * Z - 6 * Y * Z))
LUCENT_CLAMPED(odd, (Z2 * X2 - Z2 * Z2 - 2 * Z * X2 + 2 * Z2 * Z + X2 - Z2 - (X2 - Z) * (X2 - Z) -
                     Y2 * Y2 - 2 * Y2 * X2 - Y2 * Z2 + 2 * Y2 * Z + Y2))
LUCENT_CLAMPED(ovalsOfCassini, -((X2 + Y2 + Z2 + P1 * P1) * (X2 + Y2 + Z2 + P1 * P1) -
                                 P3 * P1 * P1 * (X2 + Z2) - P2 * P2))
LUCENT_CLAMPED(parabolicTorus,
               -(X2* X2 + 2 * X2 * Y2 - 2 * X2 * Z - (P1 * P1 + P2 * P2) * X2 + Y2 * Y2 -
                 2 * Y2 * Z + (P1 * P1 - P2 * P2) * Y2 + Z2 + (P1 * P1 + P2 * P2) * Z +
                 (P1 * P1 - P2 * P2) * (P1 * P1 - P2 * P2)))
LUCENT_CLAMPED(pillow, (X2 * X2 + Y2 * Y2 + Z2 * Z2 - (X2 + Y2 + Z2)))
LUCENT_CLAMPED(quarticParaboloid, -(X2* X2 + Z2 * Z2 - Y))
LUCENT_CLAMPED(quarticSaddle, -(X2* X2 - Z2 * Z2 - Y))
LUCENT_CLAMPED(quarticCylinder, -((X2 + Z2) * Y * Y + P2 * P2 * (X2 + Z2) - P2 * P2 * P1 * P1))
LUCENT_CLAMPED(steinersRoman, -(X2* Y2 + X2 * Z2 + Y2 * Z2 + X * Y * Z))
LUCENT_CLAMPED(foliumSurface, ((Y2 + Z2) * (1 + (P2 - 4 * P1) * X) + X2 * (1 + P2)))
#undef LUCENT_CLAMPED
#undef X
#undef Y
#undef Z
#undef X2
#undef Y2
#undef Z2
#undef P0
#undef P1
#undef P2
#undef P3

// The squares of torus2 and torus_gumdrop, spelt out.
#define LUCENT_X2 "($0*$0)"
#define LUCENT_Y2 "($1*$1)"
#define LUCENT_Z2 "($2*$2)"

// Every internal function of POV-Ray 3.7, by number.
const InternalFunction kInternal[] = {
    {"f_algbr_cyl1", 8, nullptr, nullptr},
    {"f_algbr_cyl2", 8, nullptr, nullptr},
    {"f_algbr_cyl3", 8, nullptr, nullptr},
    {"f_algbr_cyl4", 8, nullptr, nullptr},
    {"f_bicorn", 5, bicorn, bicornFormula},
    {"f_bifolia", 5, bifolia, bifoliaFormula},
    {"f_blob", 8, nullptr, nullptr},
    {"f_blob2", 7, nullptr, nullptr},
    {"f_boy_surface", 5, nullptr, nullptr},
    {"f_comma", 4, nullptr, nullptr},
    {"f_cross_ellipsoids", 7, nullptr, nullptr},
    {"f_crossed_trough", 4, crossedTrough, crossedTroughFormula},
    {"f_cubic_saddle", 4, cubicSaddle, cubicSaddleFormula},
    {"f_cushion", 4, cushion, cushionFormula},
    {"f_devils_curve", 4, devilsCurve, devilsCurveFormula},
    {"f_devils_curve_2d", 9, nullptr, nullptr},
    {"f_dupin_cyclid", 9, nullptr, nullptr},
    {"f_ellipsoid", 6, ellipsoid, "sqrt($0*$0*$3*$3 + $1*$1*$4*$4 + $2*$2*$5*$5)"},
    {"f_enneper", 4, nullptr, nullptr},
    {"f_flange_cover", 7, nullptr, nullptr},
    {"f_folium_surface", 6, foliumSurface, foliumSurfaceFormula},
    {"f_folium_surface_2d", 9, nullptr, nullptr},
    {"f_glob", 4, glob, globFormula},
    {"f_heart", 4, heart, heartFormula},
    {"f_helical_torus", 13, nullptr, nullptr},
    {"f_helix1", 10, helix1, helix1Formula},
    {"f_helix2", 10, nullptr, nullptr},
    {"f_hex_x", 4, nullptr, nullptr},
    {"f_hex_y", 4, nullptr, nullptr},
    {"f_hetero_mf", 9, nullptr, nullptr},
    {"f_hunt_surface", 4, huntSurface, huntSurfaceFormula},
    {"f_hyperbolic_torus", 6, hyperbolicTorus, hyperbolicTorusFormula},
    {"f_isect_ellipsoids", 7, nullptr, nullptr},
    {"f_kampyle_of_eudoxus", 6, kampyleOfEudoxus, kampyleOfEudoxusFormula},
    {"f_kampyle_of_eudoxus_2d", 9, nullptr, nullptr},
    {"f_klein_bottle", 4, kleinBottle, kleinBottleFormula},
    {"f_kummer_surface_v1", 4, kummerSurfaceV1, kummerSurfaceV1Formula},
    {"f_kummer_surface_v2", 7, kummerSurfaceV2, kummerSurfaceV2Formula},
    {"f_lemniscate_of_gerono", 4, lemniscateOfGerono, lemniscateOfGeronoFormula},
    {"f_lemniscate_of_gerono_2d", 9, nullptr, nullptr},
    {"f_mesh1", 8, nullptr, nullptr},
    {"f_mitre", 4, mitre, mitreFormula},
    {"f_nodal_cubic", 4, nodalCubic, nodalCubicFormula},
    {"f_odd", 4, odd, oddFormula},
    {"f_ovals_of_cassini", 7, ovalsOfCassini, ovalsOfCassiniFormula},
    {"f_paraboloid", 4, paraboloid, LUCENT_CLAMP_TEXT("($3 * -($0*$0 - $1 + $2*$2))")},
    {"f_parabolic_torus", 6, parabolicTorus, parabolicTorusFormula},
    {"f_ph", 3, phi, "atan2(sqrt($0*$0 + $2*$2), $1)"},
    {"f_pillow", 4, pillow, pillowFormula},
    {"f_piriform", 4, nullptr, nullptr},
    {"f_piriform_2d", 10, nullptr, nullptr},
    {"f_poly4", 8, nullptr, nullptr},
    {"f_polytubes", 9, nullptr, nullptr},
    {"f_quantum", 4, nullptr, nullptr},
    {"f_quartic_paraboloid", 4, quarticParaboloid, quarticParaboloidFormula},
    {"f_quartic_saddle", 4, quarticSaddle, quarticSaddleFormula},
    {"f_quartic_cylinder", 6, quarticCylinder, quarticCylinderFormula},
    {"f_r", 3, radius, "sqrt($0*$0 + $1*$1 + $2*$2)"},
    {"f_ridge", 9, nullptr, nullptr},
    {"f_ridged_mf", 9, nullptr, nullptr},
    {"f_rounded_box", 7, roundedBox,
     "(-$3 + sqrt(" LUCENT_BOX_AXIS("$0", "$4") "*" LUCENT_BOX_AXIS(
         "$0",
         "$4") " + " LUCENT_BOX_AXIS("$1",
                                     "$5") "*" LUCENT_BOX_AXIS("$1",
                                                               "$5") " + " LUCENT_BOX_AXIS("$2",
                                                                                           "$6") "*" LUCENT_BOX_AXIS("$2",
                                                                                                                     "$6") ") - 1e-06)"},
    {"f_sphere", 4, sphere, "(-$3 + sqrt($0*$0 + $1*$1 + $2*$2))"},
    {"f_spikes", 8, nullptr, nullptr},
    {"f_spikes_2d", 7, nullptr, nullptr},
    {"f_spiral", 9, nullptr, nullptr},
    {"f_steiners_roman", 4, steinersRoman, steinersRomanFormula},
    {"f_strophoid", 7, nullptr, nullptr},
    {"f_strophoid_2d", 10, nullptr, nullptr},
    {"f_superellipsoid", 5, superellipsoid,
     "(1 - pow(pow(pow(abs($0), 2/$3) + pow(abs($1), 2/$3), $3*(1/$4)) + pow(abs($2), 2*(1/$4)), "
     "$4*0.5))"},
    {"f_th", 3, theta, "atan2($0, $2)"},
    {"f_torus", 5, torus, "(-$4 + sqrt((sqrt($0*$0 + $2*$2) - $3)^2 + $1*$1))"},
    {"f_torus2", 6, torus2,
     LUCENT_CLAMP_TEXT("($3 * -(" LUCENT_X2 "*" LUCENT_X2 " + " LUCENT_Y2 "*" LUCENT_Y2
                       " + " LUCENT_Z2 "*" LUCENT_Z2 " + 2*" LUCENT_X2 "*" LUCENT_Y2
                       " + 2*" LUCENT_X2 "*" LUCENT_Z2 " + 2*" LUCENT_Y2 "*" LUCENT_Z2
                       " - 2*($4*$4 + $5*$5)*" LUCENT_X2 " + 2*($4*$4 - $5*$5)*" LUCENT_Y2
                       " - 2*($4*$4 + $5*$5)*" LUCENT_Z2 " + ($4*$4 - $5*$5)*($4*$4 - $5*$5)))")},
    {"f_torus_gumdrop", 4, torusGumdrop,
     LUCENT_CLAMP_TEXT("($3 * -(4*(" LUCENT_X2 "*" LUCENT_X2 " + (" LUCENT_Y2 " + " LUCENT_Z2
                       ")*(" LUCENT_Y2 " + " LUCENT_Z2 ")) + 17*" LUCENT_X2 "*(" LUCENT_Y2
                       " + " LUCENT_Z2 ") - 20*(" LUCENT_X2 " + " LUCENT_Y2 " + " LUCENT_Z2
                       ") + 17))")},
    {"f_umbrella", 4, umbrella, LUCENT_CLAMP_TEXT("($3 * -($0*$0 - $1*$2*$2))")},
    {"f_witch_of_agnesi", 5, witchOfAgnesi,
     LUCENT_CLAMP_TEXT("($3 * -($4*($1 - 1) + ($0*$0 + $2*$2)*$1))")},
    {"f_witch_of_agnesi_2d", 9, nullptr, nullptr},
    {"f_noise3d", 3, nullptr, nullptr},
    {"f_pattern", 3, nullptr, nullptr},
    {"f_noise_generator", 4, nullptr, nullptr},
};

bool usesNoise(int n) { return n == 29 || n == 58 || n == 59 || n == 76 || n == 78; }

}  // namespace

const InternalFunction* internalFunction(int n) {
  constexpr int count = static_cast<int>(sizeof kInternal / sizeof kInternal[0]);
  return n >= 0 && n < count ? &kInternal[n] : nullptr;
}

std::string internalRefusal(int n) {
  const InternalFunction* f = internalFunction(n);
  const std::string name =
      "'" + std::string(f ? f->name : "?") + "' (internal(" + std::to_string(n) + "))";
  if (usesNoise(n))
    return name +
           " is a noise function Lucent does not evaluate (of POV-Ray's noise functions it "
           "evaluates f_noise3d, as the bozo pattern: docs/povray-import.md)";
  if (n == 77) return name + " is a pattern's function, which Lucent does not evaluate";
  return name +
         " is not evaluated by Lucent's POV-Ray reader (only the closed forms listed in "
         "docs/povray-import.md are)";
}

const InternalFunction* internalFunctionNamed(std::string_view name) {
  for (int n = 0; const InternalFunction* f = internalFunction(n); ++n)
    if (name == f->name) return f;
  return nullptr;
}

const std::vector<const InternalFunction*>& evaluatedInternalFunctions() {
  static const std::vector<const InternalFunction*> all = [] {
    std::vector<const InternalFunction*> v;
    for (int n = 0; const InternalFunction* f = internalFunction(n); ++n)
      if (f->evaluate && f->text) v.push_back(f);
    return v;
  }();
  return all;
}

std::string internalFormula(const InternalFunction& f, const std::vector<std::string>& args) {
  std::string out;
  for (const char* c = f.text; *c;) {
    if (*c == '$' && c[1] >= '0' && c[1] <= '9') {
      out += args[static_cast<size_t>(c[1] - '0')];
      c += 2;
      continue;
    }
    if (!std::isalpha(static_cast<unsigned char>(*c))) {
      out += *c++;
      continue;
    }
    const char* end = c;
    while (std::isalnum(static_cast<unsigned char>(*end)) || *end == '_') ++end;
    const std::string word(c, end);
    c = end;
    if (word.size() <= 2 && (word[0] == 'X' || word[0] == 'Y' || word[0] == 'Z')) {
      const std::string& a = args[static_cast<size_t>(word[0] - 'X')];
      out += word.size() == 1 ? a : "(" + a + "*" + a + ")";
    } else if (word.size() == 2 && word[0] == 'P' &&
               std::isdigit(static_cast<unsigned char>(word[1]))) {
      out += args[static_cast<size_t>(3 + word[1] - '0')];
    } else {
      out += word;
    }
  }
  return out;
}

}  // namespace lucent
