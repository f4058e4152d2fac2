// The scene side of the world: what flattening works out once for each object and leaf
// (material, medium, transmissive, casting shadows), and the typed hits that carry it.
#include "../primitives/random_items.h"
#include "../render/scene_builder.h"

#include "csg/csg_node.h"
#include "csg/inverted.h"
#include "scenegraph/flatten.h"
#include "scenegraph/world.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

std::unique_ptr<Node> csgNode(NodeKind kind, std::optional<uint32_t> material) {
  auto n = std::make_unique<Node>();
  n->kind = kind;
  n->material = material;
  return n;
}

}  // namespace

TEST_CASE("flatten: each object's medium, transmission and shadow, each leaf's material",
          "[world][flatten]") {
  Scene scene;
  Material glassMaterial, stoneMaterial;
  glassMaterial.transmissive = Color(0.8f);
  stoneMaterial.diffuse = Color(0.5f);
  const uint32_t glass = addMaterial(scene, glassMaterial);
  const uint32_t stone = addMaterial(scene, stoneMaterial);
  // 0: a glass sphere. 1: a disc of stone (a surface: no medium).
  addShape(scene, SphereSpec{Vec3(0.0), 1.0}, glass);
  addShape(scene, DiscSpec{}, stone);
  // 2: a stone box minus a glass sphere: the medium is the first leaf's, stone, and the
  // object transmits through its glass leaf.
  auto diff = csgNode(NodeKind::Difference, stone);
  diff->children.push_back(shapeNode(BoxSpec{Vec3(-1.0), Vec3(1.0)}, std::nullopt));
  diff->children.push_back(shapeNode(SphereSpec{Vec3(1.0), 0.5}, glass));
  scene.root->children.push_back(std::move(diff));
  // 3 and 4: a union whose second child casts no shadow becomes two unions, the one that
  // casts first. Its shadowless child is glass: only the second union transmits.
  auto uni = csgNode(NodeKind::Union, stone);
  uni->children.push_back(shapeNode(SphereSpec{Vec3(3.0), 0.5}, std::nullopt));
  uni->children.push_back(shapeNode(SphereSpec{Vec3(4.0), 0.5}, glass));
  uni->children.back()->shadows = false;
  scene.root->children.push_back(std::move(uni));
  // 5: an inverted glass sphere: a solid whose medium is still its material.
  addShape(scene, SphereSpec{Vec3(-3.0), 0.5}, glass).inverse = true;

  const FlatScene flat = flattenScene(scene, makeShape);
  REQUIRE(flat.objects.size() == 6);
  const Material* glassP = &scene.materials[glass];
  const Material* stoneP = &scene.materials[stone];
  struct Want {
    const Material* medium;
    bool casts, transmits;
  };
  const Want want[] = {{glassP, true, true},  {nullptr, true, false}, {stoneP, true, true},
                       {stoneP, true, false}, {glassP, false, true},  {glassP, true, true}};
  for (size_t i = 0; i < 6; ++i) {
    INFO("object " << i);
    CHECK(flat.objects[i].medium == want[i].medium);
    CHECK(flat.objects[i].castsShadow == want[i].casts);
    CHECK(flat.objects[i].transmits == want[i].transmits);
  }
  CHECK(dynamic_cast<const CsgNode*>(flat.objects[2].shape.get()));
  CHECK(dynamic_cast<const Inverted*>(flat.objects[5].shape.get()));

  // Leaves in scene order, each Instance tagged with its index.
  REQUIRE(flat.leaves.size() == 7);
  const uint32_t leafMaterial[] = {glass, stone, stone, glass, stone, glass, glass};
  for (uint32_t i = 0; i < 7; ++i) {
    INFO("leaf " << i);
    const WorldLeaf& leaf = flat.leaves[i];
    CHECK(leaf.instance->tag() == i);
    CHECK(leaf.materialIndex == leafMaterial[i]);
    CHECK(leaf.material == &scene.materials[leafMaterial[i]]);
    CHECK(leaf.transmissive == (leafMaterial[i] == glass));
    // Every leaf is a solid but the disc.
    CHECK(leaf.medium == (i == 1 ? nullptr : leaf.material));
  }
}

