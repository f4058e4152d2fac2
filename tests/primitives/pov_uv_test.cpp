// POV-Ray's (u, v) of each shape that has them (Shape::povUV, what mapping="uv" reads),
// against POV-Ray 3.7's formulas evaluated here on their own: each point carried into
// POV-Ray's space (z negated, as the importer places shapes) and its values worked out by
// hand from the shape's UVCoord, or with atan2 where POV-Ray takes an acos.
#include "primitives/bicubic_patch.h"
#include "primitives/box.h"
#include "primitives/cylinder.h"
#include "primitives/lathe.h"
#include "primitives/sor.h"
#include "primitives/sphere.h"
#include "primitives/torus.h"
#include "primitives/triangle_mesh.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace lucent;
using Catch::Matchers::WithinAbs;

namespace {

// POV-Ray's (u, v) where the ray first meets the shape.
Vec2 povUVAlong(const Shape& shape, const Ray& ray) {
  Hit h;
  REQUIRE(shape.intersect(ray, h));
  const SurfaceInfo s = shape.surface(ray, h);
  Vec2 uv(-1.0);
  REQUIRE(shape.povUV(s, h, uv));
  return uv;
}

// The ray towards the point p from `from` (the first hit must be p).
Ray towards(const Vec3& from, const Vec3& p) { return Ray(from, p - from); }

void checkUV(const Vec2& uv, double u, double v, double eps = 1e-12) {
  CHECK_THAT(uv.x, WithinAbs(u, eps));
  CHECK_THAT(uv.y, WithinAbs(v, eps));
}

}  // namespace

TEST_CASE("pov uv: a sphere's longitude from +x towards POV-Ray's +z and its latitude",
          "[primitives][uv-mapping]") {
  const Vec3 c(0.5, -0.25, 1.0);
  const Sphere sphere(c, 1.5);
  auto at = [&](const Vec3& dir) {
    const Vec3 n = glm::normalize(dir);
    return povUVAlong(sphere, Ray(c + 4.0 * n, -n));
  };
  // By hand: +x is u 0; Lucent's -z is POV-Ray's +z, a quarter turn; Lucent's +z three
  // quarters; -x a half. The equator is v 0.5, 45 degrees up 0.75.
  checkUV(at(Vec3(1, 0, 0)), 0.0, 0.5);
  checkUV(at(Vec3(0, 0, -1)), 0.25, 0.5);
  checkUV(at(Vec3(-1, 0, 0)), 0.5, 0.5);
  checkUV(at(Vec3(0, 0, 1)), 0.75, 0.5);
  checkUV(at(Vec3(1, 1, 0)), 0.0, 0.75);
  checkUV(at(Vec3(0, -1, -1)), 0.25, 0.25);
  // Seeded directions against atan2 in POV-Ray's space and 1 - the polar angle over pi.
  std::mt19937 rng(40);
  std::uniform_real_distribution<double> any(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const Vec3 n = glm::normalize(Vec3(any(rng), any(rng), any(rng)));
    const double zPov = -n.z;
    double turns = std::atan2(zPov, n.x) / (2.0 * M_PI);
    if (turns < 0.0) turns += 1.0;
    INFO("direction " << n.x << " " << n.y << " " << n.z);
    checkUV(at(n), turns, 1.0 - std::acos(n.y) / M_PI, 1e-9);
  }
}

