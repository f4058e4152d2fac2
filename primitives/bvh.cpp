#include "bvh.h"

#include "memory/huge_page_allocator.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <atomic>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include <sys/mman.h>
#include <unistd.h>

// Lanes of one vector picked by constant indices: GCC spells it __builtin_shuffle, clang
// (the fuzz build) __builtin_shufflevector; both compile to the same one instruction.
#if defined(__clang__)
#define LUCENT_SHUFFLE4(v, a, b, c, d) __builtin_shufflevector(v, v, a, b, c, d)
#else
#define LUCENT_SHUFFLE4(v, a, b, c, d) __builtin_shuffle(v, v4i{a, b, c, d})
#endif

namespace lucent {

BvhRay::BvhRay(const Ray& r) : o(r.o), invDir(1.0 / r.d) {
  for (int a = 0; a < 3; ++a) {
    // A -0 component gives -inf: the ray runs towards lo, so hi is its near plane.
    bool negative = std::signbit(invDir[a]);
    nearOff[a] = negative ? BvhNode::hi(a) : BvhNode::lo(a);
    farOff[a] = negative ? BvhNode::lo(a) : BvhNode::hi(a);
  }
}

AABB Bvh::bounds() const {
  AABB b;
  if (empty()) return b;
  for (int c = 0; c < BvhNode::kWidth; ++c)
    if (!nodes_[0].isEmpty(c)) b.expand(nodes_[0].bounds(c));
  return b;
}

namespace {

using bvh_detail::splat;
using bvh_detail::v4f;
using bvh_detail::v4i;
using bvh_detail::vmax;
using bvh_detail::vmin;

// The build works on four floats at a time (lanes 0..2 are x, y, z) through the vector
// extensions of bvh.h.
struct Box4 {
  v4f lo = splat(INFINITY);
  v4f hi = splat(-INFINITY);

  void expand(const Box4& b) {
    lo = vmin(lo, b.lo);
    hi = vmax(hi, b.hi);
  }
  void expand(v4f p) {
    lo = vmin(lo, p);
    hi = vmax(hi, p);
  }
  // Half the surface area (the SAH compares ratios only); lane 3 plays no part.
  float halfArea() const {
    const v4f e = hi - lo;
    // The three products in one multiplication (e times e rotated), summed in the order
    // e0e1 + e1e2 + e2e0, as written out lane by lane: the same float to the bit.
    const v4f p = e * LUCENT_SHUFFLE4(e, 1, 2, 0, 3);
    return p[0] + p[1] + p[2];
  }
};

// An item during the build: its box rounded outward, 32 bytes. Lane 3 of lo and hi holds
// the item number with bit 30 set: a normal float (never a denormal, inf or NaN, for
// numbers below 2^29), so the vector arithmetic on lane 3 stays cheap and harmless.
struct Ref {
  v4f lo, hi;

