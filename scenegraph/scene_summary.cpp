#include "scene_summary.h"

#include "shape_registry.h"

#include <algorithm>
#include <sstream>
#include <unordered_map>

namespace lucent {

namespace {

long long triangleCount(const ShapeSpec& spec) { return shapeTypeOf(spec).triangles(spec); }

// What a node contributes to the world, memoised per node: a node used many times is
// counted once per use without walking it again (the parser has ruled out cycles and
// limited the depth, so the recursion is bounded).
struct Expansion {
  long long instances = 0, triangles = 0;
  int csgDepth = 0;
};

class Expander {
 public:
  Expansion of(const Node& n) {
    if (auto it = memo_.find(&n); it != memo_.end()) return it->second;
    Expansion e;
    switch (n.kind) {
      case NodeKind::Shape:
        e.instances = 1;
        e.triangles = n.shape ? triangleCount(*n.shape) : 0;
        break;
      case NodeKind::Use:
        if (n.target) e = of(*n.target);
        break;
      default:
        for (const auto& c : n.children) {
          Expansion ce = of(*c);
          e.instances += ce.instances;
          e.triangles += ce.triangles;
          e.csgDepth = std::max(e.csgDepth, ce.csgDepth);
        }
        if (n.isCsg()) ++e.csgDepth;
    }
    memo_[&n] = e;
    return e;
  }

 private:
  std::unordered_map<const Node*, Expansion> memo_;
};

void countNodes(const Node& n, std::map<std::string, int>& out) {
  if (n.kind == NodeKind::Light) return;  // counted among the lights, where they are placed
  ++out[n.element];
  for (const auto& c : n.children) countNodes(*c, out);
}

template <class Map>
std::string breakdown(const Map& m) {
  std::string s;
  for (const auto& [name, count] : m)
    s += (s.empty() ? "" : ", ") + name + ": " + std::to_string(count);
  return s;
}

template <class Map>
int total(const Map& m) {
  int t = 0;
  for (const auto& [name, count] : m) t += count;
  return t;
}

}  // namespace

SceneCounts countScene(const Scene& scene) {
  SceneCounts c;
  for (const auto& child : scene.root->children) countNodes(*child, c.nodes);
  for (const auto& d : scene.defs) countNodes(*d, c.nodes);
  c.defs = static_cast<int>(scene.defs.size());
  for (const Light& l : scene.lights) ++c.lights[std::string(lightTypeInfo(l.type).name)];
  for (const Camera& cam : scene.cameras) ++c.cameras[cameraTypeName(cam.type)];
  c.materials = static_cast<int>(scene.materials.size()) - 1;
  Expansion e = Expander().of(*scene.root);
  c.instances = e.instances;
  c.triangles = e.triangles;
  c.csgDepth = e.csgDepth;
  return c;
}

std::string sceneSummary(const Scene& scene) {
  SceneCounts c = countScene(scene);
  const RenderSettings& r = scene.render;
  std::ostringstream s;
  s << "scene: " << scene.file << "\n";
  s << "image: " << r.width << "x" << r.height << ", " << r.samples
    << (r.samples == 1 ? " sample" : " samples") << " per pixel, max depth " << r.maxDepth << "\n";
  s << "cameras: " << total(c.cameras) << " (" << breakdown(c.cameras) << ")\n";
  s << "lights: " << total(c.lights);
  if (!c.lights.empty()) s << " (" << breakdown(c.lights) << ")";
  s << "\n";
  s << "materials: " << c.materials << "\n";
  s << "nodes: " << total(c.nodes);
  if (!c.nodes.empty()) s << " (" << breakdown(c.nodes) << ")";
  s << "\n";
  if (c.defs > 0) s << "defs: " << c.defs << "\n";
  s << "instances: " << c.instances << "\n";
  s << "triangles: " << c.triangles << "\n";
  s << "csg depth: " << c.csgDepth << "\n";
  return s.str();
}

}  // namespace lucent
