// Lights in the hierarchy: a <light> in a group, CSG operation, <defs>, <repeat> or <if>,
// or instantiated by <use>, is placed in the world by its parent's world transform after
// its own (Scene::lights, scenegraph/light_placement.h).
#include "../support/scene_text.h"
#include "scenegraph/light_placement.h"

#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

ParseResult parse(const std::string& body) { return parseBody(body, "lights.xml"); }
std::unique_ptr<Scene> load(const std::string& body) { return parseClean(body, "lights.xml"); }

bool close(const Vec3& a, const Vec3& b) { return glm::length(a - b) <= 1e-12; }

}  // namespace

TEST_CASE("lang: a light in a group is placed by the group's transform after its own",
          "[lang][lights]") {
  auto s = load(R"XML(<group transform="rotate-z(90) translate(10 0 0)">
      <light type="spot" position="1 0 0" direction="1 0 0" transform="translate(0 2 0)"/>
      <sphere/>
    </group>)XML");
  REQUIRE(s->lights.size() == 1);
  const Light& l = s->lights[0];
  // (1, 0, 0) + (0, 2, 0) = (1, 2, 0); rotated 90° about z: (-2, 1, 0); moved: (8, 1, 0).
  CHECK(close(l.position, Vec3(8, 1, 0)));
  CHECK(close(l.direction, Vec3(0, 1, 0)));
  CHECK(l.angle == 30.0);
  REQUIRE(s->root->children.size() == 1);
  CHECK(s->root->children[0]->children.size() == 2);  // the light is a node of the group
}

TEST_CASE("lang: look-at, area axes and directional lights follow the frame", "[lang][lights]") {
  auto s = load(R"XML(<group transform="scale(2) rotate-y(90)">
      <light type="spot" position="0 4 0" look-at="1 0 0"/>
      <light type="area" position="0 3 0" u="1 0 0" v="0 0 0.5" samples="2 2"/>
      <light type="directional" direction="1 -1 0"/>
    </group>)XML");
  REQUIRE(s->lights.size() == 3);
  // rotate-y(90) takes +x to -z; scale(2) first.
  CHECK(close(s->lights[0].position, Vec3(0, 8, 0)));
  CHECK(close(s->lights[0].direction, glm::normalize(Vec3(0, -4, -1))));
  CHECK(close(s->lights[1].u, Vec3(0, 0, -2)));
  CHECK(close(s->lights[1].v, Vec3(1, 0, 0)));
  CHECK(close(s->lights[2].direction, glm::normalize(Vec3(0, -1, -1))));
}

TEST_CASE("lang: a lamp defined once is placed by every use and repeat", "[lang][lights]") {
  auto s = load(R"XML(<light position="0 9 0"/>
    <defs>
      <group id="lamp">
        <sphere center="0 2 0" radius="0.1" shadows="false"/>
        <light position="0 2 0" color="1 0.5 0"/>
      </group>
    </defs>
    <repeat var="i" count="3"><use ref="lamp" transform="translate(${2*i} 0 0)"/></repeat>
    <use ref="lamp" transform="scale(2) translate(0 0 5)"/>
    <group transform="translate(0 1 0)"><use ref="lamp"/></group>)XML");
  REQUIRE(s->lights.size() == 6);
  CHECK(s->lights[0].position == Vec3(0, 9, 0));  // the top-level lights come first
  CHECK(close(s->lights[1].position, Vec3(0, 2, 0)));
  CHECK(close(s->lights[2].position, Vec3(2, 2, 0)));
  CHECK(close(s->lights[3].position, Vec3(4, 2, 0)));
  CHECK(close(s->lights[4].position, Vec3(0, 4, 5)));
  CHECK(close(s->lights[5].position, Vec3(0, 3, 0)));
  CHECK(s->lights[5].color == Color(1.0f, 0.5f, 0.0f));
}

TEST_CASE("lang: a light with an id is placed again by a use, with parameters too",
          "[lang][lights]") {
  auto s = load(R"XML(<light id="key" position="1 1 1"/>
    <use ref="key" transform="translate(0 10 0)"/>
    <defs><light id="warm" position="0 3 0"><param name="c" value="1 0.8 0.6"/><param name="k" value="1"/></light></defs>
    <use ref="warm"><param name="k" value="2"/></use>
    <defs><light id="tinted" position="0 3 0" color="$c"><param name="c" value="1"/></light></defs>
    <use ref="tinted" transform="translate(1 0 0)"><param name="c" value="0.5 0.25 0"/></use>)XML");
  REQUIRE(s->lights.size() == 4);
  CHECK(s->lights[0].position == Vec3(1, 1, 1));
  CHECK(close(s->lights[1].position, Vec3(1, 11, 1)));
  CHECK(close(s->lights[2].position, Vec3(0, 3, 0)));
  CHECK(close(s->lights[3].position, Vec3(1, 3, 0)));
  CHECK(s->lights[3].color == Color(0.5f, 0.25f, 0.0f));
}

