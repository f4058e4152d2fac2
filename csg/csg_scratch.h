// Working storage of CsgNode's searches, reused from ray to ray: a CSG hit gathers its
// children's crossings into lists, and allocating those per ray cost more than combining
// them. Each thread keeps one set per level of CSG nesting (a child's search runs while
// its parent's storage is in use), so no two searches share a set and none allocates
// once its lists have grown to the sizes the scene needs.
#pragma once

#include "primitives/crossing.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace lucent {

struct CsgScratch {
  struct Tagged {
    Crossing c;
    size_t child;
  };
  std::vector<Tagged> all;  // every child's crossings, tagged with the child
  std::vector<char> in;     // each child's membership
  CrossingList list;        // one child's crossings
  CrossingList result;      // the node's own crossings (intersect)
};

// A set for the duration of one search: the calling thread's set at the current depth of
// nesting, emptied; the next one down for a search started while this one is held.
class CsgScratchLease {
 public:
  CsgScratchLease() {
    Pool& p = pool();
    if (p.depth == p.sets.size()) p.sets.push_back(std::make_unique<CsgScratch>());
    s_ = p.sets[p.depth++].get();
    s_->all.clear();
    s_->in.clear();
    s_->list.clear();
    s_->result.clear();
  }
  ~CsgScratchLease() { --pool().depth; }
  CsgScratchLease(const CsgScratchLease&) = delete;
  CsgScratchLease& operator=(const CsgScratchLease&) = delete;

  CsgScratch& operator*() const { return *s_; }
  CsgScratch* operator->() const { return s_; }

 private:
  struct Pool {
    std::vector<std::unique_ptr<CsgScratch>> sets;  // stable addresses as the pool grows
    size_t depth = 0;
  };
  static Pool& pool() {
    thread_local Pool p;
    return p;
  }
  CsgScratch* s_;
};

}  // namespace lucent