TEST_CASE("World: a typed hit names the leaf the geometry hit", "[world][flatten]") {
  // Spheres kept in world space by the aggregate, spheres and boxes through their
  // Instance, leaves inside CSG nodes, and a plane: the hit's tag leads to its leaf.
  Scene scene;
  std::vector<uint32_t> materials;
  for (int k = 0; k < 5; ++k) {
    Material m;
    m.diffuse = Color(0.1f * float(k));
    if (k % 2) m.transmissive = Color(0.5f);
    materials.push_back(addMaterial(scene, m));
  }
  std::mt19937_64 rng(5);
  for (int i = 0; i < 300; ++i) {
    const Vec3 c = testing::randomVec(rng, -8, 8);
    const uint32_t m = materials[size_t(i) % materials.size()];
    switch (i % 4) {
      case 0:
        addShape(scene, SphereSpec{c, 0.4}, m);
        break;
      case 1:
        addShape(scene, SphereSpec{Vec3(0.0), 0.4}, m,
                 glm::scale(glm::translate(Mat4(1.0), c), Vec3(1.0, 2.0, 0.5)));
        break;
      case 2:
        addShape(scene, BoxSpec{c - Vec3(0.3), c + Vec3(0.3)}, m);
        break;
      default: {
        auto inter = csgNode(NodeKind::Intersection, std::nullopt);
        inter->children.push_back(shapeNode(SphereSpec{c, 0.5}, m));
        inter->children.push_back(shapeNode(BoxSpec{c - Vec3(0.4), c + Vec3(0.4)},
                                            materials[(size_t(i) + 1) % materials.size()]));
        scene.root->children.push_back(std::move(inter));
      }
    }
  }
  addShape(scene, PlaneSpec{Vec3(0, 1, 0), -9.0}, materials[0]);
  World world(scene);
  REQUIRE(world.inlineSphereCount() == 75);
  size_t hits = 0, clear = 0;
  for (const Ray& ray : testing::randomRays(rng, 5000, 10.0)) {
    WorldHit typed;
    Hit plain;
    REQUIRE(world.intersect(ray, typed) == world.intersect(ray, plain));
    if (!plain.found()) continue;
    ++hits;
    REQUIRE(typed.hit.shape == plain.shape);
    REQUIRE(typed.t() == plain.t);
    REQUIRE(&typed.leaf() == &world.leaf(plain));
    REQUIRE(typed.leaf().instance == plain.shape);
    WorldHit glass;
    if (world.intersectTransmissive(ray, glass)) {
      ++clear;
      REQUIRE(glass.leaf().instance == glass.hit.shape);
    }
  }
  CHECK(hits > 2000);
  CHECK(clear > 500);
}

TEST_CASE("flatten: a bicubic patch with flatness-space=\"world\" is cut where it is placed",
          "[world][flatten]") {
  // S(u, v) = (u, u², v); flatness 0.01 cuts it less in its own space than scaled by 4.
  const double yOf[4] = {0.0, 0.0, 1.0 / 3.0, 1.0};
  PatchPoints points{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      points[static_cast<size_t>(4 * i + j)] = Vec3(i / 3.0, yOf[i], j / 3.0);
  BicubicPatchSpec patch;
  patch.points = std::make_shared<const PatchPoints>(points);
  patch.flatness = 0.01;
  patch.uSteps = patch.vSteps = 6;
  Scene scene;
  const uint32_t m = addMaterial(scene, Material{});
  const Mat4 scale4(4.0, 0, 0, 0, 0, 4.0, 0, 0, 0, 0, 4.0, 0, 0, 0, 0, 1.0);
  addShape(scene, patch, m, scale4);  // flatness in its own space
  patch.flatnessInWorld = true;
  addShape(scene, patch, m, scale4);  // in the world: cut as the points scaled by 4
  const FlatScene flat = flattenScene(scene, makeShape);
  REQUIRE(flat.leaves.size() == 2);
  PatchPoints scaled = points;
  for (Vec3& q : scaled) q *= 4.0;
  const size_t own = bicubicPatchMesh(points, 0.01, 6, 6)->triangles.size();
  const size_t world = bicubicPatchMesh(scaled, 0.01, 6, 6)->triangles.size();
  CHECK(own < world);
  CHECK(flat.leaves[0].instance->shape().triangleCount() == own);
  CHECK(flat.leaves[1].instance->shape().triangleCount() == world);
}
