// What one thread carries while it traces, handed down every call of the tracer: the ray
// counts, the shadow cache and the adaptive area sampler's working memory. The render loop
// makes one per worker thread, so threads share none of it and nothing of it hides in
// thread_local state. (The intersection-test counters and the shapes' scratch buffers stay
// per thread below the Shape interface, primitives/test_counts.h: a context there would be
// an argument of every shape's every test.)
#pragma once

#include "adaptive_area.h"
#include "ray_stats.h"
#include "shadow_cache.h"

#include "primitives/math.h"
#include "primitives/test_counts.h"

#include <vector>

namespace lucent {

// A lower layer's mirror ray waiting to be traced (Tracer::shadeLayers): its direction,
// weight and the layer's shading normal.
struct LayerMirror {
  Vec3 direction{0.0};
  Vec3 normal{0.0};
  Color weight{0.0f};
  double power = 1.0;  // SecondaryRays::mirrorPower
};

class TraceContext {
 public:
  // The counts of the work under way (a tile), which the tracer adds to.
  RayStats stats;
  // The object that blocked each light's last shadow ray (POV-Ray's shadow cache).
  ShadowCache shadowCache;
  // Reused from one adaptive area light's estimate to the next (no allocation per point).
  AdaptiveAreaSampler areaSampler;
  // A stack of lower layers' mirror rays: each call pushes its own above the entries of the
  // calls it recursed from and pops them before it returns (no allocation per hit).
  std::vector<LayerMirror> layerMirrors;
  // The ray being traced was reflected, or went on from a reflection: it does not see
  // reflection="false" objects, where the others do not see image="false" ones
  // (POV-Ray's ray kinds). Set around each mirror ray's trace.
  bool reflected = false;

  // Begins a tile: no counts yet, and an empty shadow cache, so that what a tile counts
  // (rays, tests, cache hits) never depends on which tiles its thread traced before.
  void startTile() {
    stats = RayStats();
    shadowCache.clear();
    testsAtStart_ = threadTestCounts;
  }
  // Ends the tile, which ran on this thread from startTile() on: adds the thread's
  // intersection tests since then to its counts, and the counts to total(). Returns them.
  const RayStats& finishTile() {
    stats.tests = threadTestCounts - testsAtStart_;
    total_ += stats;
    return stats;
  }
  // The counts of every tile finished with this context.
  const RayStats& total() const { return total_; }

 private:
  TestCounts testsAtStart_;
  RayStats total_;
};

}  // namespace lucent
