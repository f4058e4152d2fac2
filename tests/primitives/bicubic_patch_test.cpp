#include "primitives/bicubic_patch.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace lucent;
using Catch::Matchers::WithinAbs;

namespace {

// S(u, v) = (u, u², v): the Bernstein coefficients of u are i/3, of u² 0, 0, 1/3, 1.
PatchPoints parabolicSheet() {
  const double yOf[4] = {0.0, 0.0, 1.0 / 3.0, 1.0};
  PatchPoints p{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p[static_cast<size_t>(4 * i + j)] = Vec3(i / 3.0, yOf[i], j / 3.0);
  return p;
}

// A flat patch over the square [0, 3] x [0, 3] at y = 0 (P[i][j] = (i, 0, j)).
PatchPoints flatSquare() {
  PatchPoints p{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p[static_cast<size_t>(4 * i + j)] = Vec3(i, 0, j);
  return p;
}

}  // namespace

TEST_CASE("bicubic patch: the exact surface and its normal", "[primitives][bicubic]") {
  const PatchPoints p = parabolicSheet();
  for (double u : {0.0, 0.3, 0.5, 1.0})
    for (double v : {0.0, 0.7}) {
      const Vec3 s = bezierPatchPoint(p, u, v);
      CHECK_THAT(s.x, WithinAbs(u, 1e-15));
      CHECK_THAT(s.y, WithinAbs(u * u, 1e-15));
      CHECK_THAT(s.z, WithinAbs(v, 1e-15));
      // Su × Sv = (1, 2u, 0) × (0, 0, 1) = (2u, −1, 0).
      const Vec3 n = bezierPatchNormal(p, u, v);
      const Vec3 want = glm::normalize(Vec3(2 * u, -1, 0));
      CHECK_THAT(glm::length(n - want), WithinAbs(0.0, 1e-15));
    }
  // Where Su × Sv vanishes (a row of equal points collapses Sv at u = 0): POV-Ray's <1, 0, 0>.
  PatchPoints cone = p;
  for (int j = 0; j < 4; ++j) cone[static_cast<size_t>(j)] = Vec3(0.0);
  CHECK(bezierPatchNormal(cone, 0.0, 0.5) == Vec3(1, 0, 0));
}

TEST_CASE("bicubic patch: the steps and the flatness decide the parts", "[primitives][bicubic]") {
  const PatchPoints sheet = parabolicSheet();
  // Flatness 0: 2^u x 2^v parts of two triangles each.
  CHECK(bicubicPatchMesh(sheet, 0.0, 0, 0)->triangles.size() == 2);
  CHECK(bicubicPatchMesh(sheet, 0.0, 3, 2)->triangles.size() == 2 * 8 * 4);
  CHECK(bicubicPatchMesh(sheet, 0.0, 1, 4)->triangles.size() == 2 * 2 * 16);
  // A flat patch stops at once when flatness is above 0; not at flatness 0.
  CHECK(bicubicPatchMesh(flatSquare(), 1e-9, 5, 5)->triangles.size() == 2);
  CHECK(bicubicPatchMesh(flatSquare(), 0.0, 2, 2)->triangles.size() == 32);
  // The sheet's control points lie up to 1/3 − (chord) off its corners' plane: the measure.
  CHECK_THAT(
      patchFlatness(sheet),
      WithinAbs(std::abs(glm::dot(glm::normalize(Vec3(-1, 1, 0)), Vec3(2.0 / 3, 1.0 / 3, 0))),
                1e-15));
  // A large flatness keeps the whole patch; a middling one stops where the parts are flat.
  CHECK(bicubicPatchMesh(sheet, 1.0, 4, 4)->triangles.size() == 2);
  const size_t some = bicubicPatchMesh(sheet, 0.01, 4, 4)->triangles.size();
  CHECK(some > 2);
  CHECK(some < 2 * 16 * 16);
  // Every vertex is the exact surface at its (u, v); the texture (u, v) is the patch's (v, u).
  const auto mesh = bicubicPatchMesh(sheet, 0.0, 2, 1);
  REQUIRE(mesh->uvs.size() == mesh->positions.size());
  for (size_t k = 0; k < mesh->positions.size(); ++k) {
    const double u = mesh->uvs[k].y, v = mesh->uvs[k].x;
    CHECK(glm::length(mesh->positions[k] - bezierPatchPoint(sheet, u, v)) < 1e-15);
    CHECK(mesh->normals[k] == bezierPatchNormal(sheet, u, v));
  }
  CHECK_THROWS_AS(BicubicPatch(sheet, 0.0, 11, 0), std::invalid_argument);
  CHECK_THROWS_AS(BicubicPatch(sheet, 0.0, 0, -1), std::invalid_argument);
}

TEST_CASE("bicubic patch: hits on the chords of the subdivision", "[primitives][bicubic]") {
  // u-steps 2: the parts u in [0, 1/4], [1/4, 1/2], ... Each is flat (S is linear in v):
  // the chord from (u0, u0²) to (u1, u1²). A ray down y at x = 0.3, z = 0.4 meets the chord
  // of [1/4, 1/2] at y = 1/16 + (0.3 − 1/4)·3/4 = 0.1.
  const BicubicPatch patch(parabolicSheet(), 0.0, 2, 0);
  CHECK_FALSE(patch.isSolid());
  CHECK(patch.triangleCount() == 8);
  const Ray down(Vec3(0.3, 2, 0.4), Vec3(0, -1, 0));
  Hit h;
  REQUIRE(patch.intersect(down, h));
  CHECK(h.shape == &patch);
  CHECK_THAT(h.t, WithinAbs(2.0 - 0.1, 1e-14));
  const SurfaceInfo s = patch.surface(down, h);
  // The exact surface lies at 0.09 there: the chord is 0.01 above it.
  CHECK_THAT(s.p.y - 0.3 * 0.3, WithinAbs(0.01, 1e-14));
  // (u, v) interpolated: u = 0.3, v = 0.4, given as POV-Ray's (v, u).
  REQUIRE(s.hasUV);
  CHECK_THAT(s.uv.x, WithinAbs(0.4, 1e-14));
  CHECK_THAT(s.uv.y, WithinAbs(0.3, 1e-14));
  // The shading normal blends the exact normals at u = 1/4 and 1/2 by 0.8 and 0.2 (up to
  // the side it is turned to).
  const Vec3 blend = glm::normalize(0.8 * glm::normalize(Vec3(0.5, -1, 0)) +
                                    0.2 * glm::normalize(Vec3(1.0, -1, 0)));
  CHECK_THAT(std::abs(glm::dot(s.ns, blend)), WithinAbs(1.0, 1e-14));
  // Rays from below too; crossings list the one hit.
  REQUIRE(patch.intersect(Ray(Vec3(0.3, -1, 0.4), Vec3(0, 1, 0)), h));
  CHECK_THAT(h.t, WithinAbs(1.1, 1e-14));
  CrossingList cl;
  patch.crossings(down, cl);
  REQUIRE(cl.items.size() == 1);
  CHECK(cl.items[0].hit.shape == &patch);
  CHECK_FALSE(patch.intersect(Ray(Vec3(1.2, 2, 0.4), Vec3(0, -1, 0)), h));  // beside it
}

TEST_CASE("bicubic patch: flatness measured where the frame places the parts",
          "[primitives][bicubic]") {
  // A part of u-size h lies h²/3 (times the cosine of its slope) off its chord: flatness
  // 0.01 stops the sheet at depth 2 or 3 in its own space. Scaled by 4 the parts are 4
  // times less flat and cutting goes deeper, as POV-Ray cuts the scaled patch.
  const PatchPoints sheet = parabolicSheet();
  const size_t own = bicubicPatchMesh(sheet, 0.01, 6, 6)->triangles.size();
  const size_t scaled =
      bicubicPatchMesh(sheet, 0.01, 6, 6, glm::scale(Mat4(1.0), Vec3(4.0)))->triangles.size();
  PatchPoints moved = sheet;
  for (Vec3& q : moved) q *= 4.0;
  CHECK(scaled == bicubicPatchMesh(moved, 0.01, 6, 6)->triangles.size());
  CHECK(scaled > own);
  // A rotation and a translation change nothing.
  const Mat4 rigid =
      glm::translate(glm::rotate(Mat4(1.0), 0.7, glm::normalize(Vec3(1, 2, 3))), Vec3(5, -2, 1));
  CHECK(bicubicPatchMesh(sheet, 0.01, 6, 6, rigid)->triangles.size() == own);
}