TEST_CASE("pov uv: a box's faces on POV-Ray's cube map", "[primitives][uv-mapping]") {
  // Lucent's box (-1, 0, -3)..(1, 2, 1) is POV-Ray's <-1, 0, -1>..<1, 2, 3>. Each point's
  // fractions across POV-Ray's box are 0.75 along the face's first axis and 0.25 or 0.75
  // along the other; the cube map puts the faces at u = 0, 1/4, 1/2, 3/4 (min x, max z, max
  // x, min z) with v from 1/3, the min-y face below max z and max y above it.
  const Box box(Vec3(-1, 0, -3), Vec3(1, 2, 1));
  // Lucent's +z face is POV-Ray's min z: u = 1 - Px/4, v = 1/3 + Py/3.
  checkUV(povUVAlong(box, towards(Vec3(0.5, 1.5, 5), Vec3(0.5, 1.5, 1))), 1.0 - 0.75 / 4,
          1.0 / 3 + 0.75 / 3);
  // Lucent's -z face is POV-Ray's max z: u = 1/4 + Px/4.
  checkUV(povUVAlong(box, towards(Vec3(0.5, 1.5, -8), Vec3(0.5, 1.5, -3))), 0.25 + 0.75 / 4,
          1.0 / 3 + 0.75 / 3);
  // +x at POV-Ray's z = 2 (Pz 0.75), y = 0.5 (Py 0.25): u = 3/4 - Pz/4; -x: u = Pz/4.
  checkUV(povUVAlong(box, towards(Vec3(5, 0.5, -2), Vec3(1, 0.5, -2))), 0.75 - 0.75 / 4,
          1.0 / 3 + 0.25 / 3);
  checkUV(povUVAlong(box, towards(Vec3(-5, 0.5, -2), Vec3(-1, 0.5, -2))), 0.75 / 4,
          1.0 / 3 + 0.25 / 3);
  // +y: v = 1 - Pz/3; -y: v = Pz/3; both u = 1/4 + Px/4.
  checkUV(povUVAlong(box, towards(Vec3(0.5, 5, -2), Vec3(0.5, 2, -2))), 0.25 + 0.75 / 4,
          1.0 - 0.75 / 3);
  checkUV(povUVAlong(box, towards(Vec3(0.5, -5, -2), Vec3(0.5, 0, -2))), 0.25 + 0.75 / 4, 0.75 / 3);
  // The map is continuous where POV-Ray's picture joins faces: the edge of min x and max z
  // (Lucent's x = -1, z = -3) is u = 1/4 from both.
  checkUV(povUVAlong(box, towards(Vec3(-5, 1, -3 + 1e-9), Vec3(-1, 1, -3 + 1e-9))), 0.25, 0.5,
          1e-9);
  checkUV(povUVAlong(box, towards(Vec3(-1 + 1e-9, 1, -8), Vec3(-1 + 1e-9, 1, -3))), 0.25, 0.5,
          1e-9);
}

TEST_CASE("pov uv: a torus's turn about y and round its tube", "[primitives][uv-mapping]") {
  const Torus torus(2.0, 0.5);
  // u = 1 - (atan2(z, x) + pi)/2pi in POV-Ray's space: +x 0.5, Lucent's -z (POV-Ray's +z)
  // 0.25, Lucent's +z 0.75; v = (atan2(y, rho - R) + pi)/2pi: the outer equator 0.5, the
  // tube's top 0.75, its bottom 0.25.
  checkUV(povUVAlong(torus, towards(Vec3(5, 0, 0), Vec3(2.5, 0, 0))), 0.5, 0.5);
  checkUV(povUVAlong(torus, towards(Vec3(0, 0, -5), Vec3(0, 0, -2.5))), 0.25, 0.5);
  checkUV(povUVAlong(torus, towards(Vec3(0, 0, 5), Vec3(0, 0, 2.5))), 0.75, 0.5);
  checkUV(povUVAlong(torus, towards(Vec3(2, 5, 0), Vec3(2, 0.5, 0))), 0.5, 0.75);
  checkUV(povUVAlong(torus, towards(Vec3(2, -5, 0), Vec3(2, -0.5, 0))), 0.5, 0.25);
  // 30 degrees round the tube above the outer equator, at 60 degrees about y towards
  // POV-Ray's +z: atan2 gives u = 1 - (pi/3 + pi)/2pi = 1/3, v = (pi/6 + pi)/2pi = 7/12.
  const double a = M_PI / 3, b = M_PI / 6;
  const Vec3 p((2 + 0.5 * std::cos(b)) * std::cos(a), 0.5 * std::sin(b),
               -(2 + 0.5 * std::cos(b)) * std::sin(a));
  checkUV(povUVAlong(torus, Ray(p + 3.0 * Vec3(std::cos(a), 0, -std::sin(a)),
                                -Vec3(std::cos(a), 0, -std::sin(a)))),
          1.0 / 3, 7.0 / 12, 1e-6);
}

TEST_CASE("pov uv: a lathe's v counts POV-Ray's segments, degenerate ones too",
          "[primitives][uv-mapping]") {
  // Two linear segments (1,0)-(1,1)-(2,2): v = (s + segment)/2. At height 1.5 on the second,
  // s = 0.5, radius 1.5; Lucent's -z is POV-Ray's +z, u 0.25.
  const Lathe lathe(LatheSpline::Linear, {{1, 0}, {1, 1}, {2, 2}});
  checkUV(povUVAlong(lathe, towards(Vec3(0, 1.5, -5), Vec3(0, 1.5, -1.5))), 0.25, 0.75);
  checkUV(povUVAlong(lathe, towards(Vec3(5, 0.25, 0), Vec3(1, 0.25, 0))), 0.0, 0.125);
  // A repeated first point: POV-Ray's first segment has no surface but is counted.
  const Lathe repeated(LatheSpline::Linear, {{1, 0}, {1, 0}, {1, 1}});
  checkUV(povUVAlong(repeated, towards(Vec3(5, 0.25, 0), Vec3(1, 0.25, 0))), 0.0, 0.625);
  checkUV(povUVAlong(repeated, towards(Vec3(0, 0.5, 5), Vec3(0, 0.5, 1))), 0.75, 0.75);
}