  static constexpr uint32_t kIdTag = 0x40000000u;
  static float encode(uint32_t id) {
    uint32_t bits = id | kIdTag;
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
  }
  uint32_t id() const {
    float f = lo[3];
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    return bits & ~kIdTag;
  }
  // Twice the centroid (the factor cancels in the binning), kept finite so that boxes
  // reaching beyond float range still bin.
  v4f centroid2() const { return vmin(vmax(lo + hi, splat(-FLT_MAX)), splat(FLT_MAX)); }
  Box4 box() const { return {lo, hi}; }
};
static_assert(sizeof(Ref) == 32, "build references are 32 bytes");

// The references and the nodes under construction live in transparent huge pages when
// they are large (huge_page_allocator.h): the build writes about 70 MB of fresh memory per
// million triangles, and a fault per 4 KB page cost about a third of the build.
using RefVector = std::vector<Ref, HugePageAllocator<Ref>>;

// Makes the whole pages of [p, p + bytes) present and writable in one system call
// instead of one fault per page (Linux 5.14; elsewhere the pages fault as usual).
void prefault(void* p, size_t bytes) {
#ifdef MADV_POPULATE_WRITE
  const uintptr_t page = uintptr_t(sysconf(_SC_PAGESIZE));
  uintptr_t b = (uintptr_t(p) + page - 1) & ~(page - 1);
  uintptr_t e = (uintptr_t(p) + bytes) & ~(page - 1);
  if (e > b) madvise(reinterpret_cast<void*>(b), e - b, MADV_POPULATE_WRITE);
#else
  (void)p;
  (void)bytes;
#endif
}

// A point rounded to float outward, lanes 0..2 (lane 3 is 0): the same as roundDown and
// roundUp of bvh.h lane by lane, without their branches, which mispredicted about half
// the time (the rounding direction of float(x) follows no pattern). nextDown of a finite
// float is one step of its bit pattern towards -inf: -1 for a positive float, +1 for a
// negative one or -0 (a +0 cannot need it: float(x) = +0 > x only for x < 0, which gives
// -0); float(x) = ±inf (|x| beyond float range) steps to ±FLT_MAX or stays, as there.
typedef double v4d __attribute__((vector_size(32)));
typedef int64_t v4l __attribute__((vector_size(32)));
v4f roundedDown(const Vec3& p) {
  const v4d x = {p.x, p.y, p.z, 0.0};
  const v4f f = __builtin_convertvector(x, v4f);
  const v4i above = __builtin_convertvector(__builtin_convertvector(f, v4d) > x, v4i);
  const v4i positive = f > splat(0.0f);
  return reinterpret_cast<v4f>(reinterpret_cast<v4i>(f) + (above & (positive | 1)));
}
// nextUp: +1 for a positive float or +0, -1 for a negative one (-0 cannot need it).
v4f roundedUp(const Vec3& p) {
  const v4d x = {p.x, p.y, p.z, 0.0};
  const v4f f = __builtin_convertvector(x, v4f);
  const v4i below = __builtin_convertvector(__builtin_convertvector(f, v4d) < x, v4i);
  const v4i negative = f < splat(0.0f);
  return reinterpret_cast<v4f>(reinterpret_cast<v4i>(f) + (below & (negative | 1)));
}

constexpr uint32_t kMaxItems = 1u << 29;  // see Ref
constexpr int kBins = 16;
// Beyond this depth splits are at the object median, which halves the item count, so the
// depth stays below kSahDepth + 30, plus at most W - 1 for leaves split into a node's
// free slots (Builder::build: one split per free slot), < Bvh::kMaxDepth.
constexpr int kSahDepth = 64;
static_assert(kSahDepth + 30 + (BvhNode::kWidth - 1) < Bvh::kMaxDepth, "traversal stack too small");
// Subtrees with fewer items are built by one task.
constexpr uint32_t kParallelMin = 4096;
// Nodes with fewer items bin into one set of bins (findSahSplit).
constexpr uint32_t kTwoBinSetsMin = 256;
// Nodes with at least this many items bin in parallel (findSahSplit).
constexpr uint32_t kParallelBinMin = 1u << 16;

// No default initialisers: only the bins in use are cleared.
struct Bin {
  v4f lo, hi;
  uint32_t count;
  void clear() {
    lo = splat(INFINITY);
    hi = splat(-INFINITY);
    count = 0;
  }
  Box4 box() const { return {lo, hi}; }
};

// The bins of a node: b[k][a] is bin k on axis a. `used` tells a set that holds bins
// from one that a TBB reduction default-constructed (left uncleared: it is large).
struct BinSet {
  Bin b[kBins][3];
  bool used = false;
  void clear(int nb) {
    for (int k = 0; k < nb; ++k)
      for (int a = 0; a < 3; ++a) b[k][a].clear();
    used = true;
  }
  void merge(const BinSet& o, int nb) {
    for (int k = 0; k < nb; ++k)
      for (int a = 0; a < 3; ++a) {
        b[k][a].lo = vmin(b[k][a].lo, o.b[k][a].lo);
        b[k][a].hi = vmax(b[k][a].hi, o.b[k][a].hi);
        b[k][a].count += o.b[k][a].count;
      }
  }
};

// The bin of each lane: (c - lo) · scale, clamped to the bins (the same computation in
// binning and partitioning, so both agree to the bit).
// A node of n items uses 4 + n/20 bins, at most 16 (the rule of Embree's binned
// builder): clearing and sweeping 3 × 16 bins cost more than binning a small node's
// items, for a tree hardly better (docs/performance-history.md).
struct Binner {
  v4f lo, scale;
  int count;
  Binner(const Box4& cbox, uint32_t items)
      : lo(cbox.lo),
        scale(splat(0.0f)),
        count(static_cast<int>(std::min<uint32_t>(kBins, 4 + items / 20))) {
    v4f ext = cbox.hi - cbox.lo;
    for (int a = 0; a < 3; ++a) scale[a] = ext[a] > 0.0f ? float(count) / ext[a] : 0.0f;
    scale[3] = 0.0f;
    lo[3] = 0.0f;
  }
  bool splittable(int a) const { return scale[a] > 0.0f && std::isfinite(scale[a]); }
  // Clamped in float (single instructions on SSE2, where int min/max are not).
  v4i bins(v4f c) const {
    v4f f = vmin(vmax((c - lo) * scale, splat(0.0f)), splat(float(count) - 0.5f));
    return __builtin_convertvector(f, v4i);
  }
};

// A subtree to build: its items refs[begin, end), their box and centroid box, and the
// decision taken for it (a leaf, or the split to apply).
struct Child {
  uint32_t begin, end;
  Box4 box, cbox;
  int depth;  // binary splits above it
  bool leaf;
  bool sah;  // split by `split`; otherwise at the object median
  struct Split {
    int axis = -1;
    int bin = 0;     // items in bins [0, bin) go left
    float cost = 0;  // left area × count + right area × count
    Box4 left, right;
  } split;
  uint32_t size() const { return end - begin; }
};

class Builder {
 public:
  // nodes: room for one node per ref; order: one slot per ref, filled at the leaves.
  // capacity: the nodes allocated; prefaultNodes: make them present ahead of the build
  // (large trees), instead of a fault per 4 KB page as each is first written.
  Builder(RefVector& refs, BvhNode* nodes, uint32_t capacity, bool prefaultNodes, uint32_t* order,
          const Bvh::Options& opt)
      : refs_(refs),
        nodes_(nodes),
        capacity_(capacity),
        prefault_(prefaultNodes),
        order_(order),
        opt_(opt) {
    makePresent(1);
  }

