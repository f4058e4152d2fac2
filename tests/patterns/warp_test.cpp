// The warps of a pattern's placement (render/patterns/warp.h) against POV-Ray 3.7's formulas
// (warps.cpp: Warp_EPoint) worked out by hand at chosen points.
#include "render/patterns/warp.h"
#include "primitives/noise.h"
#include "render/patterns/normal_perturbation.h"
#include "render/patterns/pattern_point.h"
#include "scenegraph/turbulence.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <random>

using namespace lucent;

namespace {

void checkPoint(const Vec3& got, const Vec3& want, double tolerance = 1e-14) {
  INFO("got " << got.x << " " << got.y << " " << got.z << ", want " << want.x << " " << want.y
              << " " << want.z);
  CHECK(std::fabs(got.x - want.x) <= tolerance);
  CHECK(std::fabs(got.y - want.y) <= tolerance);
  CHECK(std::fabs(got.z - want.z) <= tolerance);
}

Vec3 warped(const PatternWarp& w, const Vec3& p) { return applyWarps({w}, p); }

RepeatWarp repeatX(double width, const Vec3& offset, bool flipX, bool flipY) {
  RepeatWarp r;
  r.axis = 0;
  r.width = width;
  r.offset = offset;
  r.flip[0] = flipX;
  r.flip[1] = flipY;
  return r;
}

}  // namespace

TEST_CASE("repeat warp: slabs along the axis, odd ones flipped, each offset", "[pattern][warp]") {
  const RepeatWarp r = repeatX(2.0, Vec3(0.0, 0.25, 0.0), false, true);
  // Slab 2 (even): x - 4, y + 2·0.25.
  checkPoint(warped(r, Vec3(5.5, 0.3, 0.7)), Vec3(1.5, 0.8, 0.7));
  // Slab 1 (odd): x - 2, y flipped, then + 0.25.
  checkPoint(warped(r, Vec3(3.5, 0.3, 0.7)), Vec3(1.5, -0.05, 0.7));
  // Flipped along its own axis: width + (−(x − slab·width)).
  const RepeatWarp f = repeatX(2.0, Vec3(0.0), true, false);
  checkPoint(warped(f, Vec3(3.5, 0.3, 0.7)), Vec3(0.5, 0.3, 0.7));
  // Slab −1 is odd too.
  checkPoint(warped(f, Vec3(-0.5, 0.3, 0.7)), Vec3(0.5, 0.3, 0.7));
  // The first slab is left as it is.
  checkPoint(warped(f, Vec3(1.25, -4.0, 9.0)), Vec3(1.25, -4.0, 9.0));
}

TEST_CASE("black hole warp: inside the radius the point moves by min(1, s·((r−d)/r)^falloff)",
          "[pattern][warp]") {
  BlackHoleWarp h;
  h.radius = 1.0;
  h.strength = 0.5;
  h.falloff = 2.0;
  // d = 0.5: 0.5·0.5² = 0.125 of the offset, away from the centre.
  checkPoint(warped(h, Vec3(0.5, 0.0, 0.0)), Vec3(0.5625, 0.0, 0.0));
  h.inverse = true;
  checkPoint(warped(h, Vec3(0.5, 0.0, 0.0)), Vec3(0.4375, 0.0, 0.0));
  checkPoint(warped(h, Vec3(2.0, 0.0, 0.0)), Vec3(2.0, 0.0, 0.0));  // outside
  h.inverse = false;
  h.strength = 10.0;  // 2.5, clipped to 1: the offset doubled
  checkPoint(warped(h, Vec3(0.0, 0.5, 0.0)), Vec3(0.0, 1.0, 0.0));
}

TEST_CASE("black hole warp: repeated holes, each moved by POV-Ray's random table",
          "[pattern][warp]") {
  BlackHoleWarp h;
  h.center = Vec3(0.5, 0.5, 0.0);
  h.radius = 0.5;
  h.repeat = Vec3(2.0, 2.0, 0.0);
  // Cell (2, 1, 0): centre (4.5, 2.5, 0); d = 0.1, (0.4/0.5)² = 0.64.
  checkPoint(warped(h, Vec3(4.6, 2.5, 0.0)), Vec3(4.6 + 0.064, 2.5, 0.0), 1e-13);
  // With turbulence the centre moves by WarpRands(Hash3d(cell) + axis)·turbulence: the
  // outputs of a default-seeded 32-bit Mersenne twister over 2^32.
  h.turbulence = Vec3(0.2, 0.1, 0.0);
  std::mt19937 twister;
  std::vector<double> rands(4100);
  for (double& v : rands) v = twister() / 4294967296.0;
  const int seed = latticeHash(2, 1, 0);
  const Vec3 c(4.5 + rands[seed] * 0.2, 2.5 + rands[seed + 1] * 0.1, 0.0);
  const Vec3 p(4.55, 2.45, 0.0);
  const Vec3 delta = p - c;
  const double d = std::sqrt(glm::dot(delta, delta));
  REQUIRE(d < 0.5);
  const double s = std::pow((0.5 - d) / 0.5, 2.0);
  checkPoint(warped(h, p), p + s * delta, 1e-13);
}

