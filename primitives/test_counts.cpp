#include "test_counts.h"

#include <cstring>

namespace lucent {

namespace {
struct KindName {
  const char* kind;    // Shape::kind()
  const char* plural;  // in reports
};
// In TestKind's order.
constexpr KindName kNames[kTestKinds] = {
    {"sphere", "spheres"}, {"box", "boxes"},       {"cylinder", "cylinders"},
    {"cone", "cones"},     {"torus", "tori"},      {"plane", "planes"},
    {"disc", "discs"},     {"triangle", "triangles"}, {"mesh", "meshes"},
    {"", "mesh triangles"}, {"", "other shapes"}};
}  // namespace

TestKind testKindOf(const char* shapeKind) {
  for (int i = 0; i < static_cast<int>(TestKind::MeshTriangle); ++i)
    if (std::strcmp(shapeKind, kNames[i].kind) == 0) return static_cast<TestKind>(i);
  return TestKind::Other;
}

const char* testKindName(TestKind kind) { return kNames[static_cast<int>(kind)].plural; }

}  // namespace lucent
