// Intersection tests counted per thread and slot, for `lucent render --stats`. A leaf's
// slot is its row in the shape registry (scenegraph/shape_registry.h), which also names
// it; two slots after the shapes count the triangles tested inside meshes and the rest.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace lucent {

constexpr size_t kShapeTestSlots = 30;  // at least the registry's row count (checked there)
constexpr size_t kMeshTriangleSlot = kShapeTestSlots;  // a mesh test searches its BVH
constexpr size_t kOtherTestSlot = kShapeTestSlots + 1;
constexpr size_t kTestSlots = kShapeTestSlots + 2;

struct TestCounts {
  std::array<uint64_t, kTestSlots> n{};

  uint64_t& operator[](size_t slot) { return n[slot]; }
  uint64_t operator[](size_t slot) const { return n[slot]; }
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

}  // namespace lucent