  uint32_t nodeCount() const { return next_.load(); }

  // Decides whether the subtree is a leaf and, if not, how it splits.
  void decide(Child& c) const {
    uint32_t n = c.size();
    c.sah = false;
    c.leaf = n <= std::max(1u, std::min(opt_.minLeafSize, opt_.maxLeafSize));
    if (c.leaf) return;
    c.sah = c.depth < kSahDepth && findSahSplit(c);
    if (c.sah && n <= opt_.maxLeafSize) {
      float leafCost = opt_.itemCost * float(n);
      float area = c.box.halfArea();
      float splitCost = area > 0.0f ? opt_.traversalCost + opt_.itemCost * c.split.cost / area
                                    : opt_.traversalCost + opt_.itemCost * float(n);
      c.leaf = !(splitCost < leafCost);
    } else if (!c.sah) {
      c.leaf = n <= opt_.maxLeafSize;
    }
  }

  // Fills node `node` with up to W children, made by splitting `self` (unless it is a
  // leaf) and then its largest non-leaf part again; recurses into the children that are
  // not leaves.
  // Returns the depth (binary splits) of the deepest leaf below.
  int build(uint32_t node, const Child& self) {
    constexpr int W = BvhNode::kWidth;
    Child kids[W];
    int k = 1;
    kids[0] = self;
    while (k < W) {
      int best = -1;
      float bestArea = -1.0f;
      for (int i = 0; i < k; ++i) {
        float area = kids[i].box.halfArea();
        if (!kids[i].leaf && area > bestArea) {
          best = i;
          bestArea = area;
        }
      }
      if (best < 0) break;
      Child left, right;
      apply(kids[best], left, right);
      kids[best] = left;
      kids[k++] = right;
    }
    // Slots still free are tested with the others anyway (all W boxes at once), so
    // leaves of two or more items are split into them: smaller boxes, fewer item tests,
    // no more nodes. Under the SAH this never costs more: each part's box lies inside
    // the leaf's. The leaf with the largest area × items goes first.
    while (k < W) {
      int best = -1;
      float bestCost = -1.0f;
      for (int i = 0; i < k; ++i) {
        float cost = kids[i].box.halfArea() * float(kids[i].size());
        if (kids[i].leaf && kids[i].size() >= 2 && cost > bestCost) {
          best = i;
          bestCost = cost;
        }
      }
      if (best < 0) break;
      Child& c = kids[best];
      // Two items part the same way whatever the plane: no binning for them.
      c.sah = c.size() > 2 && c.depth < kSahDepth && findSahSplit(c);
      Child left, right;
      apply(c, left, right, /*decideHalves=*/false);
      left.leaf = right.leaf = true;
      kids[best] = left;
      kids[k++] = right;
    }

    BvhNode& nd = nodes_[node];
    // The interior children's nodes side by side, taken with one atomic step: with one
    // step per child, the two threads of a parallel build contended for the counter.
    int interior = 0;
    for (int i = 0; i < k; ++i) interior += !kids[i].leaf;
    uint32_t childNode[W];
    uint32_t nextChild = interior ? next_.fetch_add(uint32_t(interior)) : 0;
    if (interior) makePresent(nextChild + uint32_t(interior));
    for (int i = 0; i < W; ++i) {
      for (int a = 0; a < 3; ++a) {
        nd.box[BvhNode::lo(a) + i] = i < k ? kids[i].box.lo[a] : INFINITY;
        nd.box[BvhNode::hi(a) + i] = i < k ? kids[i].box.hi[a] : -INFINITY;
      }
      if (i >= k) {
        nd.index[i] = BvhNode::kEmpty;
        nd.count[i] = 0;
      } else if (kids[i].leaf) {
        nd.index[i] = kids[i].begin;
        nd.count[i] = kids[i].size();
        // The leaf's items in ascending order (the refs were just partitioned: in
        // cache), so the order the partitions left them in does not matter.
        uint32_t* o = order_ + kids[i].begin;
        const uint32_t n = kids[i].size();
        for (uint32_t s = 0; s < n; ++s) o[s] = refs_[kids[i].begin + s].id();
        std::sort(o, o + n);
      } else {
        childNode[i] = nextChild++;
        nd.index[i] = childNode[i];
        nd.count[i] = 0;
      }
    }

    int depth[W] = {};
    auto sub = [&](int i) {
      depth[i] = kids[i].leaf ? kids[i].depth : build(childNode[i], kids[i]);
    };
    if (opt_.parallel && self.size() >= kParallelMin) {
      tbb::task_group tasks;
      for (int i = 1; i < k; ++i) tasks.run([&, i] { sub(i); });
      sub(0);
      tasks.wait();
    } else {
      for (int i = 0; i < k; ++i) sub(i);
    }
    return *std::max_element(depth, depth + k);
  }

