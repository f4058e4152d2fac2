// A bounding volume hierarchy over any items that have a box: the instances of a world,
// the triangles of a mesh, the children of a CSG node.
#pragma once

#include "aabb.h"
#include "memory/uninitialised_construct.h"
#include "ray.h"

#include <cfloat>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <new>
#include <utility>
#include <vector>

namespace lucent {

// Children per node: 8 where the target has 8-wide float vectors (AVX, as Embree chooses
// there: fewer levels, so fewer dependent cache misses per ray), else 4. A build may set
// it with -DLUCENT_BVH_WIDTH=4 or 8 (docs/performance.md compares the two).
#ifndef LUCENT_BVH_WIDTH
#if defined(__AVX__)
#define LUCENT_BVH_WIDTH 8
#else
#define LUCENT_BVH_WIDTH 4
#endif
#endif

// A node of the W-wide tree: W child entries of 32 bytes each (a float box and a
// reference), stored axis-major so the W boxes are tested with one set of W-wide float
// operations. Boxes are rounded outward from the items' double boxes, so they still
// contain every item. A child is interior (count 0: its node is `index`), a leaf (items
// in slots [index, index + count)), or an empty slot (kEmpty; its box is inverted, lo =
// +inf and hi = -inf, so every slab test misses it).
struct alignas(64) BvhNode {
  static constexpr int kWidth = LUCENT_BVH_WIDTH;
  // box[2W·axis + c] is child c's lo on that axis, box[2W·axis + W + c] its hi
  float box[6 * kWidth];
  uint32_t index[kWidth];
  uint32_t count[kWidth];

  static constexpr uint32_t kEmpty = 0xffffffffu;

