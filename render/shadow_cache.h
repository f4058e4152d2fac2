// POV-Ray's shadow cache: the object that blocked the last shadow ray towards a light is
// tested first by the next one. Neighbouring points and the samples of an area light are
// mostly shadowed by the same object, so a blocked ray is usually answered by one test
// instead of a search of the world. It is an order change of an any-hit query only: it
// never changes whether a ray is blocked (World::occluder).
#pragma once

#include "scenegraph/world.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lucent {

// A fresh owner id for a tracer: never 0, never handed out twice in a process.
uint64_t newShadowCacheOwner();

// One slot per light. It lives in a thread's TraceContext (trace_context.h), emptied at
// the start of every tile (ray and test counts then do not depend on which thread
// rendered which tile); threads never share it.
class ShadowCache {
 public:
  // Light `light`'s slot for the tracer `owner` (of a scene with `lights` lights):
  // World::kNoObject, or an id of that tracer's world. A cache last used by another
  // owner is emptied first: its ids name objects of another world, which may no longer
  // exist, and they are never handed out again.
  World::ObjectId& slot(uint64_t owner, size_t light, size_t lights) {
    if (owner != owner_ || blockers_.size() != lights) {
      owner_ = owner;
      blockers_.assign(lights, World::kNoObject);
    }
    return blockers_[light];
  }
  // Forgets every blocker.
  void clear() {
    owner_ = 0;
    blockers_.clear();
  }

 private:
  uint64_t owner_ = 0;
  std::vector<World::ObjectId> blockers_;
};

}  // namespace lucent
