// <isosurface> as the scene language reads it: the function compiled with its parameters,
// evaluated from several threads at once, in a CSG difference (also as inverse), the
// warning after a render whose function was steeper than max-gradient, and the function
// written for POV-Ray.
#include "../support/scene_text.h"
#include "lang/parser.h"
#include "povray/pov_function.h"
#include "scenegraph/gradient_report.h"
#include "scenegraph/world.h"

#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <cmath>
#include <thread>
#include <vector>

using namespace lucent;

namespace {

std::unique_ptr<Scene> parse(const std::string& body) {
  return lucent::test::parseValid(body, "iso.xml", "<camera/><param name=\"r\" value=\"0.6\"/>");
}

const IsosurfaceSpec& firstIso(const Scene& s) {
  const Node& n = *s.root->children.at(0);
  REQUIRE(n.shape);
  return std::get<IsosurfaceSpec>(*n.shape);
}

std::vector<Ray> fan() {
  std::vector<Ray> rays;
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 9; ++j) {
      const double a = 2 * kPi * i / 24, b = -0.8 + 0.2 * j;
      const Vec3 o(4 * std::cos(a), 3 * b, 4 * std::sin(a) + 0.1);
      const Vec3 target(0.3 * std::sin(3.0 * i), 0.2 * b, 0.25 * std::cos(5.0 * j));
      rays.emplace_back(o, glm::normalize(target - o));
    }
  return rays;
}

// Same hits within `tol` (distance and normal) on every ray of the fan.
void requireSame(const std::string& a, const std::string& b, double tol) {
  auto sa = parse(a), sb = parse(b);
  World wa(*sa), wb(*sb);
  int hits = 0;
  for (const Ray& ray : fan()) {
    Hit x, y;
    const bool fx = wa.intersect(ray, x), fy = wb.intersect(ray, y);
    INFO("ray from " << ray.o.x << " " << ray.o.y << " " << ray.o.z);
    REQUIRE(fx == fy);
    if (!fx) continue;
    ++hits;
    CHECK(std::abs(x.t - y.t) < tol);
    CHECK(glm::length(x.shape->surface(ray, x).ng - y.shape->surface(ray, y).ng) < 100 * tol);
  }
  CHECK(hits > 50);
}

const char* kIsoBall =
    R"(<isosurface function="sqrt((x - 0.6)^2 + (y - 0.3)^2 + z*z) - 0.9" container="sphere" center="0.6 0.3 0" radius="1")";

}  // namespace

TEST_CASE("isosurface scene: the function uses its parameters as they were when read",
          "[scenegraph][isosurface]") {
  auto s = parse(
      R"(<isosurface function="sqrt(x*x + y*y + z*z) - r" max-gradient="1.5" accuracy="0.0001"/>)");
  const IsosurfaceSpec& iso = firstIso(*s);
  CHECK(iso.function == "sqrt(x*x + y*y + z*z) - r");
  REQUIRE(iso.constants.size() == 1);
  CHECK(iso.constants[0].first == "r");
  CHECK(iso.constants[0].second == 0.6);
  CHECK(iso.field->value(Vec3(0.3, 0.4, 0.0)) == Approx(0.5 - 0.6).epsilon(1e-15));
  CHECK(iso.maxGradient == 1.5);
  CHECK(iso.accuracy == 0.0001);
  World w(*s);
  Hit h;
  REQUIRE(w.intersect(Ray(Vec3(0, 0, 5), Vec3(0, 0, -1)), h));
  CHECK(h.t == Approx(4.4).epsilon(1e-12));
}

TEST_CASE("isosurface scene: the compiled function is evaluated from many threads at once",
          "[scenegraph][isosurface]") {
  auto s = parse(R"(<isosurface function="sin(3*x) * cos(2*y) + z*z*z - r"/>)");
  std::shared_ptr<const ScalarField> f = firstIso(*s).field;
  std::vector<int> wrong(4, 0);
  std::vector<std::thread> threads;
  for (int k = 0; k < 4; ++k)
    threads.emplace_back([&, k] {
      for (int i = 0; i < 20000; ++i) {
        Vec3 p(0.001 * i, -0.0007 * i + k, 0.3 * k - 0.0001 * i);
        double expect = std::sin(3 * p.x) * std::cos(2 * p.y) + p.z * p.z * p.z - 0.6;
        if (std::abs(f->value(p) - expect) > 1e-12 * (1 + std::abs(expect))) ++wrong[k];
      }
    });
  for (std::thread& t : threads) t.join();
  CHECK(wrong == std::vector<int>(4, 0));
}