TEST_CASE("pov uv: a sor's u turns towards POV-Ray's +z, its v is its own",
          "[primitives][uv-mapping]") {
  const Sor sor({{1, -1}, {1, 0}, {1, 1}, {1, 2}}, false);
  // One segment from y 0 to 1: v the height's fraction; Lucent's +z is POV-Ray's -z, u 0.75.
  checkUV(povUVAlong(sor, towards(Vec3(0, 0.25, 5), Vec3(0, 0.25, 1))), 0.75, 0.25);
  checkUV(povUVAlong(sor, towards(Vec3(0, 0.5, -5), Vec3(0, 0.5, -1))), 0.25, 0.5);
  checkUV(povUVAlong(sor, towards(Vec3(5, 0.75, 0), Vec3(1, 0.75, 0))), 0.0, 0.75);
  // The top cap: 2 at the centre, 1 at the rim; halfway, 1.5.
  checkUV(povUVAlong(sor, towards(Vec3(-0.5, 5, 0), Vec3(-0.5, 1, 0))), 0.5, 1.5);
}

TEST_CASE("pov uv: a mesh's uv_vectors, (0, 0) without them, and a patch's own (u, v)",
          "[primitives][uv-mapping]") {
  auto data = std::make_shared<MeshData>();
  data->positions = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  data->triangles = {{0, 1, 2}};
  data->uvs = {{0.1, 0.2}, {0.9, 0.2}, {0.1, 0.6}};
  const TriangleMesh withUVs(data, false);
  // At (1, 2): barycentric weights 0.25 on the second corner, 0.5 on the third.
  checkUV(povUVAlong(withUVs, towards(Vec3(1, 2, 5), Vec3(1, 2, 0))), 0.1 + 0.25 * 0.8,
          0.2 + 0.5 * 0.4);
  auto bare = std::make_shared<MeshData>(*data);
  bare->uvs.clear();
  checkUV(povUVAlong(TriangleMesh(bare, false), towards(Vec3(1, 2, 5), Vec3(1, 2, 0))), 0.0, 0.0);
  // A flat patch over [0, 3] x [0, 3] in y = 0, P[i][j] = (i, 0, j): POV-Ray's (u, v) at the
  // point (x, z) is (z/3, x/3), exact on its flat triangles.
  PatchPoints p{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p[static_cast<size_t>(4 * i + j)] = Vec3(i, 0, j);
  const BicubicPatch patch(p, 0.0, 2, 2);
  checkUV(povUVAlong(patch, towards(Vec3(1.2, 5, 0.6), Vec3(1.2, 0, 0.6))), 0.2, 0.4);
  // With uv_vectors the corners' (u, v) are blended bilinearly at the hit's own (0.2, 0.4):
  // along the first coordinate (0.26, 0.18) and (0.14, 0.64), then 0.4 of the way between.
  // The corners are twisted (no affine map takes the square to them), so blending the
  // triangle's vertices instead would give another value.
  const PatchUvCorners corners = {Vec2(0.1, 0.2), Vec2(0.9, 0.1), Vec2(0.7, 0.8), Vec2(0.0, 0.6)};
  const BicubicPatch mapped(p, 0.0, 2, 2, Mat4(1.0), corners);
  checkUV(povUVAlong(mapped, towards(Vec3(1.2, 5, 0.6), Vec3(1.2, 0, 0.6))), 0.212, 0.364);
  // At the middle, the mean of the four corners.
  checkUV(povUVAlong(mapped, towards(Vec3(1.5, 5, 1.5), Vec3(1.5, 0, 1.5))), 0.425, 0.425);
}

TEST_CASE("pov uv: shapes POV-Ray gives no (u, v) have none", "[primitives][uv-mapping]") {
  const Cylinder cylinder(Vec3(0, -1, 0), Vec3(0, 1, 0), 1.0, false);
  const Ray ray(Vec3(5, 0, 0), Vec3(-1, 0, 0));
  Hit h;
  REQUIRE(cylinder.intersect(ray, h));
  Vec2 uv;
  CHECK_FALSE(cylinder.povUV(cylinder.surface(ray, h), h, uv));
}
