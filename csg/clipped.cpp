#include "clipped.h"

#include "coincidence.h"
#include "csg_scratch.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucent {

Clipped::Clipped(std::unique_ptr<Shape> shape, std::vector<std::unique_ptr<Shape>> clips,
                 const AABB& within)
    : shape_(std::move(shape)), clips_(std::move(clips)) {
  if (!shape_) throw std::invalid_argument("clipped_by without a shape");
  bounds_ = AABB::meet(shape_->bounds(), within);
  for (const auto& c : clips_) {
    if (!c || !c->isSolid()) throw std::invalid_argument("a clip must be a solid");
    // The kept surface lies inside every clip (POV-Ray takes the smaller box the same way).
    bounds_ = AABB::meet(bounds_, c->bounds());
  }
}

bool Clipped::inClips(const Vec3& p) const {
  return std::all_of(clips_.begin(), clips_.end(), [&](const auto& c) { return c->inside(p); });
}

bool Clipped::firstKept(const Ray& ray, Hit& hit) const {
  // The shape's hits one after another, from the nearest, until one lies inside the clips
  // (POV-Ray tests each intersection point of a clipped object the same way). A kept hit
  // lies in the clips' box, so the search is held to the ray's stretch through it, widened
  // by a margin against rounding: an unbounded shape (a quartic) then solves for its roots
  // in that stretch instead of along the whole line.
  Ray r = ray;
  if (bounds_.isBounded()) {
    const Interval in = bounds_.slab(ray, Vec3(1.0) / ray.d);
    if (in.empty()) return false;
    const double margin = 1e-9 * (std::abs(in.lo) + std::abs(in.hi)) + 1e-300;
    r.tmin = std::max(ray.tmin, in.lo - margin);
    r.tmax = std::min(ray.tmax, in.hi + margin);
  }
  Hit h;
  while (shape_->intersect(r, h)) {
    if (inClips(ray.at(h.t))) {
      hit = h;
      return true;
    }
    r.tmin = h.t;
    h = Hit();
  }
  return false;
}

bool Clipped::intersect(const Ray& ray, Hit& hit) const { return firstKept(ray, hit); }

bool Clipped::occluded(const Ray& ray) const {
  Hit h;
  return firstKept(ray, h);
}

void Clipped::crossings(const Ray& ray, CrossingList& out) const {
  const CsgScratchLease scratch;
  CrossingList& list = scratch->list;
  shape_->crossings(ray, list);
  if (!shape_->isSolid()) {
    // A surface has no inside: its crossings inside the clips are what remains.
    for (const Crossing& c : list.items)
      if (inClips(ray.at(c.hit.t))) out.items.push_back(c);
    out.startsInside = false;
    return;
  }
  // A solid: the shape's crossings and the clips' (hidden) merged as an intersection, so
  // that membership is the shape's cut by the clips while only the shape's surface shows.
  using Tagged = CsgScratch::Tagged;
  std::vector<Tagged>& all = scratch->all;
  std::vector<char>& in = scratch->in;
  in.assign(clips_.size() + 1, 0);
  in[0] = list.startsInside;
  for (const Crossing& c : list.items) all.push_back({c, 0});
  for (size_t i = 0; i < clips_.size(); ++i) {
    list.clear();
    clips_[i]->crossings(ray, list);
    in[i + 1] = list.startsInside;
    for (Crossing c : list.items) {
      c.hidden = true;
      all.push_back({c, i + 1});
    }
  }
  std::sort(all.begin(), all.end(), [](const Tagged& a, const Tagged& b) {
    return a.c.hit.t < b.c.hit.t || (a.c.hit.t == b.c.hit.t && a.child < b.child);
  });
  auto allIn = [&] { return std::all_of(in.begin(), in.end(), [](char c) { return c != 0; }); };
  bool state = allIn();
  out.startsInside = state;
  // Crossings within the coincidence window are one event (a clip flush with a face of
  // the shape); where membership changes, the shape's own crossing bounds the result when
  // it agrees, so a face the clip leaves in place still shows.
  for (size_t i = 0; i < all.size();) {
    const double limit = all[i].c.hit.t + coincidenceWindow(ray, all[i].c.hit.t);
    size_t j = i;
    for (; j < all.size() && all[j].c.hit.t <= limit; ++j) in[all[j].child] = all[j].c.entering;
    const bool next = allIn();
    if (next != state) {
      const Tagged* bound = &all[i];
      for (size_t k = i; k < j; ++k)
        if (all[k].c.entering == next && (bound->c.entering != next || all[k].child < bound->child))
          bound = &all[k];
      Crossing c = bound->c;
      c.entering = next;
      out.items.push_back(c);
      state = next;
    }
    i = j;
  }
}

}  // namespace lucent
