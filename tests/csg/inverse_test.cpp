// inverse="true" through all four CSG operations, against the identities that define it:
// A ∩ inverse(B) = A − B, A − inverse(B) = A ∩ B, A ∪ inverse(B) = inverse(B − A) and
// merge likewise; an inverted solid alone has the same surface with the normal turned, and
// its inside is the outside. Compared ray by ray over a fan of rays through the shapes.
#include "../render/scene_builder.h"

#include "../support/scene_text.h"
#include "first_hit.h"
#include "lang/parser.h"
#include "povray/pov_export.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

std::unique_ptr<Scene> parse(const std::string& body) { return parseValid(body, "inverse.xml"); }

// Rays from a ring of origins around the shapes towards points near the middle.
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

// The two scenes show the same surfaces: same hits, distances and normals on every ray.
void requireSame(const std::string& a, const std::string& b) {
  auto sa = parse(a), sb = parse(b);
  World wa(*sa), wb(*sb);
  int hits = 0;
  for (const Ray& ray : fan()) {
    const Seen x = look(wa, ray), y = look(wb, ray);
    INFO("ray from " << ray.o.x << " " << ray.o.y << " " << ray.o.z);
    REQUIRE(x.found == y.found);
    if (!x.found) continue;
    ++hits;
    CHECK(x.t == Approx(y.t).margin(1e-12));
    CHECK(glm::length(x.ng - y.ng) < 1e-9);
  }
  CHECK(hits > 50);  // the fan sees the shapes
}

const char* kBox = R"(<box min="-1 -1 -1" max="1 1 1"/>)";
const char* kBall = R"(<sphere center="0.6 0.3 0" radius="0.9")";

std::string ball(bool inverse) {
  return std::string(kBall) + (inverse ? R"( inverse="true"/>)" : "/>");
}

}  // namespace

TEST_CASE("inverse: an intersection with an inverse solid is the difference", "[csg][inverse]") {
  requireSame("<intersection>" + std::string(kBox) + ball(true) + "</intersection>",
              "<difference>" + std::string(kBox) + ball(false) + "</difference>");
}

TEST_CASE("inverse: a difference with an inverse solid is the intersection", "[csg][inverse]") {
  requireSame("<difference>" + std::string(kBox) + ball(true) + "</difference>",
              "<intersection>" + std::string(kBox) + ball(false) + "</intersection>");
}

TEST_CASE("inverse: union and merge with an inverse solid are the inverse of a difference",
          "[csg][inverse]") {
  // A ∪ ¬B = ¬(B − A): everything but the part of the ball outside the box. Seen from
  // outside it, the rays meet the ball's outer surface, turned inwards.
  const std::string outside =
      "<difference inverse=\"true\">" + ball(false) + kBox + "</difference>";
  requireSame("<merge>" + std::string(kBox) + ball(true) + "</merge>", outside);
  // A union keeps the surfaces inside other children: the box's faces inside ¬B are shown,
  // so compare the union with a union.
  requireSame("<union>" + std::string(kBox) + ball(true) + "</union>",
              "<union>" + std::string(kBox) + "<group inverse=\"true\">" + ball(false) +
                  "</group></union>");
}

TEST_CASE("inverse: alone, the same surface with the normal turned, and inverse twice is the solid",
          "[csg][inverse]") {
  auto plain = parse(ball(false)), inverted = parse(ball(true));
  auto twice = parse(R"(<group inverse="true">)" + ball(true) + "</group>");
  World wp(*plain), wi(*inverted), w2(*twice);
  int hits = 0;
  for (const Ray& ray : fan()) {
    const Seen p = look(wp, ray), i = look(wi, ray), t = look(w2, ray);
    REQUIRE(p.found == i.found);
    REQUIRE(p.found == t.found);
    if (!p.found) continue;
    ++hits;
    CHECK(i.t == p.t);
    CHECK(glm::length(i.ng + p.ng) < 1e-12);
    CHECK(glm::length(t.ng - p.ng) < 1e-12);
  }
  CHECK(hits > 50);
  // Inside is outside.
  const Shape& solid = *wi.objects().front().shape;
  CHECK_FALSE(solid.inside(Vec3(0.6, 0.3, 0)));
  CHECK(solid.inside(Vec3(5, 0, 0)));
  CrossingList list;
  solid.crossings(Ray(Vec3(-3, 0.3, 0), Vec3(1, 0, 0)), list);
  CHECK(list.startsInside);
  REQUIRE(list.items.size() == 2);
  CHECK_FALSE(list.items[0].entering);
  CHECK(list.items[0].hit.t == Approx(3.6 - 0.9).margin(1e-12));
  CHECK(list.items[1].entering);
}

TEST_CASE("inverse is exported as POV-Ray's inverse, a plane as the plane turned",
          "[csg][inverse][povray]") {
  auto scene = parse(R"(<sphere radius="1" inverse="true"/>
      <plane normal="0 1 0" offset="2" inverse="true"/>
      <group inverse="true"><sphere radius="0.5"/><box min="1 1 1" max="2 2 2"/></group>
      <intersection><box/><group inverse="true"><sphere radius="0.5"/></group></intersection>)");
  PovExport out = exportPov(*scene, PovExportOptions{});
  INFO(out.text);
  // The sphere, the union of the inverse group and the inverse sphere in the intersection.
  size_t count = 0;
  for (size_t at = out.text.find("inverse\n"); at != std::string::npos;
       at = out.text.find("inverse\n", at + 1))
    ++count;
  CHECK(count == 3);
  CHECK(out.text.find("<0, -1, 0>, -2") != std::string::npos);  // plane { -y, -2 }: y > 2 inside
}

TEST_CASE("inverse: a transparent inverse solid filters shadows as the solid does",
          "[csg][inverse]") {
  auto sceneWith = [](const char* inverse) {
    return std::string(R"(<render ambient="0"/><light type="point" position="0 6 0"/>
      <plane normal="0 1 0" offset="0"><material diffuse="1"/></plane>
      <sphere center="0 2 0" radius="1" inverse=")") +
           inverse + R"("><material diffuse="0.1" transmissive="0.5"/></sphere>)";
  };
  auto plain = parse(sceneWith("false")), inverted = parse(sceneWith("true"));
  World wp(*plain), wi(*inverted);
  // Straight below the ball: the shadow ray crosses its surface twice, 0.5 kept each time.
  const Ray down(Vec3(0.01, 0.5, 0.02), Vec3(0, -1, 0));
  const float lit = traceOne(wp, down).r;
  CHECK(lit > 0.05f);
  CHECK(traceOne(wi, down).r == Approx(lit).epsilon(1e-6));
}

TEST_CASE("inverse: a sor in a CSG difference and intersection keeps the identities",
          "[csg][inverse][sor]") {
  const std::string vase =
      R"X(<sor points="0 -1.5  0.6 -1  0.9 -0.4  0.4 0.4  0.7 1  0.8 1.2" transform="translate(0.3 0 0)")X";
  const std::string plain = vase + "/>", inverted = vase + R"( inverse="true"/>)";
  requireSame("<difference>" + std::string(kBox) + inverted + "</difference>",
              "<intersection>" + std::string(kBox) + plain + "</intersection>");
  requireSame("<intersection>" + std::string(kBox) + inverted + "</intersection>",
              "<difference>" + std::string(kBox) + plain + "</difference>");
}
