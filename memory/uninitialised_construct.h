// What Lucent's array allocators share: new elements are left uninitialised on resize.
#pragma once

#include <new>
#include <utility>

namespace lucent {

// A base for allocators whose arrays are written before they are read: a vector's
// resize(n) default-initialises (for a trivial T: leaves as it was) instead of zeroing, so
// room that is reserved but never reached is never touched and costs no memory.
// Construction with arguments is the usual placement new.
struct UninitialisedConstruct {
  template <class U>
  void construct(U* p) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

}  // namespace lucent
