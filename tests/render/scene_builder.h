// Building small scenes in code for the render tests: no parser involved.
#pragma once

#include "render/image.h"
#include "render/tracer.h"
#include "scenegraph/shape_registry.h"
#include "scenegraph/scene.h"
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
  RayStats stats;
  Color c = tracer.traceCamera(ray, tracer.mediaAt(ray.o), seed, stats);
  if (statsOut) *statsOut = stats;
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

}  // namespace lucent::test
