// A bounding volume hierarchy over any items that have a box: the instances of a world,
// the triangles of a mesh, the children of a CSG node.
#pragma once

#include "aabb.h"
#include "ray.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <new>
#include <vector>

namespace lucent {

// One node in 32 bytes, so a pair of siblings fills one 64-byte cache line. The box is
// stored in float, rounded outward, so it still contains every item (never a miss from
// the narrowing); siblings sit side by side and are tested together from their parent.
struct BvhNode {
  float box[6];    // lo.x, lo.y, lo.z, hi.x, hi.y, hi.z
  uint32_t index;  // interior node: its first child (the second is index + 1); leaf: first item slot
  uint32_t count;  // 0 for an interior node; a leaf's number of item slots

  bool isLeaf() const { return count != 0; }
  AABB bounds() const {
    return {Vec3(box[0], box[1], box[2]), Vec3(box[3], box[4], box[5])};
  }
};
static_assert(sizeof(BvhNode) == 32, "BVH nodes are 32 bytes: two per cache line");

// Allocates on 64-byte boundaries, so each sibling pair shares one cache line.
template <class T>
struct CacheLineAllocator {
  using value_type = T;
  CacheLineAllocator() = default;
  template <class U>
  CacheLineAllocator(const CacheLineAllocator<U>&) {}
  T* allocate(size_t n) {
    return static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t(64)));
  }
  void deallocate(T* p, size_t) { ::operator delete(p, std::align_val_t(64)); }
  friend bool operator==(const CacheLineAllocator&, const CacheLineAllocator&) { return true; }
  friend bool operator!=(const CacheLineAllocator&, const CacheLineAllocator&) { return false; }
};

using BvhNodes = std::vector<BvhNode, CacheLineAllocator<BvhNode>>;

// The ray's constants for the slab test, computed once per traversal.
struct BvhRay {
  Vec3 o;
  Vec3 invDir;     // ±inf for ±0 components (IEEE division keeps the sign)
  int nearIdx[3];  // index into BvhNode::box of the plane the ray meets first, per axis
  int farIdx[3];

  explicit BvhRay(const Ray& r);

  // The entry distance of the node's box within [tmin, tmax], or false if the ray misses
  // it. Robust as in Ize 2013 ("Robust BVH Ray Traversal"): the far distance is widened
  // by its rounding bound 2·gamma(3), so no ray slips between boxes that share a face.
  // A zero direction component gives ±inf distances (the ray misses unless the origin is
  // within that slab), or NaN for an origin exactly on the slab plane, which the
  // comparisons below ignore: the ray runs in the plane of the closed box.
  bool enters(const BvhNode& n, double tmin, double tmax, double& tEnter) const {
    double t0 = tmin, tf = kInf;
    for (int a = 0; a < 3; ++a) {
      double tNear = (double(n.box[nearIdx[a]]) - o[a]) * invDir[a];
      double tFar = (double(n.box[farIdx[a]]) - o[a]) * invDir[a];
      t0 = tNear > t0 ? tNear : t0;
      tf = tFar < tf ? tFar : tf;
    }
    // Widening the smallest far distance equals widening each (the map is monotone);
    // a multiplication keeps -inf finite-safe where tf + |tf|·k would give NaN.
    tf *= tf >= 0.0 ? 1.0 + kFarWiden : 1.0 - kFarWiden;
    double t1 = tf < tmax ? tf : tmax;
    tEnter = t0;
    return t0 <= t1;
  }

  static constexpr double kFarWiden = 2.0 * gamma(3);
};

struct BvhOptions {
  uint32_t maxLeafSize = 8;    // a leaf never holds more items than this
  float traversalCost = 1.0f;  // SAH cost of visiting a node, relative to...
  float itemCost = 1.0f;       // ...testing one item
  bool parallel = true;        // build large subtrees as TBB tasks (same tree either way)
};

// Built with the binned surface-area heuristic (Wald 2007, "On fast Construction of
// SAH-based Bounding Volume Hierarchies"), in parallel with TBB for large inputs, and
// traversed front to back with an explicit stack.
//
// Items are numbered 0..count-1 by the caller. The build reorders them into leaf slots;
// order() maps a slot back to the caller's item number. A caller that reorders its own
// items to match may take the order away (takeOrder()); the traversals then report slots.
// Items whose box is empty (or NaN) can never be hit and are left out of the tree.
class Bvh {
 public:
  using Options = BvhOptions;

  Bvh() = default;
  // Throws std::invalid_argument if an item's box is unbounded (infinite): such items
  // (planes) belong beside the tree, tested one by one.
  Bvh(size_t count, const std::function<AABB(uint32_t)>& boundsOf, const Options& options);
  Bvh(size_t count, const std::function<AABB(uint32_t)>& boundsOf)
      : Bvh(count, boundsOf, Options()) {}
  explicit Bvh(const std::vector<AABB>& itemBounds, const Options& options = Options());

  bool empty() const { return nodes_.empty(); }
  AABB bounds() const { return empty() ? AABB() : nodes_[0].bounds(); }
  const BvhNodes& nodes() const { return nodes_; }
  const std::vector<uint32_t>& order() const { return order_; }
  std::vector<uint32_t> takeOrder() { return std::move(order_); }
  // Number of items in the tree (items with an empty box are not).
  size_t itemCount() const { return itemCount_; }
  // Bytes held by the nodes and the order, for the memory figures of bench/.
  size_t memoryBytes() const {
    return nodes_.capacity() * sizeof(BvhNode) + order_.capacity() * sizeof(uint32_t);
  }
  int depth() const { return depth_; }