TEST_CASE(
    "isosurface scene: in a difference it carves as the exact sphere does, and inverse agrees",
    "[scenegraph][isosurface]") {
  const std::string box = R"(<box min="-1 -1 -1" max="1 1 1"/>)";
  const std::string iso = std::string(kIsoBall) + "/>";
  const std::string isoInverse = std::string(kIsoBall) + R"( inverse="true"/>)";
  // The function's roots are exact to rounding for this smooth function.
  requireSame("<difference>" + box + iso + "</difference>",
              "<difference>" + box + R"(<sphere center="0.6 0.3 0" radius="0.9"/></difference>)",
              1e-9);
  requireSame("<difference>" + box + iso + "</difference>",
              "<intersection>" + box + isoInverse + "</intersection>", 1e-12);
}

TEST_CASE("isosurface scene: a function steeper than max-gradient is reported after rendering",
          "[scenegraph][isosurface]") {
  for (const char* declared : {"1", "20"}) {
    auto s = parse(
        std::string(R"x(<isosurface function="10*(sqrt(x*x + y*y + z*z) - 0.5)" max-gradient=")x") +
        declared + R"("/>)");
    CHECK(gradientWarnings(*s).empty());  // nothing traced yet
    World w(*s);
    for (const Ray& ray : fan()) {
      Hit h;
      w.intersect(ray, h);
    }
    std::vector<std::string> warnings = gradientWarnings(*s);
    INFO("max-gradient " << declared);
    if (std::string(declared) == "1") {
      REQUIRE(warnings.size() == 1);
      CHECK(warnings[0].find("iso.xml:1:") == 0);
      CHECK(warnings[0].find(
                "warning: <isosurface> max-gradient is 1 but the function's gradient reached") !=
            std::string::npos);
      const double reached = firstIso(*s).record->largest();
      CHECK(reached > 1.0);  // slopes between pairs of values, up to the true 10
      CHECK(reached <= 10.0 + 1e-9);
    } else {
      CHECK(warnings.empty());
    }
  }
}

TEST_CASE("isosurface scene: the function is written in POV-Ray's function syntax",
          "[scenegraph][isosurface]") {
  auto number = [](double v) { return fmt::format("{}", v); };
  std::string problem;
  auto pov = [&](const std::string& t, std::vector<std::pair<std::string, double>> c = {}) {
    return povFunctionText(t, c, number, problem).value_or("(failed: " + problem + ")");
  };
  CHECK(pov("x^2 + -y^2") == "(pow(x, 2) + (-pow(y, 2)))");
  CHECK(pov("2^3^2") == "pow(2, pow(3, 2))");
  CHECK(pov("x < 0 ? a : 1", {{"a", -2.5}}) == "select(-abs((x < 0)), (-2.5), 1)");
  CHECK(pov("x == y && !z || x != 1") == "(((x = y) & (z = 0)) | (x != 1))");
  CHECK(pov("x % 2") == "(x - 2 * floor(x / 2))");
  CHECK(pov("min(x, y, z) + log10(x) + trunc(y)") == "((min(x, min(y, z)) + log(x)) + int(y))");
  CHECK(pov("clamp(x, 0, 1) * mix(y, z, 0.5)") == "(min(max(x, 0), 1) * (y + (z - y) * 0.5))");
  CHECK(pov("sign(x) + round(y)") ==
        "(select(x, -1, 0, 1) + select(y, -floor(0.5 - y), floor(y + 0.5)))");
  CHECK(pov("1.5e-3 * x <= 2") == "((0.0015 * x) <= 2)");
  CHECK_FALSE(povFunctionText("random(1, x)", {}, number, problem));
  CHECK(problem.find("random() has no POV-Ray") != std::string::npos);
  // functions.inc's functions are written out as their formulas, each argument in
  // parentheses where the formula names it: no functions.inc needed.
  CHECK(pov("f_sphere(x, y, z*2, 0.5)") ==
        "((((-(0.5)) + sqrt(((((x) * (x)) + ((y) * (y))) + (((z * 2)) * ((z * 2))))))))");
  CHECK(pov("f_torus(x, y, z, 1, 0.25)") ==
        "((((-(0.25)) + sqrt((pow(((sqrt((((x) * (x)) + ((z) * (z)))) - (1))), 2) + ((y) * "
        "(y)))))))");
}
