// <parametric>: POV-Ray 3.7's parametric surface, the points S(u, v) = (x(u, v), y(u, v),
// z(u, v)) for (u, v) in a rectangle, sought within a container (a box or a sphere). Not a
// solid (POV-Ray's has no inside either).
//
// Method (POV-Ray's, fpmetric.cpp, taken as facts): the (u, v) rectangle is halved along
// its longer side, nearer half first. For each part, each coordinate function gets an
// interval from its values at the four corners and the declared max_gradient G (along an
// edge of length l between values a and b no value lies beyond max(a, b) + (G·l − |a − b|)/2,
// first along the two v edges, then across u between their bounds). The three intervals make
// a box; a part whose box the ray misses within the container, or meets no nearer than the
// best hit so far, holds no nearer hit and is dropped. A part whose (u, v) sides or whose
// box's extent along the ray are below `accuracy` is a leaf: the ray's entry into its box is
// the hit. `precompute` keeps the intervals of the first levels of parts, computed once
// (each level's as the union of its two halves', so tighter than from its own corners).
//
// Lucent's additions: each part keeps its corners' values, so a halving evaluates the
// functions at its two new corners only; the leaf's hit is then refined by Newton's method
// on S(u, v) = o + t·d (finite-difference derivatives) to the exact surface point and its
// (u, v), kept when it converges within the leaf's neighbourhood (otherwise POV-Ray's entry
// point stands); the normal is S_u × S_v at that (u, v) by central differences. POV-Ray
// subtracts `accuracy` from every interval (it passes it as a threshold), which moves its
// surface by −accuracy on each axis; Lucent's intervals bound the functions themselves.
// Like POV-Ray, hits within 4·accuracy of where the ray enters the container (or starts
// inside it) are ignored: the search would otherwise find the surface a ray leaves from.
#pragma once

#include "isosurface.h"
#include "scalar_field.h"
#include "shape.h"

#include <array>
#include <memory>
#include <vector>

namespace lucent {

// The intervals of the first levels of parts (POV-Ray's precompute), per coordinate, indexed
// by part: 1 the whole rectangle, part k's halves 2k and 2k + 1; empty for a coordinate not
// precomputed. Shared by every copy of a shape (POV-Ray shares its table too).
struct ParametricIntervals {
  size_t parts = 0;  // parts below this index are held
  std::array<std::vector<double>, 3> low, high;
};

class Parametric final : public Shape {
 public:
  struct Params {
    // x(u, v), y(u, v), z(u, v), each a field evaluated at (u, v, 0). Required.
    std::array<std::shared_ptr<const ScalarField>, 3> functions;
    Vec2 uvMin{0.0}, uvMax{1.0};  // the rectangle, uvMin < uvMax in both
    IsosurfaceContainer container;
    double maxGradient = 1.0;
    double accuracy = 0.001;
    // Levels of parts whose intervals are computed once (0: none, at most kMaxPrecompute),
    // for the coordinates marked (x, y, z).
    int precomputeDepth = 0;
    std::array<bool, 3> precompute{false, false, false};
    // The precomputed table, when made before (precomputeParametric); null: made here.
    std::shared_ptr<const ParametricIntervals> intervals;
  };
  static constexpr int kMaxPrecompute = 20;  // POV-Ray's limit
  // Parts visited per search at most (a max_gradient far above the functions' slopes
  // leaves every part undecided down to `accuracy`); past it the search keeps the best
  // hit it found.
  static constexpr long kMaxPartsPerSearch = 1L << 20;

  // Throws std::invalid_argument for a missing function, an empty rectangle, accuracy or
  // max-gradient not > 0 and finite, an empty container or a precompute depth out of range.
  explicit Parametric(Params p);

  const char* kind() const override { return "parametric"; }
  AABB bounds() const override { return bounds_; }
  bool isSolid() const override { return false; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3&) const override { return false; }
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;
  // POV-Ray's (u, v) of a parametric: the surface's own parameters at the hit.
  bool povUV(const SurfaceInfo& s, const Hit& hit, Vec2& uv) const override;

  // The surface point at (u, v), and the unnormalised normal S_u × S_v there.
  Vec3 point(double u, double v) const;
  Vec3 normal(double u, double v) const;
  const Params& params() const { return p_; }

 private:
  struct Part;
  struct Leaf {
    double t = kInf;        // where the ray enters the leaf's box
    double u0, u1, v0, v1;  // its (u, v) rectangle
  };
  // The nearest leaf hit in (lower, upper); false when there is none.
  bool search(const Ray& ray, double lower, double upper, Leaf& best) const;
  // The leaf's hit refined (t, u, v); false when Newton's method does not settle near it.
  bool refine(const Ray& ray, const Leaf& leaf, double lower, double upper, double& t, double& u,
              double& v) const;
  // The first hit in (lower, upper) as a Hit; false when there is none.
  bool firstHit(const Ray& ray, double lower, double upper, Hit& hit) const;
  // The span of lengths along the ray inside the container, t over all reals.
  bool containerSpan(const Ray& ray, double& t0, double& t1) const;
  Params p_;
  AABB bounds_;
  double scale_ = 1.0;   // the container's largest extent
  Vec2 h_{1e-6};         // finite-difference steps in u and v
  size_t preParts_ = 0;  // parts below this index are in p_.intervals
};

// The table of `p`'s precompute depth and coordinates, or null when it asks for none.
// Throws std::invalid_argument as Parametric's constructor does for a missing function or
// an empty rectangle.
std::shared_ptr<const ParametricIntervals> precomputeParametric(const Parametric::Params& p);

// The interval of a function over a (u, v) rectangle from its corner values f[i][j] (i: u0
// or u1, j: v0 or v1) and a gradient bound g: POV-Ray's bound, exact for functions whose
// slope along u and along v is at most g.
void parametricInterval(const double f[2][2], double du, double dv, double g, double& low,
                        double& high);

}  // namespace lucent
