// <isosurface>: POV-Ray 3.7's isosurface. The solid is where f(p) < threshold inside a
// container (a box or a sphere), f any function of the object-space point (ScalarField);
// the container's surface closes it where f is below the threshold there, unless `open`
// (then only the surface f = threshold is left, and it is no solid).
//
// Method: Lipschitz-bounded root isolation, the bound being the declared max_gradient L
// (POV-Ray's documentation of max_gradient; Hart, "Sphere Tracing: A Geometric Method for
// the Antialiased Ray Tracing of Implicit Surfaces", The Visual Computer, 1996): along the
// ray g(t) = f(o + t·d) − threshold changes by at most L·|d| per unit t, so an interval
// whose end values satisfy |g0| + |g1| > L·|d|·(t1 − t0), both of one sign, holds no
// crossing and is skipped. Every other interval is halved, left half first (so crossings
// come out in order), down to `accuracy` in object-space length; a leaf whose ends differ
// in sign holds a crossing, narrowed further by the Illinois variant of false position.
// Two crossings closer than `accuracy` may be missed as a pair (POV-Ray: the same), which
// keeps them alternating. This is POV-Ray's interval test (isosurface.cpp, after R. Suzuki),
// with every crossing kept for CSG instead of the first. Where the function changes faster
// than L the test may skip a crossing: the largest slope seen is recorded (GradientRecord)
// so that the renderer can say so, as POV-Ray does after a render.
#pragma once

#include "scalar_field.h"
#include "shape.h"

#include <atomic>
#include <memory>

namespace lucent {

struct IsosurfaceContainer {
  enum Kind { Box, Sphere } kind = Box;
  Vec3 min{-1.0}, max{1.0};  // a box
  Vec3 center{0.0};          // a sphere
  double radius = 1.0;
};

// The largest gradient magnitude the root search saw (estimated from pairs of values along
// rays), shared by the render threads.
class GradientRecord {
 public:
  void note(double g) {
    double cur = largest_.load(std::memory_order_relaxed);
    while (g > cur && !largest_.compare_exchange_weak(cur, g, std::memory_order_relaxed)) {
    }
  }
  double largest() const { return largest_.load(std::memory_order_relaxed); }

 private:
  std::atomic<double> largest_{0.0};
};

class Isosurface final : public Shape {
 public:
  struct Params {
    std::shared_ptr<const ScalarField> field;  // required
    double threshold = 0.0;
    IsosurfaceContainer container;
    double maxGradient = 1.1;
    double accuracy = 0.001;
    bool open = false;
    std::shared_ptr<GradientRecord> record;  // may be null
  };
  // Payload: which surface a hit is on.
  enum Part : uint32_t { kFunctionSurface = 0, kContainerSurface = 1 };

  // Throws std::invalid_argument without a field, with max-gradient or accuracy not > 0 and
  // finite, or an empty container.
  explicit Isosurface(Params p);

  const char* kind() const override { return "isosurface"; }
  AABB bounds() const override { return bounds_; }
  bool isSolid() const override { return !p_.open; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;

  // f(p) − threshold, and its gradient by central differences. For tests.
  double value(const Vec3& p) const { return p_.field->value(p) - p_.threshold; }
  Vec3 gradient(const Vec3& p) const;
  const Params& params() const { return p_; }

 private:
  // The line's span inside the container, t over all reals; false when it misses.
  bool containerSpan(const Ray& ray, double& t0, double& t1) const;
  bool inContainer(const Vec3& p) const;
  // Calls emit(t, entering, width) at every sign change of g over [a, b] in order, width
  // bounding the root's error in t; emit returns false to stop.
  template <class Emit>
  void walk(const Ray& ray, double a, double ga, double b, double gb, Emit&& emit) const;

  Params p_;
  AABB bounds_;
  double scale_ = 1.0;  // the container's largest extent
};

}  // namespace lucent
