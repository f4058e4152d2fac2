#include "camera_inside.h"

#include "shape_registry.h"

#include "primitives/transform.h"

#include <exception>

namespace lucent {

namespace {

// The node's world transform under parentWorld; none if it is singular or overflows (the
// world builder reports those).
std::optional<Transform> worldOf(const Node& node, const Transform& parentWorld) {
  auto local = Transform::fromMatrix(node.parentFromNode);
  if (!local) return std::nullopt;
  return local->followedBy(parentWorld);
}

// Is the world point p inside the node, by the shapes' own inside() tests?
bool containsPlain(const Node& node, const Transform& parentWorld, const Vec3& p);

bool contains(const Node& node, const Transform& parentWorld, const Vec3& p) {
  const bool in = containsPlain(node, parentWorld, p);
  if (!node.clip.empty()) {
    // Inside a clipped solid is inside its clips too (POV-Ray's inside test).
    auto world = worldOf(node, parentWorld);
    if (!world) return false;
    for (const auto& c : node.clip)
      if (!contains(*c, *world, p)) return false;
  }
  return node.inverse ? !in : in;
}

// The same, the node's own inverse aside.
bool containsPlain(const Node& node, const Transform& parentWorld, const Vec3& p) {
  auto world = worldOf(node, parentWorld);
  if (!world) return false;
  switch (node.kind) {
    case NodeKind::Shape: {
      if (!node.shape || !isSolid(*node.shape)) return false;
      const Vec3 local = world->pointToObject(p);
      // A mesh's bounding box first: building it (its BVH) only to miss would cost check
      // the time of a render's set-up.
      if (const auto* mesh = std::get_if<MeshSpec>(&*node.shape)) {
        if (!mesh->data || mesh->data->positions.empty()) return false;
        AABB box;
        for (const Vec3& v : mesh->data->positions) box.expand(v);
        if (!box.contains(local)) return false;
      }
      try {
        return makeShape(*node.shape)->inside(local);
      } catch (const std::exception&) {
        return false;  // a shape that cannot be built is the world builder's error to report
      }
    }
    case NodeKind::Use:
      return node.target && contains(*node.target, *world, p);
    case NodeKind::Light:
      return false;
    case NodeKind::Group:
    case NodeKind::Union:
    case NodeKind::Merge:
      for (const auto& c : node.children)
        if (contains(*c, *world, p)) return true;
      return false;
    case NodeKind::Intersection:
      if (node.children.empty()) return false;
      for (const auto& c : node.children)
        if (!contains(*c, *world, p)) return false;
      return true;
    case NodeKind::Difference:
      if (node.children.empty() || !contains(*node.children.front(), *world, p)) return false;
      for (size_t i = 1; i < node.children.size(); ++i)
        if (contains(*node.children[i], *world, p)) return false;
      return true;
  }
  return false;
}

struct Surfaces {
  bool transmissive = false;  // some surface has a transmissive material
  bool ambient = false;       // some surface has an ambient colour it loses from inside
};

// What the materials of the shapes under the node (their own or inherited) have.
void collect(const Scene& scene, const Node& node, uint32_t inherited, Surfaces& out) {
  const uint32_t material = node.material.value_or(inherited);
  switch (node.kind) {
    case NodeKind::Shape:
      if (material < scene.materials.size()) {
        const Material& m = scene.materials[material];
        out.transmissive |= m.isTransmissive();
        // inner-ambient keeps the term from inside: nothing to lose.
        out.ambient |= maxComponent(m.ambient) > 0.0f && !m.innerAmbient;
      }
      return;
    case NodeKind::Use:
      if (node.target) collect(scene, *node.target, material, out);
      return;
    default:
      for (const auto& c : node.children) collect(scene, *c, material, out);
  }
}

// Does seeing the node from inside change the image: are its surfaces opaque, with an
// ambient term to lose? (A sky dome that only emits loses nothing.)
bool losesAmbientInside(const Scene& scene, const Node& node, uint32_t inherited) {
  if (!(maxComponent(scene.render.ambient) > 0.0f)) return false;
  Surfaces s;
  collect(scene, node, inherited, s);
  return !s.transmissive && s.ambient;
}

struct Finder {
  const Scene& scene;
  const Camera& camera;
  Vec3 position;
  std::vector<CameraInSolid>& out;

  // Walks the hierarchy as the world builder does: groups and uses are looked through,
  // shapes and CSG nodes are the objects.
  void walk(const Node& node, const Transform& parentWorld, uint32_t inherited) {
    auto world = worldOf(node, parentWorld);
    if (!world) return;
    const uint32_t material = node.material.value_or(inherited);
    switch (node.kind) {
      case NodeKind::Group:
        for (const auto& c : node.children) walk(*c, *world, material);
        return;
      case NodeKind::Use:
        if (node.target) walk(*node.target, *world, material);
        return;
      default:
        if (!node.isSolid() || !losesAmbientInside(scene, node, inherited)) return;
        if (contains(node, parentWorld, position)) out.push_back({&camera, &node});
        return;
    }
  }
};

}  // namespace

std::vector<CameraInSolid> camerasInsideOpaqueSolids(const Scene& scene) {
  std::vector<CameraInSolid> out;
  for (const Camera& camera : scene.cameras) {
    const Vec3 position = Vec3(camera.transform * Vec4(camera.position, 1.0));
    Finder{scene, camera, position, out}.walk(*scene.root, Transform(), 0);
  }
  return out;
}

}  // namespace lucent
