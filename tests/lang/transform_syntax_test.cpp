// The transform attribute's syntax: operations in the order written (the first applied
// first), exact quarter turns, the matrix forms, and errors with their offsets.
#include "lang/transform_syntax.h"

#include <catch2/catch.hpp>

#include <string>

using namespace lucent;

namespace {

Mat4 parsed(const char* text) {
  TransformSyntaxResult r = parseTransformSyntax(text);
  INFO(text << ": " << r.error);
  REQUIRE(r.ok);
  return r.matrix;
}

Vec3 apply(const Mat4& m, const Vec3& p) { return Vec3(m * Vec4(p, 1.0)); }

bool close(const Vec3& a, const Vec3& b) { return glm::length(a - b) <= 1e-12; }

TransformSyntaxResult failed(const char* text) {
  TransformSyntaxResult r = parseTransformSyntax(text);
  INFO(text);
  REQUIRE_FALSE(r.ok);
  CHECK(r.matrix == Mat4(1.0));
  return r;
}

}  // namespace

TEST_CASE("lang: transform operations apply in the order written", "[lang][transform]") {
  // The reference's worked examples.
  CHECK(apply(parsed("scale(2) translate(0 1 0)"), Vec3(0.0)) == Vec3(0, 1, 0));
  CHECK(apply(parsed("scale(2) translate(0 1 0)"), Vec3(1, 0, 0)) == Vec3(2, 1, 0));
  CHECK(apply(parsed("translate(0 1 0) scale(2)"), Vec3(0.0)) == Vec3(0, 2, 0));
  CHECK(apply(parsed("translate(3 0 0) rotate-y(90)"), Vec3(0.0)) == Vec3(0, 0, -3));
  CHECK(apply(parsed("rotate-y(90) translate(3 0 0)"), Vec3(0.0)) == Vec3(3, 0, 0));
  CHECK(apply(parsed("rotate-y(90) translate(3 0 0)"), Vec3(1, 0, 0)) == Vec3(3, 0, -1));
  // M = T3·T2·T1 for three operations.
  Mat4 m = parsed("translate(1 0 0) scale(1 2 3) rotate-z(90)");
  CHECK(apply(m, Vec3(0, 1, 0)) == Vec3(-2, 1, 0));  // (1,1,0) -> (1,2,0) -> (-2,1,0)
}

TEST_CASE("lang: rotations are right-handed and exact at quarter turns", "[lang][transform]") {
  CHECK(apply(parsed("rotate-x(90)"), Vec3(0, 1, 0)) == Vec3(0, 0, 1));
  CHECK(apply(parsed("rotate-y(90)"), Vec3(1, 0, 0)) == Vec3(0, 0, -1));
  CHECK(apply(parsed("rotate-z(90)"), Vec3(1, 0, 0)) == Vec3(0, 1, 0));
  CHECK(apply(parsed("rotate-z(-90)"), Vec3(1, 0, 0)) == Vec3(0, -1, 0));
  CHECK(apply(parsed("rotate-z(450)"), Vec3(1, 0, 0)) == Vec3(0, 1, 0));
  CHECK(apply(parsed("rotate-x(180)"), Vec3(0, 1, 0)) == Vec3(0, -1, 0));
  CHECK(apply(parsed("rotate(90, 0 0 5)"), Vec3(1, 0, 0)) ==
        Vec3(0, 1, 0));  // the axis is normalised
  CHECK(close(apply(parsed("rotate(120, 1 1 1)"), Vec3(1, 0, 0)), Vec3(0, 1, 0)));
  double h = std::sqrt(0.5);
  CHECK(close(apply(parsed("rotate-y(45)"), Vec3(1, 0, 0)), Vec3(h, 0, -h)));
  CHECK(close(apply(parsed("rotate(30, 0 1 0)"), Vec3(1, 2, 3)),
              apply(parsed("rotate-y(30)"), Vec3(1, 2, 3))));
}

