// Building small scenes in code for the render tests: no parser involved.
#pragma once

#include "render/image.h"
#include "render/tracer.h"
#include "scenegraph/scene.h"
#include "scenegraph/shape_registry.h"
#include "scenegraph/world.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstring>
#include <memory>
#include <optional>

namespace lucent::test {

// Adds a material and returns its index.
inline uint32_t addMaterial(Scene& scene, const Material& m) {
  scene.materials.push_back(m);
  return static_cast<uint32_t>(scene.materials.size() - 1);
}

inline std::unique_ptr<Node> shapeNode(const ShapeSpec& spec, std::optional<uint32_t> material,
                                       const Mat4& parentFromNode = Mat4(1.0)) {
  auto node = std::make_unique<Node>();
  node->kind = NodeKind::Shape;
  node->element = shapeElementName(spec);
  node->shape = spec;
  node->material = material;
  node->parentFromNode = parentFromNode;
  return node;
}

// Adds a shape at the top level.
inline Node& addShape(Scene& scene, const ShapeSpec& spec, std::optional<uint32_t> material,
                      const Mat4& parentFromNode = Mat4(1.0)) {
  scene.root->children.push_back(shapeNode(spec, material, parentFromNode));
  return *scene.root->children.back();
}

inline Material emissive(const Color& c) {
  Material m;
  m.emissive = c;
  return m;
}

inline Camera lookingFrom(const Vec3& position, const Vec3& lookAt, double fov = 60.0) {
  Camera c;
  c.position = position;
  c.lookAt = lookAt;
  c.fov = fov;
  return c;
}

inline Light pointLight(const Vec3& position, const Color& color = Color(1.0f)) {
  Light l;
  l.type = LightType::Point;
  l.position = position;
  l.color = color;
  return l;
}

inline Mat4 translation(const Vec3& t) { return glm::translate(Mat4(1.0), t); }

// The colour the tracer returns for one camera ray starting at ray.o (in the media there).
inline Color traceOne(const World& world, const Ray& ray, RayStats* statsOut = nullptr) {
  Tracer tracer(world);
  PathSeed seed;
  TraceContext context;
  Color c = tracer.traceCamera(ray, tracer.mediaAt(ray.o), seed, context);
  if (statsOut) *statsOut = context.stats;
  return c;
}

// A rectangular area light of nu × nv samples centred on `position`, white.
inline Light areaLight(const Vec3& position, const Vec3& u, const Vec3& v, int nu, int nv,
                       bool jitter = false) {
  Light area;
  area.type = LightType::Area;
  area.position = position;
  area.u = u;
  area.v = v;
  area.samplesU = nu;
  area.samplesV = nv;
  area.jitter = jitter;
  return area;
}

// Whether two images hold the same floats, bit for bit.
inline bool sameBits(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Color)) == 0;
}

// Everything that could make threads disagree: jittered area light, supersampling,
// adaptive refinement, glass, mirrors, textures, transparent shadows.
inline void buildBusyScene(Scene& scene) {
  scene.render.width = 40;
  scene.render.height = 30;
  scene.render.samples = 4;
  scene.render.adaptive = 0.05;
  scene.cameras.push_back(lookingFrom(Vec3(0, 2, 6), Vec3(0, 0.5, 0), 50));
  Material floor;
  floor.diffuse = Color(1.0f);
  floor.texture = CheckerTexture{Color(1.0f), Color(0.2f), 1.0, {}};
  floor.ambient = Color(0.1f);
  addShape(scene, PlaneSpec{Vec3(0, 1, 0), 0.0}, addMaterial(scene, floor));
  Material glass;
  glass.transmissive = Color(0.9f);
  glass.reflective = Color(0.1f);
  glass.ior = 1.5;
  glass.fresnel = true;
  glass.absorption = Color(0.1f, 0.2f, 0.3f);
  glass.specular = Color(1.0f);
  glass.shininess = 200;
  addShape(scene, SphereSpec{Vec3(1.2, 0.7, 0), 0.7}, addMaterial(scene, glass));
  Material brick;
  brick.diffuse = Color(1.0f, 0.3f, 0.2f);
  brick.reflective = Color(0.2f);
  addShape(scene, BoxSpec{Vec3(-2, 0, -1), Vec3(-0.5, 1.5, 0.5)}, addMaterial(scene, brick));
  scene.lights.push_back(areaLight(Vec3(3, 6, 4), Vec3(1.5, 0, 0), Vec3(0, 0, 1.5), 3, 3, true));
  scene.lights.push_back(pointLight(Vec3(-4, 5, 2), Color(0.4f)));
}

}  // namespace lucent::test
