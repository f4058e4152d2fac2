// <repeat>, <if>, local <param>s, parameterised <use>, text parameters and <animation>:
// the valid scenes of tests/lang/valid parse into the plain graph they describe (node
// counts, each generated sphere's centre and radius, lights, ids, use targets), -D and
// ParseOptions::frame pick the parameters and the moment, and a repeat-made scene renders
// exactly as the same scene written out by hand.
#include "lang/parser.h"
#include "povray/pov_export.h"
#include "render/renderer.h"
#include "render/scene_check.h"
#include "scenegraph/world.h"
#include "valid_scene_loading.h"

#include "../render/scene_builder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <functional>
#include <string>

namespace fs = std::filesystem;
using namespace lucent;

namespace {

using testing::load;
using testing::messages;
using testing::validDir;

std::unique_ptr<Scene> loadString(const std::string& xml, const ParseOptions& options = {}) {
  ParseResult r = parseSceneString(xml, "inline.xml", options);
  INFO(messages(r));
  REQUIRE(r.scene != nullptr);
  REQUIRE(r.diagnostics.all().empty());
  return std::move(r.scene);
}

// The errors of a scene that must be refused, one per line.
std::string errorsOf(const std::string& xml, const ParseOptions& options = {}) {
  ParseResult r = parseSceneString(xml, "inline.xml", options);
  CHECK(r.scene == nullptr);
  return messages(r);
}

const Node& child(const Node& n, size_t i) {
  REQUIRE(i < n.children.size());
  return *n.children[i];
}

const SphereSpec& sphere(const Node& n) {
  REQUIRE(n.kind == NodeKind::Shape);
  REQUIRE(n.shape);
  REQUIRE(std::holds_alternative<SphereSpec>(*n.shape));
  return std::get<SphereSpec>(*n.shape);
}

size_t countNodes(const Node& n) {
  size_t c = 1;
  for (const auto& k : n.children) c += countNodes(*k);
  return c;
}

bool same(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

}  // namespace

TEST_CASE("repeat: count 0 makes nothing, count N makes N instances with i = 0 .. N-1",
          "[lang][repeat]") {
  auto s = load("repeat.xml");
  const Node& root = *s->root;
  // post0..2, grid, union, difference, use row, use post1: the count-0 repeat made nothing.
  REQUIRE(root.children.size() == 8);
  for (int i = 0; i < 3; ++i) {
    INFO("instance " << i);
    const Node& post = child(root, i);
    CHECK(post.id == "post" + std::to_string(i));
    CHECK(same(sphere(post).center, Vec3(2.0 * i, 0, 0)));
    CHECK(sphere(post).radius == 0.1 + 0.1 * i);  // the same double as the expression's
  }
  // The lights of the top-level repeat, one per instance; none from the count-0 repeat.
  REQUIRE(s->lights.size() == 3);
  for (int i = 0; i < 3; ++i) CHECK(same(s->lights[i].position, Vec3(i, 10, 0)));
  // Total: the root, 8 children, 6 grid spheres, 2 boxes, 1 + 3 in the difference.
  CHECK(countNodes(root) == 1 + 8 + 6 + 2 + 4);
}

TEST_CASE(
    "repeat: nested repeats run the inner one per outer instance, counts come from expressions",
    "[lang][repeat]") {
  auto s = load("repeat.xml");
  const Node& grid = child(*s->root, 3);
  CHECK(grid.id == "grid");
  // count n - 2 = 2 outer, n / 2 + 1 = 3 inner, in the order written: x outer, y inner.
  REQUIRE(grid.children.size() == 6);
  for (int x = 0; x < 2; ++x)
    for (int y = 0; y < 3; ++y) {
      INFO("x " << x << " y " << y);
      const SphereSpec& b = sphere(child(grid, 3 * x + y));
      CHECK(same(b.center, Vec3(x, y, 10 * x + y)));
      CHECK(b.radius == 0.25);
    }
}

TEST_CASE("repeat: inside union, difference and defs, ids made per instance can be referenced",
          "[lang][repeat]") {
  auto s = load("repeat.xml");
  const Node& root = *s->root;
  const Node& u = child(root, 4);
  REQUIRE(u.kind == NodeKind::Union);
  REQUIRE(u.children.size() == 2);
  for (int k = 0; k < 2; ++k) {
    const auto& b = std::get<BoxSpec>(*child(u, k).shape);
    CHECK(same(b.min, Vec3(k, 0, 0)));
    CHECK(same(b.max, Vec3(k + 1, 1, 1)));
  }
  const Node& d = child(root, 5);
  REQUIRE(d.kind == NodeKind::Difference);
  REQUIRE(d.children.size() == 4);
  CHECK(std::holds_alternative<BoxSpec>(*child(d, 0).shape));  // the first stays the minuend
  for (int k = 0; k < 3; ++k) CHECK(same(sphere(child(d, k + 1)).center, Vec3(k - 1, 1, 0)));
  // defs: the repeat made the definition's two spheres; the use shares it.
  REQUIRE(s->defs.size() == 1);
  const Node& row = *s->defs[0];
  CHECK(row.id == "row");
  REQUIRE(row.children.size() == 2);
  CHECK(same(sphere(child(row, 1)).center, Vec3(1, 5, 0)));
  CHECK(child(root, 6).target == &row);
  // id="post${i}" registered the instance post1 under its own id.
  CHECK(child(root, 7).kind == NodeKind::Use);
  CHECK(child(root, 7).target == &child(root, 1));
}

TEST_CASE("if: a test that is not 0 instantiates the children, anywhere a repeat may stand",
          "[lang][if]") {
  auto s = load("if.xml");
  const Node& root = *s->root;
  // Spheres 1, 3 and 5 (tests 1, show == 1 && 2 > 1, -0.5), then the group, the union, the
  // use and the sphere of the <if> with a <param>; the tests 0 and show - 1 made nothing.
  REQUIRE(root.children.size() == 7);
  CHECK(sphere(child(root, 0)).radius == 1);
  CHECK(sphere(child(root, 1)).radius == 3);
  CHECK(sphere(child(root, 2)).radius == 5);
  REQUIRE(s->lights.size() == 1);  // from the true test only
  CHECK(same(s->lights[0].position, Vec3(0, 5, 0)));
  const Node& evens = child(root, 3);
  REQUIRE(evens.children.size() == 3);  // i % 2 == 0 for i = 0, 2, 4
  for (int k = 0; k < 3; ++k) CHECK(same(sphere(child(evens, k)).center, Vec3(2 * k, 0, 0)));
  const Node& u = child(root, 4);
  REQUIRE(u.kind == NodeKind::Union);
  REQUIRE(u.children.size() == 1);
  CHECK(sphere(child(u, 0)).radius == 6);
  REQUIRE(s->defs.size() == 1);
  const Node& maybe = *s->defs[0];
  REQUIRE(maybe.children.size() == 1);  // $show is 1: the box; !show is 0: no sphere
  CHECK(std::holds_alternative<BoxSpec>(*child(maybe, 0).shape));
  CHECK(child(root, 5).target == &maybe);
  CHECK(sphere(child(root, 6)).radius == 7);  // the <if>'s own parameter
}

TEST_CASE("if: -D changes what a test selects", "[lang][if]") {
  ParseOptions o;
  o.defines["show"] = "0";
  auto s = load("if.xml", o);
  const Node& root = *s->root;
  // Now the third test is false and show - 1 = -1 is true.
  REQUIRE(root.children.size() == 7);
  CHECK(sphere(child(root, 1)).radius == 4);
  REQUIRE(s->lights.size() == 1);
  CHECK(same(s->lights[0].position, Vec3(0, 6, 0)));
  const Node& maybe = *s->defs[0];
  REQUIRE(maybe.children.size() == 1);
  CHECK(std::holds_alternative<SphereSpec>(*child(maybe, 0).shape));
}

namespace {
// The radii of local_params.xml's spheres, depth first.
std::vector<double> radii(const Node& n) {
  std::vector<double> out;
  std::function<void(const Node&)> walk = [&](const Node& m) {
    if (m.kind == NodeKind::Shape) out.push_back(sphere(m).radius);
    for (const auto& k : m.children) walk(*k);
  };
  walk(n);
  return out;
}
}  // namespace

TEST_CASE("local params: visible inside their element only, hiding the outer one in that subtree",
          "[lang][params]") {
  auto s = load("local_params.xml");
  // top r = 1; the group's r = 2 (and s = r * 3 = 6 inside it); after the group r is 1
  // again; the union's r = 3; the repeat's r = 4 + i; the leaf's q = r + 0.5 with the top r.
  CHECK(radii(*s->root) == std::vector<double>{1, 2, 6, 2, 1, 3, 4, 5, 1.5, 1});
}

TEST_CASE("local params: -D sets only the top-level parameter, not the local ones that hide it",
          "[lang][params]") {
  ParseOptions o;
  o.defines["r"] = "10";
  auto s = load("local_params.xml", o);
  CHECK(radii(*s->root) == std::vector<double>{10, 2, 6, 2, 10, 3, 4, 5, 10.5, 10});
  // A -D of a name that is only declared locally leaves the local one alone.
  ParseOptions local;
  local.defines["s"] = "100";
  ParseResult r = parseSceneFile((validDir() / "local_params.xml").string(), local);
  REQUIRE(r.scene);
  CHECK(radii(*r.scene->root) == std::vector<double>{1, 2, 6, 2, 1, 3, 4, 5, 1.5, 1});
}

TEST_CASE(
    "parameterised use: the use's values hide the defaults, a use without them shares the node",
    "[lang][use]") {
  auto s = load("parameterised_use.xml");
  const Node& root = *s->root;
  REQUIRE(s->defs.size() == 2);
  const Node& post = *s->defs[0];
  const Node& ball = *s->defs[1];
  // The definition itself, read with its defaults h = 2, w = 0.1.
  const auto& own = std::get<CylinderSpec>(*child(post, 0).shape);
  CHECK(same(own.cap, Vec3(0, 2, 0)));
  CHECK(own.radius == 0.1);
  REQUIRE(root.children.size() == 8);
  // Without parameters: the same node (instancing), twice.
  CHECK(child(root, 0).kind == NodeKind::Use);
  CHECK(child(root, 0).target == &post);
  CHECK(child(root, 3).kind == NodeKind::Use);
  CHECK(child(root, 3).target == &post);
  CHECK(child(root, 7).target == &ball);
  // With h = 5: a copy of the definition, w keeps its default.
  const Node& tall = child(root, 1);
  REQUIRE(tall.children.size() == 1);
  const auto& t = std::get<CylinderSpec>(*child(child(tall, 0), 0).shape);
  CHECK(same(t.cap, Vec3(0, 5, 0)));
  CHECK(t.radius == 0.1);
  // With w = ${h * 0.3}: evaluated where the use stands (top-level h = 1); the definition's
  // own h = 2 stays for the cap.
  const Node& wide = child(root, 2);
  REQUIRE(wide.children.size() == 1);
  const auto& w = std::get<CylinderSpec>(*child(child(wide, 0), 0).shape);
  CHECK(same(w.cap, Vec3(0, 2, 0)));
  CHECK(w.radius == 1 * 0.3);
  // Inside a repeat: one instance per i, each with its own size, and its own transform.
  for (int i = 0; i < 3; ++i) {
    INFO("i = " << i);
    const Node& use = child(root, 4 + i);
    REQUIRE(use.children.size() == 1);
    CHECK(sphere(child(use, 0)).radius == 0.1 * (i + 1));
    CHECK(use.parentFromNode[3][0] == i);
  }
  CHECK(sphere(ball).radius == 0.5);  // the definition keeps its default
}

TEST_CASE("parameterised use: its parameters are visible in its own attributes too",
          "[lang][use]") {
  auto s = loadString(R"X(<scene version="1"><camera/>
    <defs><sphere id="ball" radius="$size"><param name="size" value="0.5"/></sphere></defs>
    <use ref="ball" transform="translate(${2 * size} 0 0)"><param name="size" value="0.25"/></use>
  </scene>)X");
  const Node& use = child(*s->root, 0);
  CHECK(use.parentFromNode[3][0] == 0.5);  // 2 * the use's size
  REQUIRE(use.children.size() == 1);
  CHECK(sphere(child(use, 0)).radius == 0.25);
}

TEST_CASE("parameterised use: its values are read around the use, so a name may use its outer self",
          "[lang][use]") {
  auto s = loadString(R"X(<scene version="1"><camera/>
    <param name="size" value="0.5"/>
    <defs><sphere id="ball" radius="$size"/></defs>
    <group><param name="size" value="0.75"/>
      <use ref="ball"><param name="size" value="${size * 2}"/><param name="other" value="${size}"/></use>
    </group>
  </scene>)X");
  const Node& use = child(child(*s->root, 0), 0);
  REQUIRE(use.children.size() == 1);
  CHECK(sphere(child(use, 0)).radius == 1.5);  // the group's 0.75, doubled
}

TEST_CASE("text parameters: ${name} of a non-numeric parameter is its text, $$ is a literal $",
          "[lang][params]") {
  auto s = load("text_params.xml");
  REQUIRE(s->cameras.size() == 1);
  CHECK(s->cameras[0].name == "$cam");
  REQUIRE(s->root->children.size() == 2);
  CHECK(same(sphere(child(*s->root, 0)).center, Vec3(1, 2, 3)));
  CHECK(same(sphere(child(*s->root, 1)).center, Vec3(1, 2, 3)));
  CHECK(sphere(child(*s->root, 1)).radius == 0.25);
  const Node& red = child(*s->root, 0);
  REQUIRE(red.material);
  const Color& d = s->materials[*red.material].diffuse;
  CHECK(d.r == 1.0f);
  CHECK(d.g == 0.0f);
  CHECK(d.b == 0.0f);
}

namespace {
// The centre of animation.xml's sphere is (clock, frame, frames).
Vec3 moment(const Scene& s) { return sphere(child(*s.root, 0)).center; }
}  // namespace

TEST_CASE("animation: clock runs from clock-from to clock-to over frames 1..N",
          "[lang][animation]") {
  for (int f = 1; f <= 5; ++f) {
    ParseOptions o;
    o.frame = f;
    auto s = load("animation.xml", o);
    const double clock = 1.0 + 2.0 * (f - 1) / 4.0;  // 1, 1.5, 2, 2.5, 3
    INFO("frame " << f);
    CHECK(s->animation.present);
    CHECK(s->animation.frames == 5);
    CHECK(s->frame == f);
    CHECK(s->clock == clock);
    CHECK(same(moment(*s), Vec3(clock, f, 5)));
  }
}

TEST_CASE("animation: cyclic divides by N, so the last frame leads back to the first",
          "[lang][animation]") {
  const std::string xml = R"(<scene version="1"><camera/>
    <animation frames="4" clock-from="0" clock-to="360" cyclic="true"/>
    <sphere center="${clock} ${frame} ${frames}"/></scene>)";
  for (int f = 1; f <= 4; ++f) {
    ParseOptions o;
    o.frame = f;
    auto s = loadString(xml, o);
    INFO("frame " << f);
    CHECK(s->clock == 90.0 * (f - 1));  // 0, 90, 180, 270: never 360
    CHECK(same(moment(*s), Vec3(90.0 * (f - 1), f, 4)));
  }
}

