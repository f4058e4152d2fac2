#include "text.h"

#include <algorithm>
#include <stdexcept>

namespace lucent {

namespace {

// Text space (x, y, z) and prism space (x, extrusion, outline's second axis) differ by
// swapping y and z, its own inverse.
Vec3 swapYZ(const Vec3& v) { return {v.x, v.z, v.y}; }
Ray toPrism(const Ray& r) { return Ray(swapYZ(r.o), swapYZ(r.d), r.tmin, r.tmax); }

}  // namespace

Text::Text(const std::vector<std::vector<PrismContour>>& glyphs, double thickness,
           const std::vector<Vec2>& blanks) {
  if (!(thickness > 0.0) || !std::isfinite(thickness))
    throw std::invalid_argument("text: thickness must be > 0");
  for (const auto& g : glyphs) {
    if (g.empty()) continue;
    glyphs_.push_back(std::make_unique<Prism>(g, 0.0, thickness));
    boxes_.push_back(glyphs_.back()->bounds());
    const AABB& b = boxes_.back();
    bounds_.expand(AABB(swapYZ(b.lo), swapYZ(b.hi)));
  }
  if (!boxes_.empty()) bvh_ = Bvh(boxes_);
  for (const Vec2& o : blanks) bounds_.expand(AABB(Vec3(o.x, o.y, 0.0), Vec3(o.x, o.y, thickness)));
}

size_t Text::segmentCount() const {
  size_t n = 0;
  for (const auto& g : glyphs_) n += g->segmentCount();
  return n;
}

// The glyph index rides in Hit::b2, which Prism leaves unused.
bool Text::intersect(const Ray& ray, Hit& hit) const {
  if (glyphs_.empty()) return false;
  Hit best;
  const bool found = bvh_.closest(toPrism(ray), [&](uint32_t i, Ray& r) {
    Hit h;
    if (!glyphs_[i]->intersect(r, h)) return false;
    best = h;
    best.b2 = i;
    r.tmax = h.t;
    return true;
  });
  if (!found) return false;
  hit = best;
  hit.shape = this;
  return true;
}

bool Text::occluded(const Ray& ray) const {
  if (glyphs_.empty()) return false;
  return bvh_.any(toPrism(ray), [&](uint32_t i, const Ray& r) { return glyphs_[i]->occluded(r); });
}

void Text::crossings(const Ray& ray, CrossingList& out) const {
  if (glyphs_.empty()) return;
  const Ray r = toPrism(ray);
  std::vector<Crossing> all;
  int depth = 0;
  CrossingList one;
  bvh_.all(r, [&](uint32_t i) {
    one.clear();
    glyphs_[i]->crossings(r, one);
    if (one.startsInside) ++depth;
    for (Crossing c : one.items) {
      c.hit.b2 = i;
      c.hit.shape = this;
      all.push_back(c);
    }
  });
  out.startsInside = depth > 0;
  std::stable_sort(all.begin(), all.end(),
                   [](const Crossing& a, const Crossing& b) { return a.hit.t < b.hit.t; });
  // A union of the glyphs: a crossing counts only where the count of glyphs the ray is
  // inside goes between 0 and 1 (disjoint glyphs keep every crossing).
  for (const Crossing& c : all) {
    const int before = depth;
    depth += c.entering ? 1 : -1;
    if ((before == 0) != (depth == 0)) out.items.push_back(c);
  }
}

bool Text::inside(const Vec3& p) const {
  const Vec3 q = swapYZ(p);
  for (size_t i = 0; i < glyphs_.size(); ++i)
    if (boxes_[i].contains(q) && glyphs_[i]->inside(q)) return true;
  return false;
}

SurfaceInfo Text::surface(const Ray& ray, const Hit& hit) const {
  Hit local = hit;
  const auto i = static_cast<size_t>(hit.b2);
  local.shape = glyphs_[i].get();
  SurfaceInfo s = glyphs_[i]->surface(toPrism(ray), local);
  s.p = swapYZ(s.p);
  s.pError = swapYZ(s.pError);
  s.ng = swapYZ(s.ng);
  s.ns = swapYZ(s.ns);
  return s;
}

}  // namespace lucent
