#include "bvh.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <atomic>
#include <cfloat>
#include <cmath>
#include <stdexcept>

namespace lucent {

BvhRay::BvhRay(const Ray& r) : o(r.o), invDir(1.0 / r.d) {
  for (int a = 0; a < 3; ++a) {
    // A -0 component gives -inf: the ray runs towards lo, so hi is its near plane.
    bool negative = std::signbit(invDir[a]);
    nearIdx[a] = negative ? a + 3 : a;
    farIdx[a] = negative ? a : a + 3;
  }
}

namespace {

using glm::vec3;

// Double to float, rounded down or up, so float boxes contain the double ones.
float roundDown(double x) {
  float f = static_cast<float>(x);
  return double(f) > x ? std::nextafter(f, -INFINITY) : f;
}
float roundUp(double x) {
  float f = static_cast<float>(x);
  return double(f) < x ? std::nextafter(f, INFINITY) : f;
}

struct Box3f {
  vec3 lo{INFINITY};
  vec3 hi{-INFINITY};

  void expand(const Box3f& b) { lo = glm::min(lo, b.lo); hi = glm::max(hi, b.hi); }
  void expand(const vec3& p) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
  // Half the surface area: the SAH only compares ratios.
  float halfArea() const {
    vec3 e = hi - lo;
    return e.x * e.y + e.y * e.z + e.z * e.x;
  }
};

// An item during the build: its box (rounded outward) and its number.
struct Ref {
  vec3 lo, hi;
  uint32_t id;

  // Twice the centroid (the factor cancels in the binning), kept finite so that boxes
  // reaching beyond float range still bin.
  vec3 centroid2() const { return glm::clamp(lo + hi, vec3(-FLT_MAX), vec3(FLT_MAX)); }
  Box3f box() const { return {lo, hi}; }
};

constexpr int kBins = 16;
// Beyond this depth splits are at the object median, which halves the item count, so the
// depth stays below kSahDepth + 32 < Bvh::kMaxDepth for any 32-bit item count.
constexpr int kSahDepth = 64;
static_assert(kSahDepth + 33 < Bvh::kMaxDepth, "traversal stack too small");
// Subtrees with fewer items are built by one task.
constexpr uint32_t kParallelMin = 4096;

struct Bin {
  Box3f box;
  uint32_t count = 0;
};

class Builder {
 public:
  Builder(std::vector<Ref>& refs, BvhNode* nodes, const Bvh::Options& opt)
      : refs_(refs), nodes_(nodes), opt_(opt) {}

  uint32_t nodeCount() const { return next_.load(); }

  // Builds the subtree of `node` over refs_[begin, end); returns its depth.
  int build(uint32_t node, uint32_t begin, uint32_t end, const Box3f& box, const Box3f& cbox,
            int depth) {
    BvhNode& nd = nodes_[node];
    for (int a = 0; a < 3; ++a) {
      nd.box[a] = box.lo[a];
      nd.box[a + 3] = box.hi[a];
    }
    uint32_t n = end - begin;
    if (n == 1) return makeLeaf(nd, begin, n, depth);

    Split s;
    bool sah = depth < kSahDepth && findSahSplit(begin, end, box, cbox, s);
    if (sah && n <= opt_.maxLeafSize) {
      float leafCost = opt_.itemCost * float(n);
      float area = box.halfArea();
      float splitCost = area > 0.0f ? opt_.traversalCost + opt_.itemCost * s.cost / area
                                    : opt_.traversalCost + opt_.itemCost * float(n);
      if (!(splitCost < leafCost)) return makeLeaf(nd, begin, n, depth);
    }
    if (!sah && n <= opt_.maxLeafSize) return makeLeaf(nd, begin, n, depth);

    uint32_t mid;
    Box3f lbox, rbox, lcbox, rcbox;
    if (sah) {
      mid = partition(begin, end, cbox, s, lcbox, rcbox);
      lbox = s.left;
      rbox = s.right;
    } else {
      mid = medianSplit(begin, end, cbox);
      boundsOf(begin, mid, lbox, lcbox);
      boundsOf(mid, end, rbox, rcbox);
    }

    uint32_t child = next_.fetch_add(2);
    nd.index = child;
    nd.count = 0;
    int dl = 0, dr = 0;
    auto left = [&] { dl = build(child, begin, mid, lbox, lcbox, depth + 1); };
    auto right = [&] { dr = build(child + 1, mid, end, rbox, rcbox, depth + 1); };
    if (opt_.parallel && n >= kParallelMin) {
      tbb::parallel_invoke(left, right);
    } else {
      left();
      right();
    }
    return std::max(dl, dr);
  }

 private:
  struct Split {
    int axis = -1;
    int bin = 0;      // items in bins [0, bin) go left
    float cost = 0;   // left area × count + right area × count
    Box3f left, right;
  };

  static int makeLeaf(BvhNode& nd, uint32_t begin, uint32_t n, int depth) {
    nd.index = begin;
    nd.count = n;
    return depth;
  }

  static int binOf(float c, float lo, float scale) {
    int b = static_cast<int>((c - lo) * scale);
    return std::min(std::max(b, 0), kBins - 1);
  }