TEST_CASE("animation: one frame has clock = clock-from, no <animation> is frame 1 of 1 at clock 0",
          "[lang][animation]") {
  auto one = loadString(
      R"(<scene version="1"><camera/><animation frames="1" clock-from="0.75" clock-to="9"/>
    <sphere center="${clock} ${frame} ${frames}"/></scene>)");
  CHECK(one->clock == 0.75);
  CHECK(same(moment(*one), Vec3(0.75, 1, 1)));
  auto none = loadString(
      R"(<scene version="1"><camera/><sphere center="${clock} ${frame} ${frames}"/></scene>)");
  CHECK_FALSE(none->animation.present);
  CHECK(none->frame == 1);
  CHECK(none->clock == 0);
  CHECK(same(moment(*none), Vec3(0, 1, 1)));
}

TEST_CASE("animation: -D clock=0.25 and -D frame=3 render one moment", "[lang][animation]") {
  ParseOptions c;
  c.defines["clock"] = "0.25";
  auto s = load("animation.xml", c);
  CHECK(s->clock == 0.25);
  CHECK(same(moment(*s), Vec3(0.25, 1, 5)));
  ParseOptions f;
  f.defines["frame"] = "3";
  auto t = load("animation.xml", f);
  CHECK(t->frame == 3);
  CHECK(t->clock == 2.0);
  CHECK(same(moment(*t), Vec3(2, 3, 5)));
  // -D frame wins over the frame asked for by the caller.
  f.frame = 5;
  CHECK(load("animation.xml", f)->frame == 3);
  // Without <animation>, -D clock still sets the clock.
  auto none = loadString(
      R"(<scene version="1"><camera/><sphere center="${clock} ${frame} ${frames}"/></scene>)", c);
  CHECK(same(moment(*none), Vec3(0.25, 1, 1)));
}

