// The media a ray travels in: a small stack of the solids it has entered and not left,
// innermost on top, so that leaving a glass inside water refracts into water (nested
// objects, as POV-Ray's interior list). Keyed by material: the surfaces of a CSG solid's
// medium stand for it by one material (render/medium_crossing.h), so entering through one
// leaf and leaving through another pairs up.
#pragma once

#include "scenegraph/material.h"

#include <array>

namespace lucent {

// Whether two materials fill a solid alike: the same material, or the same interior terms
// (index, absorption, fade, fade-on-exit, hollow), as one POV-Ray interior worn by the parts
// of a CSG solid with different textures.
inline bool sameMedium(const Material& a, const Material& b) {
  return &a == &b ||
         (a.ior == b.ior && a.absorption == b.absorption && a.fadeDistance == b.fadeDistance &&
          a.fadePower == b.fadePower && a.fadeColor == b.fadeColor &&
          a.fadeOnExit == b.fadeOnExit && a.hollow == b.hollow);
}

class MediaStack {
 public:
  // Deeper nesting than this is ignored (the push is dropped): eight solids inside each
  // other are far beyond any scene we know, and the stack is copied per ray.
  static constexpr int kCapacity = 8;

  bool empty() const { return size_ == 0; }
  int size() const { return size_; }
  // The medium the ray is in, or null for the scene's outside (index 1, no absorption).
  const Material* top() const { return size_ > 0 ? items_[size_ - 1] : nullptr; }
  double ior() const { return size_ > 0 ? items_[size_ - 1]->ior : 1.0; }
  // Whether every medium the ray is in is hollow (true outside all): then fog applies, as
  // POV-Ray's "hollow ray".
  bool allHollow() const {
    for (int i = 0; i < size_; ++i)
      if (!items_[i]->hollow) return false;
    return true;
  }

  // Whether fog applies over a stretch that ends where the ray leaves `leaving` (null: it
  // leaves nothing there): outside every solid the ray is known to be in, or inside hollow
  // ones only. Known by this stack, as POV-Ray knows it by its interior list: a ray that
  // came in through a clipped solid's gap never entered it, and leaving its inner side ends
  // a stretch outside it.
  bool fogStretch(const Material* leaving) const {
    return allHollow() && (!leaving || leaving->hollow || !contains(leaving));
  }

  void push(const Material* m) {
    if (size_ < kCapacity) items_[size_++] = m;
  }
  // Whether the ray is in m (this very material: two of equal terms are two media, as
  // two POV-Ray interiors; an opaque solid's default medium must not pass for a cut's).
  bool contains(const Material* m) const {
    for (int i = 0; i < size_; ++i)
      if (items_[i] == m) return true;
    return false;
  }
  // Removes the innermost occurrence of m; returns false (and changes nothing) if the ray
  // was not known to be inside m (a camera inside a solid it did not start in, say).
  bool remove(const Material* m) {
    for (int i = size_ - 1; i >= 0; --i) {
      if (items_[i] != m) continue;
      for (int j = i; j + 1 < size_; ++j) items_[j] = items_[j + 1];
      --size_;
      return true;
    }
    return false;
  }

 private:
  std::array<const Material*, kCapacity> items_{};
  int size_ = 0;
};

}  // namespace lucent
