// The world a renderer traces: every leaf placed with its world transform and material,
// CSG nodes composed of such leaves, built once from a scene graph.
#pragma once

#include "scene.h"

#include "primitives/bvh.h"
#include "primitives/instance.h"
#include "primitives/shape.h"

#include <functional>
#include <memory>
#include <vector>

namespace lucent {

// Builds the shape of one geometry node (makeShape; tests pass their own).
using ShapeMaker = std::function<std::shared_ptr<const Shape>(const ShapeSpec&)>;

class World {
 public:
  // Composes transforms down to the leaves (world matrix, inverse and normal matrix
  // computed once per instance), resolves inherited materials and shares the shape of a
  // node used many times: a mesh used through many <use> is stored and built once.
  // The top-level objects with a finite box go into a BVH; the others (planes), or a
  // lone object, are tested one by one. The scene must outlive the world.
  explicit World(const Scene& scene);
  World(const Scene& scene, const ShapeMaker& makeShape);

  const Scene& scene() const { return scene_; }
  const std::vector<std::unique_ptr<Shape>>& objects() const { return objects_; }
  // Every leaf instance, including those inside CSG nodes, in scene order.
  const std::vector<const Instance*>& instances() const { return instances_; }

  bool intersect(const Ray& ray, Hit& hit) const;
  bool occluded(const Ray& ray) const;

  // The top-level acceleration structure, for statistics.
  const Bvh& bvh() const { return bvh_; }
  // The objects tested one by one beside the BVH: unbounded ones, or a lone object.
  const std::vector<const Shape*>& directObjects() const { return direct_; }

  // The material of a hit's leaf (hit.shape is always an Instance).
  const Material& material(const Hit& hit) const {
    return scene_.materials[static_cast<const Instance*>(hit.shape)->tag()];
  }

 private:
  const Scene& scene_;
  std::vector<std::unique_ptr<Shape>> objects_;  // top level: instances and CSG nodes
  std::vector<const Instance*> instances_;
  std::vector<const Shape*> bounded_;    // in the BVH's leaf order
  std::vector<const Shape*> direct_;     // never in the BVH
  Bvh bvh_;
};

}  // namespace lucent