TEST_CASE("animation: a frame outside 1..N is an error", "[lang][animation]") {
  const std::string xml = R"(<scene version="1"><camera/><animation frames="3"/><sphere/></scene>)";
  ParseOptions d;
  d.defines["frame"] = "4";
  CHECK_THAT(errorsOf(xml, d), Catch::Contains("frame 4 does not exist: the scene has 3 frames"));
  ParseOptions z;
  z.frame = 0;
  CHECK_THAT(errorsOf(xml, z), Catch::Contains("frame 0 does not exist: the scene has 3 frames"));
}

namespace {
std::unique_ptr<Scene> parsed(const std::string& xml) {
  ParseResult r = parseSceneString(xml, "render.xml");
  INFO(messages(r));
  REQUIRE(r.scene);
  return std::move(r.scene);
}

Image renderString(const std::string& xml) {
  ParseResult r = parseSceneString(xml, "render.xml");
  INFO(messages(r));
  REQUIRE(r.scene);
  World world(*r.scene);
  Renderer renderer(world, r.scene->cameras[0]);
  return renderer.render().image;
}
}  // namespace

TEST_CASE("repeat: a scene made by repeats renders exactly as the same scene written out",
          "[lang][repeat][render]") {
  const std::string head = R"(<scene version="1">
  <render width="20" height="20" samples="1"/>
  <camera position="0 1 7" look-at="0 0.9 0"/>
  <material id="m" diffuse="0.7 0.5 0.3"/>
)";
  const std::string repeated = head + R"(
  <repeat var="i" count="2">
    <light type="point" position="${6 * i - 3} 6 4"/>
  </repeat>
  <repeat var="i" count="3">
    <repeat var="j" count="2">
      <if test="${i != 1 || j == 0}">
        <sphere center="${2 * i - 2} ${1.75 * j} 0" radius="${0.75 + 0.125 * j}" material="m"/>
      </if>
    </repeat>
  </repeat>
