// POV-Ray's transforms (sdl/pov_space.h) against POV-Ray's own numbers, and the importer's
// handedness: z negated, transforms as S·M·S.
#include "pov_meaning_support.h"

#include "sdl/pov_space.h"

using namespace lucent;
using namespace lucent::sdl;
using namespace lucent::test;

namespace {

void requireNear(const Vec3& got, const std::vector<double>& want, double tolerance) {
  REQUIRE(want.size() == 3);
  INFO("got <" << got.x << ", " << got.y << ", " << got.z << ">, POV-Ray <" << want[0] << ", "
               << want[1] << ", " << want[2] << ">");
  for (int k = 0; k < 3; ++k)
    CHECK(std::abs(got[k] - want[k]) <= tolerance * (1.0 + std::abs(want[k])));
}

}  // namespace

TEST_CASE("rotate turns by the right-hand rule of POV-Ray's numbers, x then y then z",
          "[sdl][space]") {
  const Vec3 x(1.0, 0.0, 0.0);
  const Vec3 zTurn = PovTransform::rotation(Vec3(0.0, 0.0, 90.0)).vector(x);
  CHECK(zTurn.x == Approx(0.0).margin(1e-15));
  CHECK(zTurn.y == Approx(1.0));
  const Vec3 yTurn = PovTransform::rotation(Vec3(0.0, 90.0, 0.0)).vector(x);
  CHECK(yTurn.z == Approx(-1.0));
  CHECK(yTurn.x == Approx(0.0).margin(1e-15));
  // <90, 90, 0>: y goes to z by the x turn, and z to x by the y turn.
  const Vec3 both = PovTransform::rotation(Vec3(90.0, 90.0, 0.0)).vector(Vec3(0.0, 1.0, 0.0));
  CHECK(both.x == Approx(1.0));
  CHECK(both.y == Approx(0.0).margin(1e-15));
}

TEST_CASE("translate, rotate, scale, matrix and inverse give POV-Ray's own numbers",
          "[sdl][space][povray]") {
  // POV-Ray prints its results of the same transforms (vtransform from transforms.inc).
  const std::string messages = povrayMessages(R"POV(#version 3.7;
#include "transforms.inc"
#declare T = transform { rotate <10, 20, 30> translate <1, -2, 3> scale <2, 3, 4>
                         matrix <1, 2, 3, 4, 5, 6, 7, 8, 10, 0.5, 0.25, 0.125> }
#debug concat("chain:", vstr(3, vtransform(<1, 2, 3>, T), " ", 0, 17), "\n")
#debug concat("inverse:", vstr(3, vtransform(<1, 2, 3>, transform { T inverse }), " ", 0, 17), "\n")
#debug concat("vrotate:", vstr(3, vrotate(<0.3, -1.2, 2.5>, <-35, 80, 125>), " ", 0, 17), "\n")
)POV");
  PovTransform t = PovTransform::rotation(Vec3(10.0, 20.0, 30.0));
  t.translate(Vec3(1.0, -2.0, 3.0));
  t.scale(Vec3(2.0, 3.0, 4.0));
  t = t.then(PovTransform::matrix({1, 2, 3, 4, 5, 6, 7, 8, 10, 0.5, 0.25, 0.125}));
  requireNear(t.point(Vec3(1.0, 2.0, 3.0)), printedNumbers(messages, "chain:"), 1e-12);
  requireNear(t.inverse().point(Vec3(1.0, 2.0, 3.0)), printedNumbers(messages, "inverse:"), 1e-12);
  requireNear(PovTransform::rotation(Vec3(-35.0, 80.0, 125.0)).vector(Vec3(0.3, -1.2, 2.5)),
              printedNumbers(messages, "vrotate:"), 1e-12);
}

TEST_CASE("the import negates z: a transform becomes S·M·S", "[sdl][space]") {
  PovTransform t = PovTransform::rotation(Vec3(10.0, -40.0, 75.0));
  t.translate(Vec3(0.5, 2.0, -3.0));
  t.scale(Vec3(1.0, 2.0, 0.5));
  const Vec3 p(0.25, -1.5, 2.0);
  // Moving the point in POV-Ray's space and then mirroring it is the same as mirroring it
  // and moving it with the mirrored transform.
  const Vec3 expected = lucentFromPov(t.point(p));
  const Vec3 got = Vec3(t.lucentMatrix() * Vec4(lucentFromPov(p), 1.0));
  CHECK(got.x == Approx(expected.x).epsilon(1e-14));
  CHECK(got.y == Approx(expected.y).epsilon(1e-14));
  CHECK(got.z == Approx(expected.z).epsilon(1e-14));
  // A rotation stays a rotation (determinant 1), turned the other way about z-free axes.
  CHECK(glm::determinant(Mat3(t.lucentMatrix())) ==
        Approx(glm::determinant(Mat3(t.povMatrix()))).epsilon(1e-14));
}
