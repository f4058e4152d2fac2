// POV-Ray's normal accuracy: the slope is sampled at that distance and the bend scaled by
// 0.02 / accuracy, so a pattern that varies linearly bends the same at every accuracy and
// a noisy one does not; the importer and the XML language read it.
#include "render/patterns/normal_perturbation.h"

#include "../sdl/scene_read_support.h"
#include "../support/scene_text.h"

#include <catch2/catch.hpp>

using namespace lucent;

namespace {

Vec3 bent(PatternType type, double accuracy, const Vec3& p) {
  NormalSpec n;
  n.pattern.type = type;
  n.pattern.axis = Vec3(1, 0, 0);
  n.depth = 0.5;
  n.accuracy = accuracy;
  return perturbNormal(n, p, Vec3(0, 0, 1));
}

}  // namespace

TEST_CASE("normal accuracy: a linear pattern bends alike at every accuracy, noise does not",
          "[patterns][normal][accuracy]") {
  const Vec3 p(0.3, 0.2, 0.1);  // inside one ramp of gradient x
  const Vec3 a = bent(PatternType::gradient, 0.02, p), b = bent(PatternType::gradient, 0.001, p);
  for (int i = 0; i < 3; ++i) CHECK(a[i] == Approx(b[i]).margin(1e-5));
  CHECK(a.x != Approx(0.0).margin(1e-3));  // it does bend
  const Vec3 c = bent(PatternType::granite, 0.02, p), d = bent(PatternType::granite, 0.0005, p);
  CHECK(glm::length(c - d) > 1e-3);
}

TEST_CASE("normal accuracy: read by the importer and by <normal accuracy>",
          "[patterns][normal][accuracy][sdl][lang]") {
  auto r = sdltest::readScene("sphere { 0, 1 normal { granite 0.5 accuracy 0.0005 } }");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const Material& m = s.materials.at(*s.root->children.at(0)->material);
  REQUIRE(m.normal);
  CHECK(m.normal->accuracy == 0.0005);
  CHECK_FALSE(sdltest::errorsOf("sphere { 0, 1 normal { granite accuracy 0 } }").empty());

  auto x = test::parseClean(
      "<material id=\"m\"><normal type=\"granite\" accuracy=\"0.001\"/></material>"
      "<sphere material=\"m\"/>");
  REQUIRE(test::materialNamed(*x, "m").normal);
  CHECK(test::materialNamed(*x, "m").normal->accuracy == 0.001);
  CHECK(test::messages(test::parseBody("<material id=\"m\"><normal type=\"granite\" "
                                       "accuracy=\"-1\"/></material>"))
            .find("accuracy") != std::string::npos);
}