</scene>)";
  const std::string literal = head + R"(
  <light type="point" position="-3 6 4"/>
  <light type="point" position="3 6 4"/>
  <sphere center="-2 0 0" radius="0.75" material="m"/>
  <sphere center="-2 1.75 0" radius="0.875" material="m"/>
  <sphere center="0 0 0" radius="0.75" material="m"/>
  <sphere center="2 0 0" radius="0.75" material="m"/>
  <sphere center="2 1.75 0" radius="0.875" material="m"/>
</scene>)";
  Image a = renderString(repeated);
  Image b = renderString(literal);
  REQUIRE(a.width == 20);
  CHECK(test::sameBits(a, b));
  // Not a vacuous comparison: the spheres cover part of the picture, and one sphere less
  // changes it.
  int lit = 0;
  for (const Color& c : a.pixels)
    if (c.r > 0.0f) ++lit;
  INFO("lit pixels: " << lit);
  CHECK(lit > 40);
  std::string fewer = literal;
  fewer.erase(
      fewer.find("  <sphere center=\"2 1.75 0\""),
      std::string("  <sphere center=\"2 1.75 0\" radius=\"0.875\" material=\"m\"/>\n").size());
  CHECK_FALSE(test::sameBits(a, renderString(fewer)));
  // export-pov writes the expanded scene: the same file as for the scene written out, but
  // for the comments that say where each element stands in the source.
  auto withoutSourceNotes = [](const std::string& pov) {
    std::string out;
    size_t start = 0;
    while (start < pov.size()) {
      size_t end = pov.find('\n', start);
      if (end == std::string::npos) end = pov.size();
      std::string line = pov.substr(start, end - start);
      size_t note = line.find("  // <");
      if (note != std::string::npos && line.find("render.xml:", note) != std::string::npos)
        line.resize(note);
      out += line + "\n";
      start = end + 1;
    }
    return out;
  };
  PovExport pa = exportPov(*parsed(repeated));
  PovExport pb = exportPov(*parsed(literal));
  REQUIRE(pa.ok());
  CHECK(withoutSourceNotes(pa.text) == withoutSourceNotes(pb.text));
  CHECK(pa.text.find("sphere {") != std::string::npos);
}