 private:
  // Splits c as decided, and decides for both halves unless told not to.
  void apply(Child& c, Child& left, Child& right, bool decideHalves = true) {
    uint32_t mid;
    left = Child();
    right = Child();
    if (c.sah) {
      mid = partition(c, left.cbox, right.cbox);
      left.box = c.split.left;
      right.box = c.split.right;
    } else {
      mid = medianSplit(c.begin, c.end, c.cbox);
      boundsOf(c.begin, mid, left.box, left.cbox);
      boundsOf(mid, c.end, right.box, right.cbox);
    }
    left.begin = c.begin;
    left.end = mid;
    right.begin = mid;
    right.end = c.end;
    left.depth = right.depth = c.depth + 1;
    if (!decideHalves) return;
    decide(left);
    decide(right);
  }

  // Bins refs[first, last) into `set` (which it clears first).
  void binRange(const Binner& binner, uint32_t first, uint32_t last, BinSet& set) const {
    const int nb = binner.count;
    set.clear(nb);
    auto add = [&binner](BinSet& to, const Ref& r) {
      v4i b = binner.bins(r.centroid2());
      for (int a = 0; a < 3; ++a) {
        Bin& bin = to.b[b[a]][a];
        bin.lo = vmin(bin.lo, r.lo);
        bin.hi = vmax(bin.hi, r.hi);
        bin.count++;
      }
    };
    if (last - first >= kTwoBinSetsMin) {
      // Two sets of bins for alternate items, merged at the end: neighbouring items tend
      // to fall into the same bin, and one set would make each update wait for the last.
      // Small nodes skip this: clearing and merging the second set costs more than it
      // saves (most of the build's nodes are small).
      BinSet other;
      other.clear(nb);
      uint32_t i = first;
      for (; i + 1 < last; i += 2) {
        add(set, refs_[i]);
        add(other, refs_[i + 1]);
      }
      if (i < last) add(set, refs_[i]);
      set.merge(other, nb);
    } else {
      for (uint32_t i = first; i < last; ++i) add(set, refs_[i]);
    }
  }

