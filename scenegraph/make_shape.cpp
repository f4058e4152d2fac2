#include "make_shape.h"

#include "primitives/box.h"
#include "primitives/plane.h"
#include "primitives/sphere.h"

#include <stdexcept>
#include <string>

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
  template <class T>
  std::shared_ptr<const Shape> operator()(const T& s) const {
    throw std::invalid_argument(std::string("makeShape: <") + shapeElementName(ShapeSpec(s)) +
                                "> is not implemented yet");
  }
};

}  // namespace

std::shared_ptr<const Shape> makeShape(const ShapeSpec& spec) { return std::visit(Builder{}, spec); }

}  // namespace lucent
