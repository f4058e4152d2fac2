// An allocator for large temporary arrays: blocks of 4 MB or more in transparent huge pages.
#pragma once

#include "uninitialised_construct.h"

#include <cstddef>
#include <new>
#include <vector>

#include <sys/mman.h>

namespace lucent {

// Large blocks are whole 2 MB pages with madvise(MADV_HUGEPAGE). In this VM writing memory
// in 4 KB pages was several times slower than in 2 MB pages even once the pages were
// present (docs/performance-history.md), and each 4 KB page costs a fault on first touch.
// Loading a mesh file and building its BVH write several hundred MB of fresh memory per
// million triangles, mostly in arrays freed before the render.
// Smaller blocks take ordinary memory: a huge page would make a few elements cost 2 MB.
// Leaves new elements uninitialised on resize (std::vector<T, HugePageAllocator<T>>(n)
// holds garbage for a trivial T): every element must be written before it is read; the
// room reserved but never reached is never touched.
template <class T>
struct HugePageAllocator : UninitialisedConstruct {
  using value_type = T;
  static constexpr std::size_t kHugePage = std::size_t(2) << 20;
  static constexpr std::size_t kHugeMin = 2 * kHugePage;
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) {}
  static bool huge(std::size_t n) { return n * sizeof(T) >= kHugeMin; }
  static std::size_t rounded(std::size_t n) {
    return (n * sizeof(T) + kHugePage - 1) & ~(kHugePage - 1);
  }
  T* allocate(std::size_t n) {
    if (!huge(n)) return static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t(64)));
    // Whole huge pages, so the advice covers this block alone.
    void* p = ::operator new(rounded(n), std::align_val_t(kHugePage));
#ifdef MADV_HUGEPAGE
    madvise(p, rounded(n), MADV_HUGEPAGE);
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) {
    ::operator delete(p, std::align_val_t(huge(n) ? kHugePage : 64));
  }
  friend bool operator==(const HugePageAllocator&, const HugePageAllocator&) { return true; }
  friend bool operator!=(const HugePageAllocator&, const HugePageAllocator&) { return false; }
};

// A vector whose large blocks are huge pages (elements uninitialised on resize, as above).
template <class T>
using HugeVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace lucent
