// The POV-Ray text of numbers, colours and matrices: the layout POV-Ray reads.
#include "povray/pov_writer.h"
#include "lang/transform_syntax.h"

#include <catch2/catch.hpp>

#include <random>
#include <sstream>

using namespace lucent;

TEST_CASE("pov matrix lists the images of x, y, z and the translation (row-vector layout)",
          "[povray][writer]") {
  // rotate-z(90) maps +x to +y and +y to -x; then translate(1 2 3).
  auto t = parseTransformSyntax("rotate-z(90) translate(1 2 3)");
  REQUIRE(t.ok);
  CHECK(povMatrix(t.matrix) == "matrix <0, 1, 0,  -1, 0, 0,  0, 0, 1,  1, 2, 3>");

  // rotate-y(90) maps +x to -z (POV-Ray's `rotate y*90` does the same).
  auto ry = parseTransformSyntax("rotate-y(90)");
  CHECK(povMatrix(ry.matrix) == "matrix <0, 0, -1,  0, 1, 0,  1, 0, 0,  0, 0, 0>");

  // A shear written as 12 numbers (3 rows of 4, column-vector convention p' = A p + t):
  // POV-Ray's m_ik is A_ki.
  auto shear = parseTransformSyntax("matrix(1 2 0 5  0 1 0 6  0 0 1 7)");
  REQUIRE(shear.ok);
  CHECK(povMatrix(shear.matrix) == "matrix <1, 0, 0,  2, 1, 0,  0, 0, 1,  5, 6, 7>");
}

TEST_CASE("pov matrix read back with POV-Ray's x'_k = sum_i x_i m_ik + t_k maps points as we do",
          "[povray][writer]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int trial = 0; trial < 50; ++trial) {
    Mat4 m(1.0);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 3; ++r) m[c][r] = u(rng);
    // Parse the twelve numbers the way POV-Ray does.
    std::string text = povMatrix(m);
    REQUIRE(text.rfind("matrix <", 0) == 0);
    std::string numbers = text.substr(8, text.size() - 9);
    for (char& ch : numbers)
      if (ch == ',') ch = ' ';
    std::istringstream in(numbers);
    double v[12];
    for (double& x : v) REQUIRE(in >> x);
    Vec3 p(u(rng), u(rng), u(rng));
    Vec3 expected = Vec3(m * Vec4(p, 1.0));
    for (int k = 0; k < 3; ++k) {
      double pov = p.x * v[0 * 3 + k] + p.y * v[1 * 3 + k] + p.z * v[2 * 3 + k] + v[9 + k];
      CHECK(pov == Approx(expected[k]).epsilon(1e-15));
    }
  }
}

TEST_CASE("pov numbers round-trip and colours are written as their float values",
          "[povray][writer]") {
  CHECK(povNumber(0.1) == "0.1");
  CHECK(povNumber(-0.0) == "0");
  CHECK(povNumber(1e-7) == "1e-07");
  CHECK(std::stod(povNumber(1.0 / 3.0)) == 1.0 / 3.0);
  CHECK(povFloat(static_cast<double>(0.8f)) == "0.8");
  CHECK(povRgb(Color(0.8f, 0.0f, 1.0f)) == "rgb <0.8, 0, 1>");
  CHECK(povRgbft(Vec3(0.5), 0.25, 0.75) == "rgbft <0.5, 0.5, 0.5, 0.25, 0.75>");
  CHECK(povVector(Vec3(1, -2.5, 3)) == "<1, -2.5, 3>");
}

TEST_CASE("pov identifiers keep letters, digits and underscores only", "[povray][writer]") {
  CHECK(povIdentifier("M3", "brick-red") == "M3_brick_red");
  CHECK(povIdentifier("M0", "") == "M0");
  CHECK(povIdentifier("M1", std::string(60, 'a')).size() == 40);
  CHECK(povString("a \"b\" \\c") == "\"a \\\"b\\\" \\\\c\"");
}