TEST_CASE("black hole parameters are settled as POV-Ray's parser settles them", "[pattern][warp]") {
  BlackHoleWarp h;
  h.center = Vec3(0.0, 0.0, 0.0);
  h.radius = 0.5;
  h.repeat = Vec3(0.75, 1.25, 0.0);
  h.turbulence = Vec3(0.5, 0.0, 0.0);
  bool changed[3];
  settleBlackHole(h, changed);
  CHECK(h.center == Vec3(0.5, 0.5, 0.0));   // raised to the radius on the repeated axes
  CHECK(h.repeat == Vec3(1.5, 1.25, 0.0));  // x raised to 0.5 + 0.5 + 0.5
  CHECK(changed[0]);
  CHECK_FALSE(changed[1]);
  CHECK_FALSE(changed[2]);
}

TEST_CASE("cylindrical warp: the angle around y over 2π, y, and the distance from the axis",
          "[pattern][warp]") {
  MappingWarp m;
  m.kind = MappingWarpKind::cylindrical;
  checkPoint(warped(m, Vec3(0.0, 3.0, 2.0)), Vec3(0.25, 3.0, 2.0));
  checkPoint(warped(m, Vec3(0.0, 3.0, -2.0)), Vec3(0.75, 3.0, 2.0));
  checkPoint(warped(m, Vec3(-1.0, 3.0, 0.0)), Vec3(0.5, 3.0, 1.0));
  checkPoint(warped(m, Vec3(0.0, 3.0, 0.0)), Vec3(0.0, 3.0, 0.0));  // the axis: unchanged
  m.distExp = 1.0;
  checkPoint(warped(m, Vec3(0.0, 3.0, 2.0)), Vec3(0.5, 3.0, 2.0));
  m.distExp = 2.0;
  checkPoint(warped(m, Vec3(0.0, 3.0, 2.0)), Vec3(1.0, 3.0, 2.0));
  // Orientation y: (x, y, z) of the flat coordinates become (x, −z, y).
  m.distExp = 0.0;
  m.orientation = Vec3(0.0, 1.0, 0.0);
  checkPoint(warped(m, Vec3(0.0, 3.0, 2.0)), Vec3(0.25, -2.0, 3.0));
}

TEST_CASE("spherical warp: longitude and latitude in [0, 1] and the distance", "[pattern][warp]") {
  MappingWarp m;
  m.kind = MappingWarpKind::spherical;
  checkPoint(warped(m, Vec3(0.0, 0.0, 2.0)), Vec3(0.25, 0.5, 2.0));
  // 45° up over +x: latitude 0.5 + (π/4)/π.
  checkPoint(warped(m, Vec3(1.0, 1.0, 0.0)), Vec3(0.0, 0.75, std::sqrt(2.0)));
  m.distExp = 1.0;
  checkPoint(warped(m, Vec3(0.0, 0.0, 2.0)), Vec3(0.5, 1.0, 2.0));
  // Orientation x: (x, y, z) become (z, y, −x).
  m.distExp = 0.0;
  m.orientation = Vec3(1.0, 0.0, 0.0);
  checkPoint(warped(m, Vec3(0.0, 0.0, 2.0)), Vec3(2.0, 0.5, -0.25));
}

TEST_CASE("toroidal warp: the angles around the ring and around the tube", "[pattern][warp]") {
  MappingWarp m;
  m.kind = MappingWarpKind::toroidal;
  m.majorRadius = 1.0;
  // (2, 0.5, 0): around the ring 0; in the tube's plane (1, 0.5) from its centre, above.
  const double tube = std::sqrt(1.25);
  const double phi = (2.0 * kPi - std::acos(-1.0 / tube)) / (2.0 * kPi);
  checkPoint(warped(m, Vec3(2.0, 0.5, 0.0)), Vec3(0.0, phi, tube));
  // Below the ring's plane the tube angle is not reflected; a quarter round the ring.
  const double below = std::acos(-1.0 / tube) / (2.0 * kPi);
  checkPoint(warped(m, Vec3(0.0, -0.5, 2.0)), Vec3(0.25, below, tube));
  m.majorRadius = 2.0;
  checkPoint(warped(m, Vec3(0.0, 1.0, -2.0)), Vec3(0.75, 0.75, 1.0));
}

