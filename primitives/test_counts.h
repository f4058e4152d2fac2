// Intersection tests counted per thread and kind of shape, for `lucent render --stats`.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace lucent {

// What a test was run against: each leaf shape kind, and the triangles tested inside
// meshes (a mesh test is one search of its BVH, which tests some of its triangles).
enum class TestKind : uint8_t {
  Sphere, Box, Cylinder, Cone, Torus, Plane, Disc, Triangle, Mesh, MeshTriangle, Other, Count
};

constexpr int kTestKinds = static_cast<int>(TestKind::Count);

struct TestCounts {
  std::array<uint64_t, kTestKinds> n{};

  uint64_t& operator[](TestKind k) { return n[static_cast<size_t>(k)]; }
  uint64_t operator[](TestKind k) const { return n[static_cast<size_t>(k)]; }
  TestCounts& operator+=(const TestCounts& o) {
    for (size_t i = 0; i < n.size(); ++i) n[i] += o.n[i];
    return *this;
  }
  TestCounts operator-(const TestCounts& o) const {
    TestCounts d;
    for (size_t i = 0; i < n.size(); ++i) d.n[i] = n[i] - o.n[i];
    return d;
  }
};

// This thread's running totals. Each thread counts into its own, so counting costs one
// increment and never makes threads wait; a reader takes the difference over its work.
inline thread_local TestCounts threadTestCounts;

// The kind for Shape::kind()'s name ("sphere", ...), Other for anything unlisted.
TestKind testKindOf(const char* shapeKind);
// The plural a report prints ("spheres", "mesh triangles", ...).
const char* testKindName(TestKind kind);

}  // namespace lucent