  // Binned SAH: the cheapest of the planes between bins, per axis (Wald 2007).
  bool findSahSplit(Child& c) const {
    Binner binner(c.cbox, c.size());
    const int nb = binner.count;
    if (!binner.splittable(0) && !binner.splittable(1) && !binner.splittable(2))
      return false;  // every centroid in one point: no plane separates them

    // bins.b[k][a]: bin k on axis a (the three axes of a bin side by side, so the sweeps
    // below run them together and their dependency chains overlap).
    BinSet bins;
    if (opt_.parallel && c.size() >= kParallelBinMin) {
      // Large nodes (the top of the tree, where few subtrees run side by side) bin in
      // parallel: each task its own set, merged (min, max and counts: the same bins in
      // any order, so the same tree).
      bins = tbb::parallel_reduce(
          tbb::blocked_range<uint32_t>(c.begin, c.end, kParallelBinMin / 4), BinSet(),
          [&](const tbb::blocked_range<uint32_t>& r, BinSet acc) {
            BinSet part;
            binRange(binner, r.begin(), r.end(), part);
            if (acc.used) part.merge(acc, nb);
            return part;
          },
          [nb](BinSet x, const BinSet& y) {
            if (!x.used) return y;
            if (y.used) x.merge(y, nb);
            return x;
          });
    } else {
      binRange(binner, c.begin, c.end, bins);
    }

    // The plane left of bin k: items of bins [0, k) left, the others right.
    float rightArea[kBins][3], cost[kBins][3];
    uint32_t rightCount[kBins][3];
    Box4 acc[3];
    uint32_t cnt[3] = {0, 0, 0};
    for (int k = nb - 1; k > 0; --k)
      for (int a = 0; a < 3; ++a) {
        acc[a].expand(bins.b[k][a].box());
        cnt[a] += bins.b[k][a].count;
        rightArea[k][a] = acc[a].halfArea();
        rightCount[k][a] = cnt[a];
      }
    for (int a = 0; a < 3; ++a) {
      acc[a] = Box4();
      cnt[a] = 0;
    }
    for (int k = 1; k < nb; ++k)
      for (int a = 0; a < 3; ++a) {
        acc[a].expand(bins.b[k - 1][a].box());
        cnt[a] += bins.b[k - 1][a].count;
        cost[k][a] =
            cnt[a] == 0 || rightCount[k][a] == 0
                ? INFINITY
                : acc[a].halfArea() * float(cnt[a]) + rightArea[k][a] * float(rightCount[k][a]);
      }

    Child::Split& s = c.split;
    s = Child::Split();
    float best = INFINITY;
    for (int a = 0; a < 3; ++a) {
      if (!binner.splittable(a)) continue;
      for (int k = 1; k < nb; ++k)
        if (cost[k][a] < best) {
          best = cost[k][a];
          s.axis = a;
          s.bin = k;
        }
    }
    if (s.axis < 0) return false;  // only infinite costs (boxes beyond float range)
    s.cost = best;
    for (int k = 0; k < nb; ++k) (k < s.bin ? s.left : s.right).expand(bins.b[k][s.axis].box());
    return true;
  }

  // Moves the refs left of the split plane first; returns the first of the right ones.
  // Branch-free (Lomuto's scheme: every ref is swapped with the first right one, which
  // moves on past it when it goes left): which side a ref goes to follows its centroid
  // and does not predict well, and a mispredicted branch per ref cost more than the
  // swap. The order within each side is of no consequence: which refs each node holds
  // is decided by the planes alone, and each leaf lists its items in ascending order
  // (build()), so the tree is the same whatever the order the partition leaves.
  uint32_t partition(const Child& c, Box4& lcbox, Box4& rcbox) {
    switch (c.split.axis) {
      case 0:
        return partitionOn<0>(c, lcbox, rcbox);
      case 1:
        return partitionOn<1>(c, lcbox, rcbox);
      default:
        return partitionOn<2>(c, lcbox, rcbox);
    }
  }