  bool isEmpty(int c) const { return count[c] == 0 && index[c] == kEmpty; }
  bool isLeaf(int c) const { return count[c] != 0; }
  bool isInterior(int c) const { return count[c] == 0 && index[c] != kEmpty; }
  static constexpr int lo(int axis) { return 2 * kWidth * axis; }
  static constexpr int hi(int axis) { return 2 * kWidth * axis + kWidth; }
  AABB bounds(int c) const {
    return {Vec3(box[lo(0) + c], box[lo(1) + c], box[lo(2) + c]),
            Vec3(box[hi(0) + c], box[hi(1) + c], box[hi(2) + c])};
  }
};
static_assert(BvhNode::kWidth == 4 || BvhNode::kWidth == 8, "4- or 8-wide nodes");
static_assert(sizeof(BvhNode) == BvhNode::kWidth * 32, "32-byte child entries");

// Allocates on 64-byte boundaries and leaves new elements uninitialised on resize, so
// the nodes the build reserves but never reaches are never touched (cost no memory).
template <class T>
struct CacheLineAllocator : UninitialisedConstruct {
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

namespace bvh_detail {

// GCC/Clang vector extensions: SSE on x86-64, NEON on ARM, scalar code elsewhere.
typedef float v4f __attribute__((vector_size(16)));
typedef int32_t v4i __attribute__((vector_size(16)));
// One lane per child of a node (the traversal's node test).
typedef float vwf __attribute__((vector_size(4 * BvhNode::kWidth)));
typedef int32_t vwi __attribute__((vector_size(4 * BvhNode::kWidth)));

// a < b ? a : b and a > b ? a : b: so the second operand wherever either is NaN. On SSE
// these are minps and maxps exactly; written as conditionals, GCC made some of them
// (the clamps of the build's centroids) a compare and three logic operations.
inline v4f vmin(v4f a, v4f b) {
#if defined(__SSE__)
  return __builtin_ia32_minps(a, b);
#else
  return a < b ? a : b;
#endif
}
inline v4f vmax(v4f a, v4f b) {
#if defined(__SSE__)
  return __builtin_ia32_maxps(a, b);
#else
  return a > b ? a : b;
#endif
}
inline v4f splat(float f) { return v4f{f, f, f, f}; }
inline vwf splatW(float f) { return f - vwf{}; }
// minps/maxps of the node width where the target has them (the same NaN rule as vmin).
#if LUCENT_BVH_WIDTH == 8 && defined(__AVX__)
inline vwf wmin(vwf a, vwf b) { return __builtin_ia32_minps256(a, b); }
inline vwf wmax(vwf a, vwf b) { return __builtin_ia32_maxps256(a, b); }
#elif LUCENT_BVH_WIDTH == 4 && defined(__SSE__)
inline vwf wmin(vwf a, vwf b) { return __builtin_ia32_minps(a, b); }
inline vwf wmax(vwf a, vwf b) { return __builtin_ia32_maxps(a, b); }
#else
inline vwf wmin(vwf a, vwf b) { return a < b ? a : b; }
inline vwf wmax(vwf a, vwf b) { return a > b ? a : b; }
#endif
inline vwf loadW(const float* p) {
  vwf v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
// Bit c set when lane c of the comparison result is true.
inline int laneMask(vwi m) {
#if LUCENT_BVH_WIDTH == 8 && defined(__AVX__)
  return __builtin_ia32_movmskps256(reinterpret_cast<vwf>(m));
#elif LUCENT_BVH_WIDTH == 4 && defined(__SSE__)
  return __builtin_ia32_movmskps(reinterpret_cast<vwf>(m));
#else
  int mask = 0;
  for (int c = 0; c < BvhNode::kWidth; ++c) mask |= (m[c] & 1) << c;
  return mask;
#endif
}

// The neighbouring floats (finite input; ±0 handled), to round double to float outward
// without a libm call.
inline float nextUp(float f) {
  if (f == 0.0f) return FLT_TRUE_MIN;
  uint32_t b;
  std::memcpy(&b, &f, 4);
  b = f > 0.0f ? b + 1 : b - 1;
  std::memcpy(&f, &b, 4);
  return f;
}
inline float nextDown(float f) { return -nextUp(-f); }
inline float roundDown(double x) {
  float f = static_cast<float>(x);
  return double(f) > x ? nextDown(f) : f;
}
inline float roundUp(double x) {
  float f = static_cast<float>(x);
  return double(f) < x ? nextUp(f) : f;
}

// Slab test of a node's W boxes in float, for rays whose direction has no zero
// component (so no 0·inf NaN can arise). Conservative, after Ize 2013 ("Robust BVH Ray
// Traversal"): for each plane the origin is rounded the way that moves the plane's
// distance outward (up for lo planes, down for hi planes, whatever the direction's
// sign), and the entry and exit distances are widened by 2·gamma(3) in float for the
// rounding of the subtraction, the reciprocal and the product. So no box is missed
// through rounding; distances beyond float range (3.4e38) count as infinite.
struct FastNodeTest {
  static constexpr int W = BvhNode::kWidth;
  int nearOff[3], farOff[3];  // offsets in BvhNode::box of the near and far planes
  vwf orgNear[3], orgFar[3];  // the origin, rounded for the near and far planes
  vwf inv[3];                 // 1/d in float
  vwf tmin;                   // rounded down

  static constexpr v4i kAbsMask4 = {0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff};
  // 2·gamma(3) for float (pbrt's gamma with the float unit roundoff).
  static constexpr float kWiden =
      2.0f * (3.0f * (FLT_EPSILON * 0.5f)) / (1.0f - 3.0f * (FLT_EPSILON * 0.5f));

  bool usable = false;  // no zero direction component, and everything within float range

  explicit FastNodeTest(const Ray& r) {
    // The origin rounded to float and then moved outward by more than the rounding:
    // |o - f| <= ulp(f)/2 < |f|·2^-23, and FLT_MIN covers an origin that rounds to 0.
    v4f o = {float(r.o.x), float(r.o.y), float(r.o.z), 0.0f};
    v4f absO = reinterpret_cast<v4f>(reinterpret_cast<v4i>(o) & kAbsMask4);
    v4f slack = absO * splat(FLT_EPSILON) + splat(FLT_MIN);
    v4f up = o + slack, down = o - slack;
    usable = true;
    for (int a = 0; a < 3; ++a) {
      double invD = 1.0 / r.d[a];
      usable = usable && r.d[a] != 0.0 && std::abs(invD) < double(FLT_MAX) &&
               std::abs(r.o[a]) < double(FLT_MAX);
      bool negative = r.d[a] < 0.0;
      // Going up the axis the lo plane is met first; going down, the hi plane.
      nearOff[a] = negative ? BvhNode::hi(a) : BvhNode::lo(a);
      farOff[a] = negative ? BvhNode::lo(a) : BvhNode::hi(a);
      orgNear[a] = splatW(negative ? down[a] : up[a]);
      orgFar[a] = splatW(negative ? up[a] : down[a]);
      inv[a] = splatW(static_cast<float>(invD));
    }
    tmin = splatW(roundDown(r.tmin));
  }

  // Bit c set if child c's box overlaps [tmin, tmax]; tEnter[c] is then a lower bound
  // of its entry distance.
  int test(const BvhNode& n, float tmaxUp, float tEnter[W]) const {
    vwf t0 = tmin, t1 = splatW(tmaxUp);
    for (int a = 0; a < 3; ++a) {
      vwf tn = (loadW(n.box + nearOff[a]) - orgNear[a]) * inv[a];
      vwf tf = (loadW(n.box + farOff[a]) - orgFar[a]) * inv[a];
      t0 = wmax(t0, tn);
      t1 = wmin(t1, tf);
    }
    // Widen both ends by the rounding bound: t0 - |t0|·k and t1 + |t1|·k.
    const vwi absMask = 0x7fffffff - vwi{};
    vwf k = splatW(kWiden);
    t0 = t0 - reinterpret_cast<vwf>(reinterpret_cast<vwi>(t0) & absMask) * k;
    t1 = t1 + reinterpret_cast<vwf>(reinterpret_cast<vwi>(t1) & absMask) * k;
    std::memcpy(tEnter, &t0, sizeof t0);
    return laneMask(t0 <= t1);
  }
};

}  // namespace bvh_detail

// The ray's constants for the double-precision slab test, for the rays the float test
// cannot take (a zero direction component, an origin beyond float range).
struct BvhRay {
  Vec3 o;
  Vec3 invDir;     // ±inf for ±0 components (IEEE division keeps the sign)
  int nearOff[3];  // offsets in BvhNode::box of the plane met first on each axis
  int farOff[3];

