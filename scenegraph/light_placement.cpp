#include "light_placement.h"

#include "light_group.h"
#include "located_error.h"

#include <fmt/format.h>

#include <cmath>
#include <unordered_map>

namespace lucent {

namespace {

bool finite(const Mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

// How many lights a walk from the node places, counted once per node (a definition used a
// thousand times is counted once) and saturated just past the limit.
class LightCounter {
 public:
  explicit LightCounter(size_t limit) : cap_(limit + 1) {}

  size_t of(const Node& n) {
    if (n.kind == NodeKind::Light) return 1;
    if (auto it = memo_.find(&n); it != memo_.end()) return it->second;
    size_t count = 0;
    if (n.kind == NodeKind::Use) {
      if (n.target) count = of(*n.target);
    } else {
      for (const auto& c : n.children) count = std::min(cap_, count + of(*c));
    }
    memo_[&n] = count;
    return count;
  }

 private:
  size_t cap_;
  std::unordered_map<const Node*, size_t> memo_;
};

// `group`: the light group instance a light reached here belongs to (0: none); `groups`
// counts the instances met, in flattenScene's order (light_group.h).
void place(const Node& n, const Mat4& parentWorld, uint32_t group, uint32_t& groups,
           std::vector<Light>& out) {
  const Mat4 world = parentWorld * n.parentFromNode;
  switch (n.kind) {
    case NodeKind::Light: {
      if (!finite(world))
        throw LocatedError(n.loc, "the transforms down to this light multiply beyond double range");
      Light placed = placedLight(*n.light, world);
      const bool flat =
          !(glm::length(placed.direction) > 0.0) ||
          (placed.type == LightType::Area && !(glm::length(glm::cross(placed.u, placed.v)) > 0.0));
      if (flat) throw LocatedError(n.loc, "the transforms down to this light scale it to nothing");
      placed.group = group;
      out.push_back(placed);
      return;
    }
    case NodeKind::Use:
      // The referenced node's own transform applies first, then the <use>'s.
      if (n.target) place(*n.target, world, group, groups, out);
      return;
    default: {
      // A light group's own lights are its light children; lights deeper are global.
      const uint32_t mine = n.lightGroup ? ++groups : 0;
      for (const auto& c : n.children) place(*c, world, c->isLight() ? mine : 0, groups, out);
    }
  }
}

}  // namespace

Light placedLight(const Light& local, const Mat4& worldFromLight) {
  Light l = local;
  const Mat3 linear(worldFromLight);
  l.position = Vec3(worldFromLight * Vec4(local.position, 1.0));
  const Vec3 d = linear * local.direction;
  const double len = glm::length(d);
  l.direction = len > 0.0 ? d / len : Vec3(0.0);
  l.u = linear * local.u;
  l.v = linear * local.v;
  l.worldFromLight = worldFromLight;
  return l;
}

std::vector<Light> placeLights(const Scene& scene, size_t limit) {
  LightCounter counter(limit);
  size_t total = 0;
  for (const Node* top : {scene.lightRoot.get(), scene.root.get()})
    for (const auto& c : top->children) {
      total += counter.of(*c);
      if (total > limit)
        throw LocatedError(c->loc,
                           fmt::format("the scene places more than {} lights (each <use> of a node "
                                       "holding lights places them again); this node is where the "
                                       "count crosses the limit",
                                       limit));
    }
  std::vector<Light> lights;
  lights.reserve(total);
  uint32_t groups = 0;
  place(*scene.lightRoot, Mat4(1.0), 0, groups, lights);
  place(*scene.root, Mat4(1.0), 0, groups, lights);
  return lights;
}

}  // namespace lucent