  // partition() along axis A (a constant, so picking lane A is one shuffle).
  template <int A>
  uint32_t partitionOn(const Child& c, Box4& lcbox, Box4& rcbox) {
    const Binner binner(c.cbox, c.size());
    // A ref goes left when its bin is below the split bin. bins() truncates
    // (c - lo) · scale clamped to [0, count - 0.5], and bin is in [1, count - 1], so that
    // is (c - lo) · scale < bin: the same floats, the same decisions.
    const v4f lo = binner.lo, scale = binner.scale, split = splat(float(c.split.bin));
    Ref* refs = refs_.data();
    uint32_t l = c.begin;
    // The boxes in locals: through the references the compiler had to store them back
    // after every swap (a v4f store into refs might have changed them).
    Box4 lc = lcbox, rc = rcbox;
    // A side's box must not grow by a ref that goes to the other side: that ref's
    // centroid is replaced by a quiet NaN there, which vmin and vmax (x < y ? x : y with
    // the NaN as x) ignore, keeping the box's own value.
    const v4i qnan = reinterpret_cast<v4i>(splat(NAN));
    for (uint32_t i = c.begin; i < c.end; ++i) {
      const Ref r = refs[i];
      const v4f ctr = r.centroid2();
      const v4i goesLeft = (ctr - lo) * scale < split;
      // All ones in every lane if the ref goes left.
      const v4i m = LUCENT_SHUFFLE4(goesLeft, A, A, A, A);
      const v4i ci = reinterpret_cast<v4i>(ctr);
      const v4f toLeft = reinterpret_cast<v4f>(ci | (qnan & ~m));
      const v4f toRight = reinterpret_cast<v4f>(ci | (qnan & m));
      lc.lo = vmin(toLeft, lc.lo);
      lc.hi = vmax(toLeft, lc.hi);
      rc.lo = vmin(toRight, rc.lo);
      rc.hi = vmax(toRight, rc.hi);
      refs[i] = refs[l];
      refs[l] = r;
      l -= uint32_t(m[0]);
    }
    lcbox = lc;
    rcbox = rc;
    return l;
  }

  // Half the refs on each side, split along the widest centroid extent.
  uint32_t medianSplit(uint32_t begin, uint32_t end, const Box4& cbox) {
    v4f ext = cbox.hi - cbox.lo;
    int a = ext[0] >= ext[1] && ext[0] >= ext[2] ? 0 : (ext[1] >= ext[2] ? 1 : 2);
    uint32_t mid = begin + (end - begin) / 2;
    if (ext[a] > 0.0f) {
      std::nth_element(refs_.begin() + begin, refs_.begin() + mid, refs_.begin() + end,
                       [a](const Ref& x, const Ref& y) {
                         float cx = x.centroid2()[a], cy = y.centroid2()[a];
                         return cx < cy || (cx == cy && x.id() < y.id());
                       });
    }
    return mid;
  }

  void boundsOf(uint32_t begin, uint32_t end, Box4& box, Box4& cbox) const {
    for (uint32_t i = begin; i < end; ++i) {
      box.expand(refs_[i].box());
      cbox.expand(refs_[i].centroid2());
    }
  }

  // Makes the nodes below `end`, and a block beyond, present: one system call per block
  // of 1 MB (prefault) instead of a fault per 4 KB page. Whichever thread first needs a
  // block populates it; a node written before its block is present just faults as usual.
  void makePresent(uint32_t end) {
    if (!prefault_) return;
    constexpr uint32_t kBlock = (1u << 20) / sizeof(BvhNode);
    uint32_t done = present_.load(std::memory_order_relaxed);
    while (done < capacity_ && end + kBlock > done) {
      const uint32_t next = std::min(capacity_, done + kBlock);
      if (present_.compare_exchange_weak(done, next, std::memory_order_relaxed)) {
        prefault(nodes_ + done, size_t(next - done) * sizeof(BvhNode));
        done = next;
      }
    }
  }