TEST_CASE("lang: a light inside a CSG operation is no operand", "[lang][lights]") {
  auto s = load(
      R"XML(<difference><light position="0 5 0"/><box/><sphere radius="0.5"/></difference>)XML");
  CHECK(s->lights.size() == 1);
  ParseResult r = parse("<difference><light/></difference>");
  CHECK_FALSE(r.scene);
  CHECK(messages(r).find("lights.xml:1:29: error: <difference> needs at least one child shape") !=
        std::string::npos);
}

TEST_CASE("lang: lights placed through uses of uses are limited", "[lang][lights]") {
  // Ten lights, ten uses of them, ten uses of those ... seven levels: 10^8 lights from a
  // small file.
  std::string body =
      "<defs><group id=\"l0\"><repeat var=\"i\" count=\"10\"><light/></repeat></group>";
  for (int k = 1; k <= 7; ++k)
    body += "<group id=\"l" + std::to_string(k) + "\"><repeat var=\"i\" count=\"10\"><use ref=\"l" +
            std::to_string(k - 1) + "\"/></repeat></group>";
  body += "</defs><use ref=\"l7\"/>";
  ParseResult r = parse(body);
  CHECK_FALSE(r.scene);
  CHECK(messages(r).find("error: the scene places more than 10000000 lights") != std::string::npos);
}

TEST_CASE("placedLight maps position as a point and directions and axes as vectors",
          "[scenegraph][lights]") {
  Light l;
  l.type = LightType::Area;
  l.position = Vec3(1, 0, 0);
  l.direction = Vec3(0, 0, -1);
  l.u = Vec3(1, 0, 0);
  l.v = Vec3(0, 1, 0);
  const Mat4 m = glm::translate(Mat4(1.0), Vec3(0, 0, 3)) * glm::scale(Mat4(1.0), Vec3(2, 3, 4));
  Light p = placedLight(l, m);
  CHECK(p.position == Vec3(2, 0, 3));
  CHECK(p.direction == Vec3(0, 0, -1));  // normalised again
  CHECK(p.u == Vec3(2, 0, 0));
  CHECK(p.v == Vec3(0, 3, 0));
}

TEST_CASE("lang: an area light with spot attributes is spot-shaped, its cone placed with it",
          "[lang][lights]") {
  auto s = load(R"XML(<defs><group id="lamp">
      <light type="area" position="0 0 0" u="0.6 0 0" v="0 0 0.6" samples="2 2" direction="0 -1 0"
             angle="15" inner="6"/>
    </group></defs>
    <use ref="lamp" transform="rotate-z(90) translate(0 4 0)"/>
    <light type="area" position="0 3 0" u="1 0 0" v="0 0 1" samples="2 2" look-at="3 3 0"/>
    <light type="area" position="0 3 0" u="1 0 0" v="0 0 1" samples="2 2"/>)XML");
  REQUIRE(s->lights.size() == 3);
  // Top-level lights come first (scenegraph/light_placement.h).
  const Light& aimed = s->lights[0];
  CHECK(aimed.hasCone());
  CHECK(close(aimed.direction, Vec3(1, 0, 0)));
  CHECK(aimed.angle == 30.0);  // the spot's default angle
  CHECK(aimed.inner == 30.0);
  CHECK_FALSE(s->lights[1].hasCone());  // no spot attribute: a plain area light
  const Light& lamp = s->lights[2];
  CHECK(lamp.hasCone());
  CHECK(lamp.angle == 15.0);
  CHECK(lamp.inner == 6.0);
  // rotate-z(90) turns -y to +x, and the axis u to +y.
  CHECK(glm::length(lamp.direction - Vec3(1, 0, 0)) <= 1e-12);
  CHECK(glm::length(lamp.u - Vec3(0, 0.6, 0)) <= 1e-12);
  CHECK(close(lamp.position, Vec3(0, 4, 0)));
}
