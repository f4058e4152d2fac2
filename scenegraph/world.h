// The world a renderer traces: every leaf placed with its world transform and material,
// CSG nodes composed of such leaves, built once from a scene graph.
#pragma once

#include "scene.h"

#include "primitives/instance.h"
#include "primitives/shape.h"

#include <memory>
#include <vector>

namespace lucent {

class World {
 public:
  // Composes transforms down to the leaves (world matrix, inverse and normal matrix
  // computed once per instance), resolves inherited materials and shares the shape of a
  // node used many times. The scene must outlive the world.
  explicit World(const Scene& scene);

  const Scene& scene() const { return scene_; }
  const std::vector<std::unique_ptr<Shape>>& objects() const { return objects_; }
  // Every leaf instance, including those inside CSG nodes, in scene order.
  const std::vector<const Instance*>& instances() const { return instances_; }

  bool intersect(const Ray& ray, Hit& hit) const;
  bool occluded(const Ray& ray) const;

  // The material of a hit's leaf (hit.shape is always an Instance).
  const Material& material(const Hit& hit) const {
    return scene_.materials[static_cast<const Instance*>(hit.shape)->tag()];
  }

 private:
  const Scene& scene_;
  std::vector<std::unique_ptr<Shape>> objects_;  // top level: instances and CSG nodes
  std::vector<const Instance*> instances_;
};

}  // namespace lucent