TEST_CASE("planar warp: x and y kept, z the distance", "[pattern][warp]") {
  MappingWarp m;
  m.kind = MappingWarpKind::planar;
  m.distance = 0.5;
  checkPoint(warped(m, Vec3(1.0, 2.0, 3.0)), Vec3(1.0, 2.0, 0.5));
  m.orientation = Vec3(1.0, 0.0, 0.0);
  checkPoint(warped(m, Vec3(1.0, 2.0, 3.0)), Vec3(0.5, 2.0, -1.0));
}

TEST_CASE("cubic warp: each face of the cube onto its square of the unfolded cube",
          "[pattern][warp]") {
  MappingWarp m;
  m.kind = MappingWarpKind::cubic;
  // +x face: u = 0.75 − (z/x + 1)/8, v = 1/3 + (y/x + 1)/6.
  checkPoint(warped(m, Vec3(2.0, 0.5, -1.0)), Vec3(0.75 - 0.5 / 8.0, 1.0 / 3.0 + 1.25 / 6.0, 2.0));
  // −y face: u = 0.25 + (x/|y| + 1)/8, v = (z/|y| + 1)/6.
  checkPoint(warped(m, Vec3(0.5, -2.0, 1.0)), Vec3(0.25 + 1.25 / 8.0, 1.5 / 6.0, 2.0));
  // −z face: u = 1 − (x/|z| + 1)/8.
  checkPoint(warped(m, Vec3(0.0, 0.0, -4.0)), Vec3(1.0 - 1.0 / 8.0, 1.0 / 3.0 + 1.0 / 6.0, 4.0));
}

TEST_CASE("turbulence warp displaces as the classic turbulence does, on wood too",
          "[pattern][warp]") {
  TurbulenceWarp t;
  t.strength = Vec3(0.4, 0.2, 0.0);
  t.octaves = 3;
  t.lambda = 2.5;
  PatternPlacement classic;
  classic.turbulence = t.strength;
  classic.octaves = 3;
  classic.lambda = 2.5;
  const Vec3 p(0.3, -1.7, 2.2);
  const Vec3 d = dturbulence(p, classic);
  checkPoint(warped(t, p), Vec3(p.x + 0.4 * d.x, p.y + 0.2 * d.y, p.z), 0.0);
  // A turbulence step moves wood's point (POV-Ray's extra turbulence), the classic one not.
  PatternPlacement place;
  place.warps.push_back(t);
  checkPoint(warpPoint(place, p, false), warped(t, p), 0.0);
  checkPoint(warpPoint(classic, p, false), p, 0.0);
}

TEST_CASE(
    "warps apply last written first, after the placement's transform and before its "
    "turbulence",
    "[pattern][warp]") {
  // POV-Ray: pigment { P translate x warp { repeat x*2 } scale 2 }: the point is halved,
  // repeated, then moved back by x.
  PatternPlacement place;
  place.patternFromObject = glm::scale(Mat4(1.0), Vec3(0.5));
  place.warps.push_back(TransformWarp{glm::translate(Mat4(1.0), Vec3(-1.0, 0.0, 0.0))});
  place.warps.push_back(repeatX(2.0, Vec3(0.0), false, false));
  // (7, 1, 1) → (3.5, 0.5, 0.5) → slab 1: (1.5, 0.5, 0.5) → (0.5, 0.5, 0.5).
  checkPoint(warpPoint(place, Vec3(7.0, 1.0, 1.0)), Vec3(0.5, 0.5, 0.5));
  // The transforms alone carry normals: the translation and scale, not the repeat.
  checkPoint(Vec3(linearPatternFromObject(place) * Vec4(7.0, 1.0, 1.0, 1.0)), Vec3(2.5, 0.5, 0.5));
}

TEST_CASE("a normal carried through transform steps equals one through the same transform",
          "[pattern][warp]") {
  NormalSpec a;
  a.pattern.type = PatternType::bumps;
  a.depth = 0.8;
  const Mat4 m = glm::rotate(glm::scale(Mat4(1.0), Vec3(0.5, 2.0, 1.0)), 0.7, Vec3(1.0, 1.0, 0.0));
  a.pattern.placement.patternFromObject = m;
  NormalSpec b = a;
  b.pattern.placement.patternFromObject = Mat4(1.0);
  b.pattern.placement.warps.push_back(TransformWarp{m});
  for (const Vec3& p : {Vec3(0.3, 0.2, 0.1), Vec3(-2.0, 1.5, 4.0)})
    checkPoint(perturbNormal(b, p, Vec3(0.0, 0.0, 1.0)), perturbNormal(a, p, Vec3(0.0, 0.0, 1.0)),
               1e-12);
}
