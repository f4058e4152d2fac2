// The scene reader's answer to trace(), inside(), min_extent() and max_extent(): an object
// item built into a world of its own (its nodes as the scene would hold them, Lucent's
// shapes), kept for as long as the item lives so that a loop of trace() calls builds it
// once. Points go between POV-Ray's space and Lucent's by negating z.
#include "scene_reader.h"

#include "scenegraph/world.h"

#include <limits>

namespace lucent::sdl {

namespace {

Vec3 toVec(const ObjectGeometry::Vec& v) { return Vec3(v[0], v[1], v[2]); }
// A Lucent point or direction in POV-Ray's space; a z of +0 stays +0 (POV-Ray's sign).
ObjectGeometry::Vec povArray(const Vec3& v) { return {v.x, v.y, -v.z + 0.0}; }

class BuiltObject final : public ObjectGeometry {
 public:
  explicit BuiltObject(std::unique_ptr<Scene> scene) : scene_(std::move(scene)), world_(*scene_) {}

  bool trace(const Vec& origin, const Vec& direction, Vec& point, Vec& normal) const override {
    const Ray ray(lucentFromPov(toVec(origin)), glm::normalize(lucentFromPov(toVec(direction))));
    WorldHit hit;
    if (!world_.intersect(ray, hit)) return false;
    const SurfaceInfo s = hit.surface(ray);
    point = povArray(s.p);
    normal = povArray(s.ng);
    return true;
  }

  bool inside(const Vec& p) const override {
    const Vec3 q = lucentFromPov(toVec(p));
    for (const WorldObject& o : world_.objects())
      if (o.shape->inside(q)) return true;
    return false;
  }

  void extent(Vec& lo, Vec& hi) const override {
    AABB box;
    for (const WorldObject& o : world_.objects()) {
      const AABB b = o.shape->bounds();
      box.lo = glm::min(box.lo, b.lo);
      box.hi = glm::max(box.hi, b.hi);
    }
    if (world_.objects().empty()) box = AABB(Vec3(0.0), Vec3(0.0));
    // z negated: Lucent's lowest z is POV-Ray's highest.
    lo = {box.lo.x, box.lo.y, -box.hi.z};
    hi = {box.hi.x, box.hi.y, -box.lo.z};
  }

 private:
  std::unique_ptr<Scene> scene_;
  World world_;
};

}  // namespace

std::shared_ptr<const ObjectGeometry> SceneReader::geometry(const ItemPtr& item, TokenStream& in) {
  const auto* object = dynamic_cast<const ObjectItem*>(item.get());
  if (!object || object->object.kind == NodeKind::Light) return nullptr;
  for (const auto& [built, geometry] : built_)
    if (built == item) return geometry;
  // A declared object that keeps refusals: said here, where it is used, and the call
  // refused unless they are left out (--skip-unsupported).
  const SourceLoc usedAt = in.current().loc();
  if (!object->refused.empty()) {
    const size_t errorsBefore = diags_.errorCount();
    reportRefused(*object, usedAt, in);
    if (diags_.errorCount() > errorsBefore)
      in.error(usedAt,
               "the object cannot be built by Lucent (what it holds that Lucent cannot "
               "render is listed)");
  }
  // Its nodes as place() makes them, in a scene of their own.
  auto scene = std::make_unique<Scene>();
  scene->file = scene_.file;
  Diagnostics diagnostics;
  SceneReader reader(*scene, diagnostics, options_);
  reader.defaults_ = defaults_;
  const PovTexture texture = defaultTexture();
  const PovInterior interior;
  Inherited top;
  top.texture = &texture;
  top.interior = &interior;
  std::unique_ptr<Node> node = reader.toNode(object->object, top, true, in);
  if (node) scene->root->children.push_back(std::move(node));
  if (diagnostics.hasErrors()) {
    const Diagnostic& d = diagnostics.all().front();
    in.error(d.loc, d.message);
  }
  std::shared_ptr<const ObjectGeometry> geometry;
  try {
    geometry = std::make_shared<BuiltObject>(std::move(scene));
  } catch (const LocatedError& e) {
    in.error(e.loc(), e.message());
  } catch (const std::exception& e) {
    in.error(usedAt, std::string("the object cannot be built: ") + e.what());
  }
  // Kept with the item itself, so that the item's address is never another's.
  built_.emplace_back(item, geometry);
  return geometry;
}

}  // namespace lucent::sdl
