#include "shape_spec.h"

namespace lucent {

namespace {
struct SolidVisitor {
  bool operator()(const CylinderSpec& s) const { return !s.open; }
  bool operator()(const ConeSpec& s) const { return !s.open; }
  bool operator()(const DiscSpec&) const { return false; }
  bool operator()(const TriangleSpec&) const { return false; }
  bool operator()(const MeshSpec& s) const { return s.data && s.data->closed; }
  template <class T> bool operator()(const T&) const { return true; }
};
struct NameVisitor {
  const char* operator()(const SphereSpec&) const { return "sphere"; }
  const char* operator()(const BoxSpec&) const { return "box"; }
  const char* operator()(const CylinderSpec&) const { return "cylinder"; }
  const char* operator()(const ConeSpec&) const { return "cone"; }
  const char* operator()(const TorusSpec&) const { return "torus"; }
  const char* operator()(const PlaneSpec&) const { return "plane"; }
  const char* operator()(const DiscSpec&) const { return "disc"; }
  const char* operator()(const TriangleSpec&) const { return "triangle"; }
  const char* operator()(const MeshSpec&) const { return "mesh"; }
};
}  // namespace

bool isSolid(const ShapeSpec& spec) { return std::visit(SolidVisitor{}, spec); }
const char* shapeElementName(const ShapeSpec& spec) { return std::visit(NameVisitor{}, spec); }

}  // namespace lucent
