// POV-Ray 3.7's object pattern (pattern.cpp, object_pattern: 1 where Inside_Object says so,
// else 0) against the exact inside of the named solid, at random points kept away from its
// surface by 1e-9 and at points on it: a sphere, a box, a CSG difference and a transformed
// object, each named from <defs> by <pattern type="object" object="id">, with the pattern's
// own transform composed; and the colour a two-entry map gives, the first entry outside.
#include "../support/scene_text.h"

#include "render/patterns/pattern_value.h"
#include "render/texture.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <functional>
#include <random>
#include <string>

using namespace lucent;
using namespace lucent::test;

namespace {

const char* kDefs =
    "<defs>"
    "<sphere id=\"ball\" center=\"0.5 0 0\" radius=\"1\"/>"
    "<box id=\"brick\" min=\"-1 -0.5 -0.25\" max=\"1 0.5 0.25\"/>"
    "<difference id=\"cut\"><box min=\"-1 -1 -1\" max=\"1 1 1\"/>"
    "<sphere center=\"1 1 1\" radius=\"1.2\"/></difference>"
    "<box id=\"turned\" min=\"-1 -1 -1\" max=\"1 1 1\" "
    "transform=\"scale(0.5 1 0.25) rotate-z(30) translate(0.2 0.3 -0.4)\"/>"
    "</defs>";

// The pattern of the i-th sphere of a scene whose spheres wear `patterns` in turn.
std::unique_ptr<Scene> sceneOf(const std::vector<std::string>& patterns) {
  std::string body = kDefs;
  for (const std::string& p : patterns) body += "<sphere><material>" + p + "</material></sphere>";
  return parseClean(body);
}

// A point within 1e-9 of the surface is skipped.
using Exact = std::function<double(const Vec3&)>;  // signed distance-like: < 0 inside

void checkAgainst(const PatternSpec& s, const Exact& exact, const Mat4& patternFromObject) {
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  int inside = 0, outside = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec3 object(u(rng), u(rng), u(rng));
    const Vec3 p = Vec3(patternFromObject * Vec4(object, 1.0));
    const double d = exact(p);
    if (std::fabs(d) < 1e-9) continue;
    INFO("object point " << object.x << " " << object.y << " " << object.z);
    CHECK(patternValue(s, object) == (d < 0.0 ? 1.0 : 0.0));
    (d < 0.0 ? inside : outside)++;
  }
  CHECK(inside > 30);  // each solid fills at least 1/64 of the cube sampled
  CHECK(outside > 30);
}

double boxDistance(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  // < 0 strictly inside: the largest of the distances inside each pair of faces, negated.
  double d = -1e300;
  for (int a = 0; a < 3; ++a) d = std::max(d, std::max(lo[a] - p[a], p[a] - hi[a]));
  return d;
}

}  // namespace

TEST_CASE("object pattern: 1 inside a sphere, a box, a difference and a turned box, else 0",
          "[pattern][object]") {
  auto scene = sceneOf({"<pattern type=\"object\" object=\"ball\"/>",
                        "<pattern type=\"object\" object=\"brick\" transform=\"rotate-y(40)\"/>",
                        "<pattern type=\"object\" object=\"cut\"/>",
                        "<pattern type=\"object\" object=\"turned\" "
                        "transform=\"translate(0.1 0 0)\"/>"});
  const Exact ball = [](const Vec3& p) {
    const Vec3 f = p - Vec3(0.5, 0, 0);
    return glm::dot(f, f) - 1.0;
  };
  checkAgainst(nodePigmentPattern(*scene, 0), ball, Mat4(1.0));

  const Exact brick = [](const Vec3& p) {
    return boxDistance(p, Vec3(-1, -0.5, -0.25), Vec3(1, 0.5, 0.25));
  };
  const Mat4 rotY = glm::rotate(Mat4(1.0), glm::radians(40.0), Vec3(0, 1, 0));
  checkAgainst(nodePigmentPattern(*scene, 1), brick, glm::inverse(rotY));

  const Exact cut = [](const Vec3& p) {
    const double box = boxDistance(p, Vec3(-1), Vec3(1));
    const Vec3 f = p - Vec3(1, 1, 1);
    const double ball = 1.44 - glm::dot(f, f);  // < 0 outside the subtracted sphere
    return std::max(box, ball);
  };
  checkAgainst(nodePigmentPattern(*scene, 2), cut, Mat4(1.0));

  // The node's own transform (scale, then rotate, then translate) is the object's.
  Mat4 place = glm::translate(Mat4(1.0), Vec3(0.2, 0.3, -0.4));
  place = glm::rotate(place, glm::radians(30.0), Vec3(0, 0, 1));
  place = glm::scale(place, Vec3(0.5, 1, 0.25));
  const Mat4 unplace = glm::inverse(place);
  const Exact turned = [unplace](const Vec3& p) {
    const Vec3 q = Vec3(unplace * Vec4(p, 1.0));
    return boxDistance(q, Vec3(-1), Vec3(1));
  };
  checkAgainst(nodePigmentPattern(*scene, 3), turned,
               glm::inverse(glm::translate(Mat4(1.0), Vec3(0.1, 0, 0))));
}