  explicit BvhRay(const Ray& r);

  // The entry distance of child c's box within [tmin, tmax], or false if the ray misses
  // it. Robust as in Ize 2013: the far distance is widened by its rounding bound
  // 2·gamma(3), so no ray slips between boxes that share a face. A zero direction
  // component gives ±inf distances (the ray misses unless the origin is within that
  // slab), or NaN for an origin exactly on the slab plane, which the comparisons below
  // ignore: the ray runs in the plane of the closed box.
  bool enters(const BvhNode& n, int c, double tmin, double tmax, double& tEnter) const {
    double t0 = tmin, tf = kInf;
    for (int a = 0; a < 3; ++a) {
      double tNear = (double(n.box[nearOff[a] + c]) - o[a]) * invDir[a];
      double tFar = (double(n.box[farOff[a] + c]) - o[a]) * invDir[a];
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
  uint32_t minLeafSize = 1;    // subtrees of at most this many items are leaves, unsplit
  float traversalCost = 1.0f;  // SAH cost of visiting a node, relative to...
  float itemCost = 1.0f;       // ...testing one item
  bool parallel = true;        // build large subtrees as TBB tasks (same tree either way)
};

// Built top-down with the binned surface-area heuristic (Wald 2007, "On fast Construction
// of SAH-based Bounding Volume Hierarchies"), each node taking up to W children by
// splitting its largest child again (as Embree's BVH4 and BVH8 builders do), in parallel
// with TBB for large inputs; traversed with an explicit stack, front to back for closest
// hits and in the tree's order for any-hit searches (Order).
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
  AABB bounds() const;
  // nodes()[0] is the root.
  const BvhNodes& nodes() const { return nodes_; }
  const std::vector<uint32_t>& order() const { return order_; }
  std::vector<uint32_t> takeOrder() { return std::move(order_); }
  // Number of items in the tree (items with an empty box are not).
  size_t itemCount() const { return itemCount_; }
  // Bytes held by the nodes and the order (the capacity reserved for the build beyond
  // the nodes' size was never touched: address space, not memory).
  size_t memoryBytes() const {
    return nodes_.size() * sizeof(BvhNode) + order_.capacity() * sizeof(uint32_t);
  }
  // Levels of the binary splits the build made (the W-wide tree has fewer).
  int depth() const { return depth_; }

  // The traversal every query below is made of: visit(uint32_t item) for the items of
  // each leaf whose box the ray enters within [ray.tmin, tFar], nearest box first. tFar
  // is read again after every call, so a closest-hit search can shrink it and skip the
  // boxes that start beyond; visit returns false to end the search. Returns false if
  // it was ended so.
  //
  // prefetch(uint32_t first, uint32_t count) is called for each leaf as soon as its box
  // is found entered, with the leaf's slots [first, first + count): a caller that keeps
  // its items' data in slot order (the world's spheres) can ask the processor to fetch
  // it, so that the cache misses of a node's leaves overlap instead of coming one after
  // another as the search reaches them. The entered interior nodes are fetched the same
  // way. NoPrefetch fetches nothing.
  //
  // With Order::Tree the entered children are searched in the tree's order instead of
  // nearest first: an any-hit search visits every entered box unless an item blocks the
  // ray, so sorting them is wasted work (docs/performance-history.md, "Seventh pass").
  struct NoPrefetch {
    void operator()(uint32_t, uint32_t) const {}
  };
  enum class Order { NearestFirst, Tree };
  template <class Visit, class Prefetch = NoPrefetch>
  bool candidates(const Ray& ray, const double& tFar, Visit&& visit,
                  Prefetch&& prefetch = Prefetch(), Order order = Order::NearestFirst) const {
    auto visitLeaf = [&](uint32_t first, uint32_t count) {
      for (uint32_t s = first, e = first + count; s < e; ++s)
        if (!visit(itemOf(s))) return false;
      return true;
    };
    return leaves(ray, tFar, visitLeaf, prefetch, order);
  }

  // candidates() a leaf at a time: visitLeaf(uint32_t first, uint32_t count) for the slots
  // [first, first + count) of each entered leaf (order() names their items), so that a
  // caller can test a leaf's items together (a mesh's triangles, four at once). tFar is
  // read again after every call; visitLeaf returns false to end the search.
  template <class VisitLeaf, class Prefetch = NoPrefetch>
  bool leaves(const Ray& ray, const double& tFar, VisitLeaf&& visitLeaf,
              Prefetch&& prefetch = Prefetch(), Order order = Order::NearestFirst) const {
    if (nodes_.empty()) return true;
    bvh_detail::FastNodeTest fast(ray);
    if (fast.usable) return candidatesWith(fast, tFar, visitLeaf, prefetch, order);
    return candidatesWith(SafeNodeTest(ray), tFar, visitLeaf, prefetch, order);
  }

  // Closest hit. hitItem(uint32_t item, Ray& ray) tests one item against (ray.tmin,
  // ray.tmax); on a closer hit it records it, shrinks ray.tmax to it and returns true.
  // Returns whether any call returned true. prefetch as for candidates().
  template <class HitItem, class Prefetch = NoPrefetch>
  bool closest(const Ray& ray, HitItem&& hitItem, Prefetch&& prefetch = Prefetch()) const {
    Ray r = copyByMembers(ray);
    bool found = false;
    candidates(
        r, r.tmax,
        [&](uint32_t item) {
          if (hitItem(item, r)) found = true;
          return true;
        },
        prefetch);
    return found;
  }

  // Any hit (shadow rays): blocks(uint32_t item, const Ray& ray) says whether the item has
  // a hit in (ray.tmin, ray.tmax); the search stops at the first true. Boxes in tree
  // order (Order::Tree).
  template <class Blocks, class Prefetch = NoPrefetch>
  bool any(const Ray& ray, Blocks&& blocks, Prefetch&& prefetch = Prefetch()) const {
    return !candidates(
        ray, ray.tmax, [&](uint32_t item) { return !blocks(item, ray); }, prefetch, Order::Tree);
  }

  // Every item whose box the ray overlaps in [ray.tmin, ray.tmax]: visit(uint32_t item)
  // (CSG gathers crossings this way).
  template <class Visit>
  void all(const Ray& ray, Visit&& visit) const {
    candidates(ray, ray.tmax, [&](uint32_t item) {
      visit(item);
      return true;
    });
  }

  // Bound of depth(): the build switches to median splits before it (bvh.cpp).
  static constexpr int kMaxDepth = 120;

 private:
  // The double-precision test with the fast test's interface.
  struct SafeNodeTest {
    BvhRay r;
    double tmin;
    explicit SafeNodeTest(const Ray& ray) : r(ray), tmin(ray.tmin) {}
    int test(const BvhNode& n, double tmax, double tEnter[BvhNode::kWidth]) const {
      int mask = 0;
      for (int c = 0; c < BvhNode::kWidth; ++c)
        mask |= int(r.enters(n, c, tmin, tmax, tEnter[c])) << c;
      return mask;
    }
  };

  // The fast test takes tmax rounded up to float, the safe one as it is.
  static float limit(const bvh_detail::FastNodeTest&, double tmax) {
    return bvh_detail::roundUp(tmax);
  }
  static double limit(const SafeNodeTest&, double tmax) { return tmax; }

  uint32_t itemOf(uint32_t slot) const { return order_.empty() ? slot : order_[slot]; }

  // Asks for node i's cache lines (a hint: never faults, costs no wait).
  void prefetchNode(uint32_t i) const {
    const char* p = reinterpret_cast<const char*>(nodes_.data() + i);
    for (size_t line = 0; line < sizeof(BvhNode); line += 64) __builtin_prefetch(p + line);
  }

  // A child to visit: a node (count 0) or a leaf's slots, with its entry distance.
  template <class T>
  struct Entry {
    uint32_t index, count;
    T t;
  };
  // Up to W - 1 children wait per level of the W-wide tree, which has at most
  // kMaxDepth levels.
  static constexpr int kStackSize = (BvhNode::kWidth - 1) * kMaxDepth + 1;

  // Pushes the children in `mask` (two or more) farthest first, keeping the nearest in
  // `next`: the caller descends into it.
  template <class T>
  static void pushOrdered(const BvhNode& n, int mask, const T tEnter[BvhNode::kWidth],
                          Entry<T>* stack, int& sp, Entry<T>& next);

  template <class Test, class VisitLeaf, class Prefetch>
  bool candidatesWith(const Test& test, const double& tFar, VisitLeaf& visitLeaf,
                      Prefetch& prefetch, Order order) const;

  BvhNodes nodes_;
  std::vector<uint32_t> order_;
  size_t itemCount_ = 0;
  int depth_ = 0;
};

template <class T>
void Bvh::pushOrdered(const BvhNode& n, int mask, const T tEnter[BvhNode::kWidth], Entry<T>* stack,
                      int& sp, Entry<T>& next) {
  int c0 = __builtin_ctz(mask);
  mask &= mask - 1;
  int c1 = __builtin_ctz(mask);
  mask &= mask - 1;
  Entry<T> a{n.index[c0], n.count[c0], tEnter[c0]}, b{n.index[c1], n.count[c1], tEnter[c1]};
  if (b.t < a.t) std::swap(a, b);
  if (!mask) {  // the common case: two children hit
    stack[sp++] = b;
    next = a;
    return;
  }
  // More: insertion sort, farthest first.
  Entry<T> e[BvhNode::kWidth] = {b, a};
  int k = 2;
  for (; mask; mask &= mask - 1) {
    int c = __builtin_ctz(mask);
    Entry<T> x{n.index[c], n.count[c], tEnter[c]};
    int j = k++;
    for (; j > 0 && e[j - 1].t < x.t; --j) e[j] = e[j - 1];
    e[j] = x;
  }
  for (int i = 0; i < k - 1; ++i) stack[sp++] = e[i];
  next = e[k - 1];
}

template <class Test, class VisitLeaf, class Prefetch>
bool Bvh::candidatesWith(const Test& test, const double& tFar, VisitLeaf& visitLeaf,
                         Prefetch& prefetch, Order order) const {
  if (nodes_.empty()) return true;
  double lastFar = tFar;
  auto tmax = limit(test, lastFar);
  using T = decltype(tmax);
  T tEnter[BvhNode::kWidth];
  Entry<T> stack[kStackSize];
  int sp = 0;
  Entry<T> cur{0, 0, T(0)};  // the root: node 0
  for (;;) {
    if (cur.count == 0) {
      const BvhNode& n = nodes_[cur.index];
      int mask = test.test(n, tmax, tEnter);
      if (mask) {
        // Fetch every entered child now, so that their cache misses overlap (meshes, whose
        // leaves are not in slot order, fetch only the nodes; docs/performance-history.md).
        for (int m = mask; m; m &= m - 1) {
          const int c = __builtin_ctz(m);
          if (n.count[c] == 0) prefetchNode(n.index[c]);
          else prefetch(n.index[c], n.count[c]);
        }
        if ((mask & (mask - 1)) == 0) {
          int c = __builtin_ctz(mask);
          cur = {n.index[c], n.count[c], tEnter[c]};
        } else if (order == Order::Tree) {
          // The first child now, the others later (all of them unless an item blocks).
          int c = __builtin_ctz(mask);
          cur = {n.index[c], n.count[c], tEnter[c]};
          for (mask &= mask - 1; mask; mask &= mask - 1) {
            c = __builtin_ctz(mask);
            stack[sp++] = {n.index[c], n.count[c], tEnter[c]};
          }
        } else {
          // Nearest child now, the others later unless tFar closes in before they start.
          pushOrdered(n, mask, tEnter, stack, sp, cur);
        }
        continue;
      }
    } else {
      if (!visitLeaf(cur.index, cur.count)) return false;
      if (tFar != lastFar) {
        lastFar = tFar;
        tmax = limit(test, lastFar);
      }
    }
    for (;;) {
      if (sp == 0) return true;
      cur = stack[--sp];
      if (double(cur.t) <= tFar) break;
    }
  }
}

}  // namespace lucent