TEST_CASE("lang: matrix() takes 3 rows of 4 or 4 rows of 4, row-major", "[lang][transform]") {
  // x' = x + 0.5 y + 7, y' = 2 y, z' = z - 1
  Mat4 a = parsed("matrix(1 0.5 0 7, 0 2 0 0, 0 0 1 -1)");
  CHECK(a[1][0] == 0.5);  // glm: column 1, row 0
  CHECK(a[3][0] == 7.0);
  CHECK(apply(a, Vec3(1, 1, 1)) == Vec3(8.5, 2, 0));
  Mat4 b = parsed("matrix(1,0.5,0,7,0,2,0,0,0,0,1,-1,0,0,0,1)");
  CHECK(a == b);
}

TEST_CASE("lang: separators: spaces and commas in arguments, spaces between operations",
          "[lang][transform]") {
  Mat4 t = parsed("translate(1 2 3)");
  CHECK(parsed("translate(1,2,3)") == t);
  CHECK(parsed("translate( 1 , 2 ,3 )") == t);
  CHECK(parsed("  translate (1 2 3)  ") == t);
  CHECK(parsed("translate(1 2 3),scale(1)") == t);
  CHECK(parsed("translate(+1 2e0 .3e1)") == t);
  CHECK(parsed("") == Mat4(1.0));
  CHECK(parsed("   ") == Mat4(1.0));
  CHECK(parsed("scale(1 2 3)\n  rotate-x(0)") == scaleMatrix(Vec3(1, 2, 3)));
}

TEST_CASE("lang: transform errors say what is wrong and where", "[lang][transform]") {
  TransformSyntaxResult r = failed("rotate-y(30) tranlate(1 2 3)");
  CHECK(r.error == "unknown operation 'tranlate'");
  CHECK(r.unknownOperation == "tranlate");
  CHECK(r.errorOffset == 13);

  r = failed("translate(1 2)");
  CHECK(r.error == "'translate' expects 3 numbers (x y z), got 2");
  CHECK(r.errorOffset == 0);
  r = failed("scale(1 2)");
  CHECK(r.error == "'scale' expects 1 or 3 numbers, got 2");
  r = failed("rotate(90)");
  CHECK(r.error == "'rotate' expects 4 numbers (angle, x y z), got 1");
  r = failed("matrix(1 0 0 0 1 0 0 0 1)");
  CHECK(r.error == "'matrix' expects 12 numbers (3 rows of 4) or 16 (4 rows of 4), got 9");
  r = failed("matrix(1 0 0 0  0 1 0 0  0 0 1 0  0.5 0 0 1)");
  CHECK(r.error == "'matrix': the last row must be 0 0 0 1 (only affine transforms are allowed)");
  r = failed("rotate(10, 0 0 0)");
  CHECK(r.error == "'rotate': the rotation axis must not be zero");
  r = failed("scale(1 0 1)");
  CHECK(r.error ==
        "the transform is singular (it flattens space, e.g. a zero scale) and cannot be inverted");
  // Numbers below 1e-30 are refused (docs/security.md); allowed ones whose product
  // underflows to a zero matrix make a singular transform.
  r = failed("scale(1e-200)");
  CHECK_THAT(r.error, Catch::Contains("too small"));
  std::string tiny;
  for (int i = 0; i < 11; ++i) tiny += "scale(1e-30) ";
  r = failed(tiny.c_str());
  CHECK_THAT(r.error, Catch::Contains("singular"));

  r = failed("translate(1 2 x)");
  CHECK(r.error == "'translate': expected a number, got 'x'");
  CHECK(r.errorOffset == 14);
  r = failed("translate(1 2 3");
  CHECK(r.error == "'translate(' is missing its ')'");
  r = failed("translate 1 2 3");
  CHECK(r.error == "'translate' must be followed by '(' and its arguments");
  CHECK(r.errorOffset == 10);
  r = failed("translate(1,,2 3)");
  CHECK(r.error == "'translate': a number is missing before ','");
  CHECK(r.errorOffset == 12);
  r = failed("translate(1 2 inf)");
  CHECK(r.error == "'translate': expected a finite number, got 'inf'");
  r = failed("translate(1 2 nan)");
  CHECK(r.error == "'translate': expected a finite number, got 'nan'");
  r = failed("scale(2) )");
  CHECK(r.errorOffset == 9);
  r = failed("scale(2),");
  CHECK(r.error == "expected an operation after ','");
}
