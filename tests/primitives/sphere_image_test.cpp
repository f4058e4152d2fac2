// sphereImage: what a similarity transform makes of a sphere, with a bound of its error
// that really bounds the distance to the exact image (checked in long double).
#include "shape_checks.h"

#include "primitives/sphere_image.h"

#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

using Vec3L = glm::tvec3<long double>;

// The exact image (to long double's 64-bit significand) of object point p under m.
Vec3L mapExactly(const Mat4& m, const Vec3& p) {
  Vec3L out;
  for (int r = 0; r < 3; ++r) {
    long double v = m[3][r];
    for (int c = 0; c < 3; ++c) v += (long double)m[c][r] * (long double)p[c];
    out[r] = v;
  }
  return out;
}

// A random similarity: rotation about a random axis, uniform scale (mirrored when
// `mirror`), translation.
Mat4 randomSimilarity(Rng& rng, double translate, bool mirror) {
  double s = std::exp(uniform(rng, -5.0, 5.0));
  Mat4 m = glm::translate(Mat4(1.0), translate * randomUnit(rng)) *
           glm::rotate(Mat4(1.0), uniform(rng, -kPi, kPi), randomUnit(rng)) *
           glm::scale(Mat4(1.0), Vec3(mirror ? -s : s, s, s));
  return m;
}

}  // namespace

TEST_CASE("the image of a sphere under the identity is the sphere itself, exactly",
          "[primitives][sphere]") {
  auto img = sphereImage(Transform(), Vec3(0.1, -2.5, 1e5), 0.3);
  REQUIRE(img);
  CHECK(img->center == Vec3(0.1, -2.5, 1e5));
  CHECK(img->radius == 0.3);
  CHECK(img->error == 0.0);
}

TEST_CASE("the image of a sphere under a similarity is within its error bound of the exact image",
          "[primitives][sphere]") {
  Rng rng(41);
  int checked = 0;
  for (int k = 0; k < 2000; ++k) {
    const double far = k % 4 == 0 ? 1e5 : (k % 4 == 1 ? 1.0 : 1e-3);
    Mat4 m = randomSimilarity(rng, far * uniform(rng, 0.0, 1.0), k % 3 == 0);
    auto t = Transform::fromMatrix(m);
    REQUIRE(t);
    Vec3 c = far * randomUnit(rng) * uniform(rng, 0.0, 1.0);
    double r = std::exp(uniform(rng, -8.0, 3.0));
    auto img = sphereImage(*t, c, r);
    REQUIRE(img);
    // The bound is tight enough to be worth having: a few hundred units of rounding of
    // the magnitudes involved, never a loose tolerance.
    double scale = std::cbrt(std::abs(glm::determinant(Mat3(m))));
    double magnitude = glm::length(Vec3(m[3])) + scale * (glm::length(c) + r);
    CHECK(img->error > 0.0);
    CHECK(img->error < 1e-13 * magnitude);
    // Every exact image of a point of the object's sphere lies within `error` of the
    // image sphere's surface.
    for (int j = 0; j < 20; ++j) {
      Vec3 p = c + r * randomUnit(rng);
      // p itself is off the object's sphere by rounding, by objErr; its image is off
      // the exact image by about scale times that.
      long double objErr = std::abs(glm::length(Vec3L(p) - Vec3L(c)) - (long double)r);
      Vec3L q = mapExactly(m, p);
      long double dist = std::abs(glm::length(q - Vec3L(img->center)) - (long double)img->radius);
      REQUIRE(dist <= (long double)img->error + objErr * (long double)scale * 1.0001L);
      ++checked;
    }
  }
  CHECK(checked == 40000);
}

TEST_CASE("a sphere under a non-uniform scale or a shear has no spherical image",
          "[primitives][sphere]") {
  auto squash = Transform::fromMatrix(glm::scale(Mat4(1.0), Vec3(1.0, 1.0, 1.0 + 1e-9)));
  REQUIRE(squash);
  CHECK_FALSE(sphereImage(*squash, Vec3(0.0), 1.0));
  Mat4 shear(1.0);
  shear[1][0] = 1e-10;
  auto sheared = Transform::fromMatrix(shear);
  REQUIRE(sheared);
  CHECK_FALSE(sphereImage(*sheared, Vec3(0.0), 1.0));
  // A rotation composed many times stays a similarity within rounding.
  Mat4 spin(1.0);
  for (int i = 0; i < 50; ++i) spin = glm::rotate(Mat4(1.0), 0.1 * (i + 1), Vec3(1, 2, 3)) * spin;
  auto spun = Transform::fromMatrix(spin);
  REQUIRE(spun);
  auto img = sphereImage(*spun, Vec3(1, 0, 0), 2.0);
  REQUIRE(img);
  CHECK(img->radius == Approx(2.0).epsilon(1e-14));
}