  // Closest hit. hitItem(uint32_t item, Ray& ray) tests one item against (ray.tmin,
  // ray.tmax); on a closer hit it records it, shrinks ray.tmax to it and returns true.
  // Children are visited nearest first and a subtree is skipped once it starts beyond
  // ray.tmax. Returns whether any call returned true.
  template <class HitItem>
  bool closest(const Ray& ray, HitItem&& hitItem) const;

  // Any hit (shadow rays): blocks(uint32_t item, const Ray& ray) says whether the item has
  // a hit in (ray.tmin, ray.tmax); the search stops at the first true.
  template <class Blocks>
  bool any(const Ray& ray, Blocks&& blocks) const;

  // Every item whose box the ray overlaps in [ray.tmin, ray.tmax]: visit(uint32_t item),
  // in no particular order (CSG gathers crossings this way).
  template <class Visit>
  void all(const Ray& ray, Visit&& visit) const;

  // Stack size of the traversals: the build keeps the depth below it (bvh.cpp).
  static constexpr int kMaxDepth = 120;

 private:
  uint32_t itemOf(uint32_t slot) const { return order_.empty() ? slot : order_[slot]; }

  BvhNodes nodes_;  // [0] is the root; [1] is unused so sibling pairs align
  std::vector<uint32_t> order_;
  size_t itemCount_ = 0;
  int depth_ = 0;
};

template <class HitItem>
bool Bvh::closest(const Ray& ray0, HitItem&& hitItem) const {
  if (nodes_.empty()) return false;
  Ray ray = ray0;
  const BvhRay br(ray);
  double tEnter;
  if (!br.enters(nodes_[0], ray.tmin, ray.tmax, tEnter)) return false;
  struct Entry { uint32_t node; double t; };
  Entry stack[kMaxDepth];
  int sp = 0;
  uint32_t cur = 0;
  bool found = false;
  for (;;) {
    const BvhNode& n = nodes_[cur];
    if (!n.isLeaf()) {
      double t0, t1;
      bool h0 = br.enters(nodes_[n.index], ray.tmin, ray.tmax, t0);
      bool h1 = br.enters(nodes_[n.index + 1], ray.tmin, ray.tmax, t1);
      if (h0 && h1) {
        // Nearer child now, the other later unless a hit closes in before it starts.
        if (t1 < t0) {
          stack[sp++] = {n.index, t0};
          cur = n.index + 1;
        } else {
          stack[sp++] = {n.index + 1, t1};
          cur = n.index;
        }
        continue;
      }
      if (h0 || h1) {
        cur = h0 ? n.index : n.index + 1;
        continue;
      }
    } else {
      for (uint32_t s = n.index, e = n.index + n.count; s < e; ++s)
        if (hitItem(itemOf(s), ray)) found = true;
    }
    for (;;) {
      if (sp == 0) return found;
      const Entry& e = stack[--sp];
      if (e.t <= ray.tmax) {
        cur = e.node;
        break;
      }
    }
  }
}

template <class Blocks>
bool Bvh::any(const Ray& ray, Blocks&& blocks) const {
  if (nodes_.empty()) return false;
  const BvhRay br(ray);
  double tEnter;
  if (!br.enters(nodes_[0], ray.tmin, ray.tmax, tEnter)) return false;
  uint32_t stack[kMaxDepth];
  int sp = 0;
  uint32_t cur = 0;
  for (;;) {
    const BvhNode& n = nodes_[cur];
    if (!n.isLeaf()) {
      double t0, t1;
      bool h0 = br.enters(nodes_[n.index], ray.tmin, ray.tmax, t0);
      bool h1 = br.enters(nodes_[n.index + 1], ray.tmin, ray.tmax, t1);
      if (h0 && h1) {
        // Nearer first here too: near occluders end the search sooner.
        bool secondFirst = t1 < t0;
        stack[sp++] = secondFirst ? n.index : n.index + 1;
        cur = secondFirst ? n.index + 1 : n.index;
        continue;
      }
      if (h0 || h1) {
        cur = h0 ? n.index : n.index + 1;
        continue;
      }
    } else {
      for (uint32_t s = n.index, e = n.index + n.count; s < e; ++s)
        if (blocks(itemOf(s), static_cast<const Ray&>(ray))) return true;
    }
    if (sp == 0) return false;
    cur = stack[--sp];
  }
}

template <class Visit>
void Bvh::all(const Ray& ray, Visit&& visit) const {
  if (nodes_.empty()) return;
  const BvhRay br(ray);
  double tEnter;
  if (!br.enters(nodes_[0], ray.tmin, ray.tmax, tEnter)) return;
  uint32_t stack[kMaxDepth];
  int sp = 0;
  uint32_t cur = 0;
  for (;;) {
    const BvhNode& n = nodes_[cur];
    if (!n.isLeaf()) {
      double t0, t1;
      bool h0 = br.enters(nodes_[n.index], ray.tmin, ray.tmax, t0);
      bool h1 = br.enters(nodes_[n.index + 1], ray.tmin, ray.tmax, t1);
      if (h0 && h1) stack[sp++] = n.index + 1;
      if (h0 || h1) {
        cur = h0 ? n.index : n.index + 1;
        continue;
      }
    } else {
      for (uint32_t s = n.index, e = n.index + n.count; s < e; ++s) visit(itemOf(s));
    }
    if (sp == 0) return;
    cur = stack[--sp];
  }
}

}  // namespace lucent