  // Binned SAH: the cheapest of the kBins-1 planes per axis (Wald 2007).
  bool findSahSplit(uint32_t begin, uint32_t end, const Box3f& box, const Box3f& cbox,
                    Split& s) const {
    (void)box;
    vec3 ext = cbox.hi - cbox.lo;
    vec3 scale;
    bool any = false;
    for (int a = 0; a < 3; ++a) {
      scale[a] = ext[a] > 0.0f ? float(kBins) / ext[a] : 0.0f;
      any = any || ext[a] > 0.0f;
    }
    if (!any) return false;  // every centroid in one point: no plane separates them

    Bin bins[3][kBins];
    for (uint32_t i = begin; i < end; ++i) {
      const Ref& r = refs_[i];
      vec3 c = r.centroid2();
      for (int a = 0; a < 3; ++a) {
        if (scale[a] == 0.0f) continue;
        Bin& b = bins[a][binOf(c[a], cbox.lo[a], scale[a])];
        b.count++;
        b.box.expand(r.box());
      }
    }

    float best = INFINITY;
    for (int a = 0; a < 3; ++a) {
      if (scale[a] == 0.0f) continue;
      float rightArea[kBins];
      uint32_t rightCount[kBins];
      Box3f acc;
      uint32_t cnt = 0;
      for (int i = kBins - 1; i > 0; --i) {
        acc.expand(bins[a][i].box);
        cnt += bins[a][i].count;
        rightArea[i] = acc.halfArea();
        rightCount[i] = cnt;
      }
      acc = Box3f();
      cnt = 0;
      for (int i = 1; i < kBins; ++i) {
        acc.expand(bins[a][i - 1].box);
        cnt += bins[a][i - 1].count;
        if (cnt == 0 || rightCount[i] == 0) continue;
        float cost = acc.halfArea() * float(cnt) + rightArea[i] * float(rightCount[i]);
        if (cost < best) {
          best = cost;
          s.axis = a;
          s.bin = i;
        }
      }
    }
    if (s.axis < 0) return false;  // only infinite costs (boxes beyond float range)
    s.cost = best;
    for (int i = 0; i < kBins; ++i)
      (i < s.bin ? s.left : s.right).expand(bins[s.axis][i].box);
    return true;
  }

  // Moves the refs left of the split plane first; returns the first of the right ones.
  uint32_t partition(uint32_t begin, uint32_t end, const Box3f& cbox, const Split& s,
                     Box3f& lcbox, Box3f& rcbox) {
    int a = s.axis;
    float scale = float(kBins) / (cbox.hi[a] - cbox.lo[a]);
    uint32_t i = begin, j = end;
    while (i < j) {
      vec3 c = refs_[i].centroid2();
      if (binOf(c[a], cbox.lo[a], scale) < s.bin) {
        lcbox.expand(c);
        ++i;
      } else {
        rcbox.expand(c);
        std::swap(refs_[i], refs_[--j]);
      }
    }
    return i;
  }

  // Half the refs on each side, split along the widest centroid extent.
  uint32_t medianSplit(uint32_t begin, uint32_t end, const Box3f& cbox) {
    vec3 ext = cbox.hi - cbox.lo;
    int a = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
    uint32_t mid = begin + (end - begin) / 2;
    if (ext[a] > 0.0f) {
      std::nth_element(refs_.begin() + begin, refs_.begin() + mid, refs_.begin() + end,
                       [a](const Ref& x, const Ref& y) {
                         float cx = x.centroid2()[a], cy = y.centroid2()[a];
                         return cx < cy || (cx == cy && x.id < y.id);
                       });
    }
    return mid;
  }

  void boundsOf(uint32_t begin, uint32_t end, Box3f& box, Box3f& cbox) const {
    for (uint32_t i = begin; i < end; ++i) {
      box.expand(refs_[i].box());
      cbox.expand(refs_[i].centroid2());
    }
  }

  std::vector<Ref>& refs_;
  BvhNode* nodes_;
  const Bvh::Options& opt_;
  std::atomic<uint32_t> next_{2};  // [0] root, [1] padding: sibling pairs start even
};

}  // namespace

Bvh::Bvh(const std::vector<AABB>& itemBounds, const Options& options)
    : Bvh(itemBounds.size(), [&](uint32_t i) { return itemBounds[i]; }, options) {}

Bvh::Bvh(size_t count, const std::function<AABB(uint32_t)>& boundsOf, const Options& options) {
  if (count >= (size_t(1) << 31)) throw std::invalid_argument("BVH: too many items");
  if (options.maxLeafSize == 0) throw std::invalid_argument("BVH: maxLeafSize must be >= 1");
  std::vector<Ref> refs;
  refs.reserve(count);
  Box3f box, cbox;
  for (uint32_t i = 0; i < count; ++i) {
    AABB b = boundsOf(i);
    if (b.empty()) continue;  // never hit: not in the tree
    if (!b.isBounded()) throw std::invalid_argument("BVH: an item has an unbounded box");
    Ref r{vec3(roundDown(b.lo.x), roundDown(b.lo.y), roundDown(b.lo.z)),
          vec3(roundUp(b.hi.x), roundUp(b.hi.y), roundUp(b.hi.z)), i};
    box.expand(r.box());
    cbox.expand(r.centroid2());
    refs.push_back(r);
  }
  itemCount_ = refs.size();
  if (refs.empty()) return;

  // At most 2 nodes per item (one leaf each, one interior per pair) plus the padding.
  // new[] of a trivial type leaves the pages untouched: only the used ones cost memory.
  size_t capacity = 2 * refs.size() + 2;
  std::unique_ptr<BvhNode[]> scratch(new BvhNode[capacity]);
  Builder builder(refs, scratch.get(), options);
  depth_ = builder.build(0, 0, static_cast<uint32_t>(refs.size()), box, cbox, 0);
  scratch[1] = BvhNode{{0, 0, 0, 0, 0, 0}, 0, 0};

  nodes_.assign(scratch.get(), scratch.get() + builder.nodeCount());
  scratch.reset();
  order_.resize(refs.size());
  for (size_t k = 0; k < refs.size(); ++k) order_[k] = refs[k].id;
}

}  // namespace lucent
