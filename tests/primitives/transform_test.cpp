// Transform: inverse and inverse-transpose computed once and correct; singular refused.
#include "primitives/transform.h"

#include <catch2/catch.hpp>
#include <glm/ext/matrix_transform.hpp>

using namespace lucent;

namespace {
bool near(const Vec3& a, const Vec3& b, double tol = 1e-12) {
  return glm::length(a - b) <= tol * std::max(1.0, glm::length(b));
}
}  // namespace

TEST_CASE("singular and non-affine matrices are refused", "[transform]") {
  CHECK_FALSE(Transform::fromMatrix(glm::scale(Mat4(1.0), Vec3(1, 0, 1))));
  Mat4 flat(1.0);
  flat[2] = flat[0];  // z axis equals x axis: rank 2
  CHECK_FALSE(Transform::fromMatrix(flat));
  Mat4 projective(1.0);
  projective[0][3] = 0.5;  // bottom row not (0 0 0 1)
  CHECK_FALSE(Transform::fromMatrix(projective));
  Mat4 nan(1.0);
  nan[3][0] = std::nan("");
  CHECK_FALSE(Transform::fromMatrix(nan));
  // A tiny but regular scale is fine: singularity is relative to the matrix's own size.
  CHECK(Transform::fromMatrix(glm::scale(Mat4(1.0), Vec3(1e-6))));
  // ... and to its axes: very different scales on orthogonal axes are no flattening
  // (stones.inc scales patterns by <0.01, 0.01, 1e5>), nearly parallel axes are.
  CHECK(Transform::fromMatrix(glm::scale(Mat4(1.0), Vec3(0.01, 0.01, 1e5))));
  Mat4 nearlyFlat(1.0);
  nearlyFlat[2] = nearlyFlat[0] + Vec4(0, 0, 1e-13, 0);  // z axis within 1e-13 of x
  CHECK_FALSE(Transform::fromMatrix(nearlyFlat));
}

TEST_CASE("points, vectors and normals round-trip through a sheared, scaled transform",
          "[transform]") {
  Mat4 m(1.0);
  m[1][0] = 0.7;  // shear: x += 0.7 y
  m = glm::translate(Mat4(1.0), Vec3(1, -2, 3)) * glm::scale(Mat4(1.0), Vec3(2, 3, 0.5)) * m;
  auto t = Transform::fromMatrix(m);
  REQUIRE(t);
  Vec3 p(0.3, -1.2, 2.5);
  CHECK(near(t->pointToObject(t->pointToWorld(p)), p));
  CHECK(near(t->vectorToObject(t->vectorToWorld(p)), p));
  // A normal stays perpendicular to every tangent after transformation.
  Vec3 n = glm::normalize(Vec3(1, 2, -1));
  Vec3 tangent1 = glm::normalize(glm::cross(n, Vec3(0, 0, 1)));
  Vec3 tangent2 = glm::cross(n, tangent1);
  Vec3 nw = t->normalToWorld(n);
  CHECK(glm::length(nw) == Approx(1.0));
  CHECK(std::abs(glm::dot(nw, t->vectorToWorld(tangent1))) < 1e-12);
  CHECK(std::abs(glm::dot(nw, t->vectorToWorld(tangent2))) < 1e-12);
}

TEST_CASE("ray parameters are the same in world and object space", "[transform]") {
  auto t = Transform::fromMatrix(glm::scale(Mat4(1.0), Vec3(4, 1, 0.25)));
  REQUIRE(t);
  Ray world(Vec3(1, 2, 3), Vec3(0.5, -1, 2), 0.25, 9.0);
  Ray obj = t->rayToObject(world);
  CHECK(obj.tmin == 0.25);
  CHECK(obj.tmax == 9.0);
  for (double s : {0.0, 0.5, 3.0}) CHECK(near(t->pointToWorld(obj.at(s)), world.at(s)));
}

TEST_CASE("a mirror transform is recognised and keeps outward normals outward", "[transform]") {
  auto t = Transform::fromMatrix(glm::scale(Mat4(1.0), Vec3(-1, 1, 1)));
  REQUIRE(t);
  CHECK(t->flipsHandedness());
  // On the unit sphere the outward normal at p is p: after mirroring it must still be.
  Vec3 p = glm::normalize(Vec3(0.6, 0.3, -0.2));
  CHECK(near(t->normalToWorld(p), t->pointToWorld(p)));
}

TEST_CASE("followedBy composes in the order written", "[transform]") {
  auto a = Transform::fromMatrix(glm::translate(Mat4(1.0), Vec3(1, 0, 0)));
  auto b = Transform::fromMatrix(glm::scale(Mat4(1.0), Vec3(2)));
  REQUIRE(a);
  REQUIRE(b);
  Transform ab = a->followedBy(*b);  // translate, then scale
  CHECK(near(ab.pointToWorld(Vec3(0)), Vec3(2, 0, 0)));
  CHECK(near(ab.pointToObject(Vec3(2, 0, 0)), Vec3(0)));
  CHECK(ab.normalToWorld() == b->normalToWorld() * a->normalToWorld());
}

TEST_CASE("error bounds grow with the magnitude of the transformed point", "[transform]") {
  auto t = Transform::fromMatrix(glm::translate(Mat4(1.0), Vec3(1e5, 0, 0)));
  REQUIRE(t);
  Vec3 e = t->errorToWorld(Vec3(1, 0, 0), Vec3(0));
  CHECK(e.x > 1e5 * kMachineEps);
  CHECK(e.x < 1e5 * 1e-14);
  CHECK(e.y == 0.0);
}