  RefVector& refs_;
  BvhNode* nodes_;
  const uint32_t capacity_;
  const bool prefault_;
  uint32_t* order_;
  const Bvh::Options& opt_;
  // On a cache line of its own: the fields above are read all the time by every thread.
  alignas(64) std::atomic<uint32_t> next_{1};  // node 0 is the root
  std::atomic<uint32_t> present_{0};           // nodes [0, present_) made present
};

}  // namespace

Bvh::Bvh(const std::vector<AABB>& itemBounds, const Options& options)
    : Bvh(
          itemBounds.size(), [&](uint32_t i) { return itemBounds[i]; }, options) {}

Bvh::Bvh(size_t count, const std::function<AABB(uint32_t)>& boundsOf, const Options& options) {
  if (count >= kMaxItems) throw std::invalid_argument("BVH: too many items");
  if (options.maxLeafSize == 0) throw std::invalid_argument("BVH: maxLeafSize must be >= 1");
  // The items' boxes rounded outward, in parallel for large inputs (boundsOf must then
  // be safe to call from several threads: it only reads). Items with an empty box are
  // marked and dropped after.
  RefVector refs(count);
  struct Bounds {
    Box4 box, cbox;
    size_t empties = 0;
    bool unbounded = false;
    void join(const Bounds& o) {
      box.expand(o.box);
      cbox.expand(o.cbox);
      empties += o.empties;
      unbounded = unbounded || o.unbounded;
    }
  };
  auto fill = [&](uint32_t first, uint32_t last, Bounds& acc) {
    for (uint32_t i = first; i < last; ++i) {
      AABB b = boundsOf(i);
      float id = Ref::encode(i);
      if (b.empty() || !b.isBounded()) {
        acc.unbounded = acc.unbounded || !b.empty();
        acc.empties++;
        refs[i] = Ref{splat(NAN), splat(NAN)};
        continue;
      }
      Ref& r = refs[i];
      r = Ref{roundedDown(b.lo), roundedUp(b.hi)};
      r.lo[3] = r.hi[3] = id;
      acc.box.expand(r.box());
      acc.cbox.expand(r.centroid2());
    }
  };
  Bounds all;
  if (options.parallel && count >= kParallelMin) {
    all = tbb::parallel_reduce(
        tbb::blocked_range<uint32_t>(0, uint32_t(count), 4096), Bounds(),
        [&](const tbb::blocked_range<uint32_t>& r, Bounds acc) {
          fill(r.begin(), r.end(), acc);
          return acc;
        },
        [](Bounds a, const Bounds& b) {
          a.join(b);
          return a;
        });
  } else {
    fill(0, uint32_t(count), all);
  }
  if (all.unbounded) throw std::invalid_argument("BVH: an item has an unbounded box");
  if (all.empties)  // never hit: not in the tree
    refs.erase(
        std::remove_if(refs.begin(), refs.end(), [](const Ref& r) { return std::isnan(r.lo[0]); }),
        refs.end());
  const Box4 box = all.box, cbox = all.cbox;
  itemCount_ = refs.size();
  if (refs.empty()) return;

  // At most one node per item (each holds at least one of the binary tree's interior
  // nodes, which number items - 1, and the root). The allocator leaves new nodes
  // uninitialised, so those never used cost nothing. Large trees are built in place in
  // ordinary 4 KB pages made present a block ahead of the build (Builder::makePresent).
  // Not in huge pages, since rays were slower on nodes there (the reason was not found);
  // and not built in huge pages and copied, since the copy costs more than the faults it
  // saves (docs/performance-history.md, "Figures behind comments in the code").
  nodes_.resize(refs.size());
  order_.resize(refs.size());
  Builder builder(refs, nodes_.data(), uint32_t(refs.size()),
                  HugePageAllocator<BvhNode>::huge(refs.size()), order_.data(), options);
  Child root;
  root.begin = 0;
  root.end = static_cast<uint32_t>(refs.size());
  root.box = box;
  root.cbox = cbox;
  root.depth = 0;
  builder.decide(root);
  // A root that is a leaf becomes node 0's only child.
  depth_ = builder.build(0, root);
  // The references (32 bytes per item) are done with.
  refs = RefVector();
  // The capacity stays: shrinking would copy the tree, and the nodes beyond nodeCount
  // cost address space, not memory (none was written; at most the 2 MB made present
  // ahead of the last node are resident).
  nodes_.resize(builder.nodeCount());
}

}  // namespace lucent
