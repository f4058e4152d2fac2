// A white floor y = 0 lit from straight above, with grey emissive boxes ("blockers") placed
// over it at y in [2, 3]: the scene of the tests of what casts a shadow and what the camera
// sees (no_shadow_test.cpp, visibility_test.cpp).
#pragma once

#include "scene_builder.h"

#include <memory>
#include <utility>
#include <vector>

namespace lucent::test {

struct LitFloor {
  Scene scene;
  uint32_t grey;
  LitFloor() {
    Material floor;
    floor.diffuse = Color(1.0f);
    addShape(scene, PlaneSpec{Vec3(0, 1, 0), 0.0}, addMaterial(scene, floor));
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = Vec3(0, -1, 0);
    scene.lights.push_back(sun);
    Material m;
    m.emissive = Color(0.25f);
    grey = addMaterial(scene, m);
  }
  // The colour at floor point (x, 0, 0), seen from above at an angle that passes beside
  // the blockers.
  Color floorAt(double x) {
    World world(scene);
    return traceOne(world, Ray(Vec3(x, 1, 3), glm::normalize(Vec3(0, -1, -3))));
  }
  // Straight down at x: a blocker's emission if the camera sees it, else the floor.
  Color fromAbove(double x) {
    World world(scene);
    return traceOne(world, Ray(Vec3(x, 5, 0), Vec3(0, -1, 0)));
  }
  // A box 1 wide over floor point x.
  std::unique_ptr<Node> blocker(double x) {
    return shapeNode(BoxSpec{Vec3(x - 0.5, 2, -0.5), Vec3(x + 0.5, 3, 0.5)}, grey);
  }
  Node& add(std::unique_ptr<Node> n) {
    scene.root->children.push_back(std::move(n));
    return *scene.root->children.back();
  }
  Node& csg(NodeKind kind, std::vector<std::unique_ptr<Node>> children) {
    auto n = std::make_unique<Node>();
    n->kind = kind;
    for (auto& c : children) n->children.push_back(std::move(c));
    return add(std::move(n));
  }
};

}  // namespace lucent::test