TEST_CASE("object pattern: on a sphere's surface the point is outside, as POV-Ray's test",
          "[pattern][object]") {
  auto scene = sceneOf({"<pattern type=\"object\" object=\"ball\"/>"});
  const PatternSpec& s = nodePigmentPattern(*scene, 0);
  // |p - c|² < r² is false on the surface (POV-Ray's Sphere::Inside, strict).
  for (const Vec3& p : {Vec3(1.5, 0, 0), Vec3(-0.5, 0, 0), Vec3(0.5, 1, 0), Vec3(0.5, 0, -1)})
    CHECK(patternValue(s, p) == 0.0);
  CHECK(patternValue(s, Vec3(1.5 - 1e-12, 0, 0)) == 1.0);
  CHECK(patternValue(s, Vec3(0.5, 0, 0)) == 1.0);
}

TEST_CASE("object pattern: on a box's faces the point is inside, as POV-Ray's test",
          "[pattern][object]") {
  auto scene = sceneOf(
      {"<pattern type=\"object\" object=\"brick\"/>", "<pattern type=\"object\" object=\"cut\"/>"});
  const PatternSpec& s = nodePigmentPattern(*scene, 0);
  // POV-Ray's Box::Inside: outside only strictly beyond a face, so faces, edges and corners
  // are inside.
  for (const Vec3& p : {Vec3(1, 0, 0), Vec3(-1, 0.2, 0.1), Vec3(0.3, 0.5, 0), Vec3(0, -0.5, 0.25),
                        Vec3(0.5, 0.1, -0.25), Vec3(1, 0.5, 0.25), Vec3(-1, -0.5, -0.25)})
    CHECK(patternValue(s, p) == 1.0);
  for (const Vec3& p : {Vec3(1 + 1e-12, 0, 0), Vec3(0, 0.5 + 1e-12, 0), Vec3(0, 0, -0.25 - 1e-12)})
    CHECK(patternValue(s, p) == 0.0);
  // A box inside a difference: its faces are inside the box there too, and the sphere cut
  // away strictly, as POV-Ray's CSG asks each operand.
  const PatternSpec& cut = nodePigmentPattern(*scene, 1);
  CHECK(patternValue(cut, Vec3(-1, 0, 0)) == 1.0);
  CHECK(patternValue(cut, Vec3(-1, -1, -1)) == 1.0);
  CHECK(patternValue(cut, Vec3(1, -1, -1)) == 1.0);
}

TEST_CASE("object pattern: a two-entry map's first colour outside, its second inside",
          "[pattern][object]") {
  auto scene = sceneOf(
      {"<pattern type=\"object\" object=\"ball\"><color-map><entry at=\"0\" color=\"1 0 0\"/>"
       "<entry at=\"1\" color=\"0 0 1\"/></color-map></pattern>",
       "<pattern type=\"object\" object=\"ball\"><pigment-map><entry at=\"0\">"
       "<checker color1=\"1\" color2=\"0\"/></entry><entry at=\"1\" color=\"0 1 0\"/>"
       "</pigment-map></pattern>",
       "<pattern type=\"object\" object=\"ball\"/>"});
  auto colour = [&](size_t i, const Vec3& p) {
    const Material& m = scene->materials.at(*scene->root->children[i]->material);
    return pigmentAt(m.texture, p, Vec3(0.0)).rgb;
  };
  CHECK(colour(0, Vec3(0.5, 0, 0)) == Color(0, 0, 1));
  CHECK(colour(0, Vec3(1.7, 0, 0)) == Color(1, 0, 0));
  CHECK(colour(1, Vec3(0.5, 0.5, 0.5)) == Color(0, 1, 0));
  CHECK(colour(1, Vec3(1.7, 0.5, 0.5)) == Color(0.0f));   // checker cell [1,2)x[0,1)x[0,1)
  CHECK(colour(1, Vec3(-1.5, 0.5, 0.5)) == Color(1.0f));  // cell [-2,-1)x[0,1)x[0,1)
  CHECK(colour(2, Vec3(0.5, 0, 0)) == Color(1.0f));       // the grey map: white inside
  CHECK(colour(2, Vec3(3, 0, 0)) == Color(0.0f));
}

TEST_CASE("object pattern: a node may wear a pattern of itself (its materials are not asked)",
          "[pattern][object]") {
  auto scene = parseClean(
      "<sphere id=\"self\" radius=\"1\"><material><pattern type=\"object\" object=\"self\" "
      "transform=\"translate(0.5 0 0)\"/></material></sphere>");
  const PatternSpec& s = nodePigmentPattern(*scene, 0);
  CHECK(patternValue(s, Vec3(0.9, 0, 0)) == 1.0);
  CHECK(patternValue(s, Vec3(-0.6, 0, 0)) == 0.0);
}
