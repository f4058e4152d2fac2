// shadows="false" on geometry nodes (Node::shadows): the node casts no shadow but is still
// seen; a union's children keep their own flags, a merge, intersection or difference casts
// its shadow as a whole (as POV-Ray's no_shadow).
#include "lit_floor.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

std::vector<std::unique_ptr<Node>> nodes(std::unique_ptr<Node> a, std::unique_ptr<Node> b) {
  std::vector<std::unique_ptr<Node>> v;
  v.push_back(std::move(a));
  v.push_back(std::move(b));
  return v;
}

}  // namespace

TEST_CASE("shadows=false: the floor under the node is lit, the node is still seen",
          "[render][no-shadow]") {
  LitFloor f;
  Node& box = f.add(f.blocker(0.0));
  CHECK(f.floorAt(0.0) == Color(0.0f));
  box.shadows = false;
  CHECK(f.floorAt(0.0) == Color(1.0f));
  // A camera ray straight down meets the box and its emission.
  World world(f.scene);
  CHECK(traceOne(world, Ray(Vec3(0, 5, 0), Vec3(0, -1, 0))) == Color(0.25f));
}

TEST_CASE("shadows=false: a transparent node does not even filter the light",
          "[render][no-shadow]") {
  LitFloor f;
  Material glass;
  glass.transmissive = Color(0.5f);
  Node& box = f.add(
      shapeNode(BoxSpec{Vec3(-0.5, 2, -0.5), Vec3(0.5, 3, 0.5)}, addMaterial(f.scene, glass)));
  CHECK(f.floorAt(0.0) == Color(0.25f));  // two crossings of k_t = 0.5
  box.shadows = false;
  CHECK(f.floorAt(0.0) == Color(1.0f));
}

TEST_CASE("shadows=false: inherited through groups and <use>", "[render][no-shadow]") {
  LitFloor f;
  auto def = f.blocker(0.0);
  const Node* target = def.get();
  f.scene.defs.push_back(std::move(def));
  auto use = std::make_unique<Node>();
  use->kind = NodeKind::Use;
  use->target = target;
  use->shadows = false;
  f.add(std::move(use));
  auto group = std::make_unique<Node>();
  group->shadows = false;
  group->children.push_back(f.blocker(2.0));
  f.add(std::move(group));
  CHECK(f.floorAt(0.0) == Color(1.0f));
  CHECK(f.floorAt(2.0) == Color(1.0f));
}

TEST_CASE("shadows=false: a union's children keep their own, a difference casts as a whole",
          "[render][no-shadow]") {
  LitFloor f;
  auto shadowless = f.blocker(0.0);
  shadowless->shadows = false;
  f.csg(NodeKind::Union, nodes(std::move(shadowless), f.blocker(2.0)));
  CHECK(f.floorAt(0.0) == Color(1.0f));
  CHECK(f.floorAt(2.0) == Color(0.0f));

  // A difference whose second operand (a small box inside the first) has shadows=false:
  // ignored. The same difference with shadows=false: no shadow.
  auto hole = shapeNode(BoxSpec{Vec3(3.9, 2.4, -0.1), Vec3(4.1, 2.6, 0.1)}, f.grey);
  hole->shadows = false;
  f.csg(NodeKind::Difference, nodes(f.blocker(4.0), std::move(hole)));
  CHECK(f.floorAt(4.0) == Color(0.0f));
  Node& whole = f.csg(
      NodeKind::Difference,
      nodes(f.blocker(6.0), shapeNode(BoxSpec{Vec3(5.9, 2.4, -0.1), Vec3(6.1, 2.6, 0.1)}, f.grey)));
  whole.shadows = false;
  CHECK(f.floorAt(6.0) == Color(1.0f));
}
