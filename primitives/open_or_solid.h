// The Shape base of a shape that is either an open surface (at most two roots,
// `sideRoots`) or a convex solid (one span, `solidSpan`), both found on the ray carried into
// the shape's frame: what the cylinder and the cone share. Self gives this base (its
// friend) `open_`, `frame_` (an AxisFrame) and
//   int sideRoots(const Ray& local, SurfaceRoot roots[2]) const;  // the open surface
//   bool solidSpan(const Ray& local, Span& out) const;            // the solid
#pragma once

#include "shape.h"
#include "span.h"

namespace lucent {

template <class Self>
class OpenOrSolidShape : public Shape {
 public:
  bool isSolid() const override { return !self().open_; }

  bool intersect(const Ray& ray, Hit& hit) const override {
    const Self& s = self();
    const Ray local = s.frame_.rayToLocal(ray);
    if (s.open_) {
      SurfaceRoot roots[2];
      const int n = s.sideRoots(local, roots);
      return intersectRoots(roots, n, ray, this, hit);
    }
    Span span;
    return s.solidSpan(local, span) && intersectSpan(span, ray, this, hit);
  }

  void crossings(const Ray& ray, CrossingList& out) const override {
    const Self& s = self();
    const Ray local = s.frame_.rayToLocal(ray);
    if (s.open_) {
      SurfaceRoot roots[2];
      const int n = s.sideRoots(local, roots);
      crossingsOfRoots(roots, n, ray, this, out);
      return;
    }
    Span span;
    if (!s.solidSpan(local, span)) span = Span();
    crossingsOfSpan(span, ray, this, out);
  }

 private:
  const Self& self() const { return static_cast<const Self&>(*this); }
};

}  // namespace lucent
