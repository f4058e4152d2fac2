#include "make_shape.h"

#include "primitives/box.h"
#include "primitives/cone.h"
#include "primitives/cylinder.h"
#include "primitives/disc.h"
#include "primitives/plane.h"
#include "primitives/sphere.h"
#include "primitives/torus.h"
#include "primitives/triangle.h"
#include "primitives/triangle_mesh.h"

#include <stdexcept>

namespace lucent {

namespace {

// One explicit table from element parameters to primitives (style habit 7).
struct Builder {
  std::shared_ptr<const Shape> operator()(const SphereSpec& s) const {
    return std::make_shared<Sphere>(s.center, s.radius);
  }
  std::shared_ptr<const Shape> operator()(const BoxSpec& s) const {
    return std::make_shared<Box>(s.min, s.max);
  }
  std::shared_ptr<const Shape> operator()(const PlaneSpec& s) const {
    return std::make_shared<Plane>(s.normal, s.offset);
  }
  std::shared_ptr<const Shape> operator()(const CylinderSpec& s) const {
    return std::make_shared<Cylinder>(s.base, s.cap, s.radius, s.open);
  }
  std::shared_ptr<const Shape> operator()(const ConeSpec& s) const {
    return std::make_shared<Cone>(s.base, s.baseRadius, s.cap, s.capRadius, s.open);
  }
  std::shared_ptr<const Shape> operator()(const TorusSpec& s) const {
    return std::make_shared<Torus>(s.major, s.minor);
  }
  std::shared_ptr<const Shape> operator()(const DiscSpec& s) const {
    return std::make_shared<Disc>(s.center, s.normal, s.radius, s.innerRadius);
  }
  std::shared_ptr<const Shape> operator()(const TriangleSpec& s) const {
    return std::make_shared<Triangle>(s.a, s.b, s.c, s.normals);
  }
  std::shared_ptr<const Shape> operator()(const MeshSpec& s) const {
    if (!s.data) throw std::invalid_argument("makeShape: <mesh> has no data");
    switch (s.smooth) {
      case SmoothMode::Auto:  // the file's normals if it has them, else flat
        return std::make_shared<TriangleMesh>(s.data, !s.data->normals.empty());
      case SmoothMode::False:
        return std::make_shared<TriangleMesh>(s.data, false);
      case SmoothMode::True: {
        // Computed normals replace any the file had: a copy of the data owned by this
        // shape (makeShape runs once per node, and every <use> shares the result).
        auto smoothed = std::make_shared<MeshData>(*s.data);
        smoothed->normals = computeVertexNormals(*smoothed);
        return std::make_shared<TriangleMesh>(std::move(smoothed), true);
      }
    }
    throw std::invalid_argument("makeShape: unknown smooth mode");
  }
};

}  // namespace

std::shared_ptr<const Shape> makeShape(const ShapeSpec& spec) { return std::visit(Builder{}, spec); }

}  // namespace lucent
