#include "span.h"

#include <algorithm>

namespace lucent {

namespace {
Hit makeHit(const Shape* shape, double t, uint32_t part, double b1, double b2) {
  Hit h;
  h.t = t;
  h.shape = shape;
  h.part = part;
  h.b1 = b1;
  h.b2 = b2;
  return h;
}
}  // namespace

bool intersectSpan(const Span& s, const Ray& ray, const Shape* shape, Hit& hit) {
  if (ray.tmin < s.tIn && s.tIn < ray.tmax) {
    hit = makeHit(shape, s.tIn, s.partIn, s.b1In, s.b2In);
    return true;
  }
  if (ray.tmin < s.tOut && s.tOut < ray.tmax) {
    hit = makeHit(shape, s.tOut, s.partOut, s.b1Out, s.b2Out);
    return true;
  }
  return false;
}

void crossingsOfSpan(const Span& s, const Ray& ray, const Shape* shape, CrossingList& out) {
  out.startsInside = s.tIn < ray.tmin && ray.tmin <= s.tOut;
  if (!(s.tIn <= s.tOut)) return;
  if (ray.tmin <= s.tIn && s.tIn <= ray.tmax)
    out.items.push_back({makeHit(shape, s.tIn, s.partIn, s.b1In, s.b2In), true});
  if (ray.tmin <= s.tOut && s.tOut <= ray.tmax)
    out.items.push_back({makeHit(shape, s.tOut, s.partOut, s.b1Out, s.b2Out), false});
}

bool intersectRoots(const SurfaceRoot* roots, int n, const Ray& ray, const Shape* shape, Hit& hit) {
  int best = -1;
  for (int i = 0; i < n; ++i)
    if (ray.tmin < roots[i].t && roots[i].t < ray.tmax && (best < 0 || roots[i].t < roots[best].t))
      best = i;
  if (best < 0) return false;
  hit = makeHit(shape, roots[best].t, roots[best].part, roots[best].b1, roots[best].b2);
  return true;
}

void crossingsOfRoots(const SurfaceRoot* roots, int n, const Ray& ray, const Shape* shape,
                      CrossingList& out) {
  out.startsInside = false;
  size_t first = out.items.size();
  for (int i = 0; i < n; ++i)
    if (ray.tmin <= roots[i].t && roots[i].t <= ray.tmax)
      out.items.push_back(
          {makeHit(shape, roots[i].t, roots[i].part, roots[i].b1, roots[i].b2), true});
  std::sort(out.items.begin() + static_cast<std::ptrdiff_t>(first), out.items.end(),
            [](const Crossing& a, const Crossing& b) { return a.hit.t < b.hit.t; });
}

void crossingsOfLine(const double* t, const bool* entering, int n, bool insideBefore,
                     const Ray& ray, const Shape* shape, CrossingList& out) {
  bool inside = insideBefore;
  for (int i = 0; i < n; ++i)
    if (t[i] < ray.tmin) inside = entering[i];
  out.startsInside = inside;
  for (int i = 0; i < n; ++i)
    if (ray.tmin <= t[i] && t[i] <= ray.tmax)
      out.items.push_back({makeHit(shape, t[i], 0, 0.0, 0.0), entering[i]});
}

}  // namespace lucent
