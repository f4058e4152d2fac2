#include "csg_node.h"

#include "coincidence.h"
#include "csg_scratch.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace lucent {

const char* csgOpName(CsgOp op) {
  switch (op) {
    case CsgOp::Union:
      return "union";
    case CsgOp::Merge:
      return "merge";
    case CsgOp::Intersection:
      return "intersection";
    case CsgOp::Difference:
      return "difference";
  }
  return "?";
}

namespace {

// Membership of the combination, given each child's membership.
bool combine(CsgOp op, const std::vector<char>& in) {
  switch (op) {
    case CsgOp::Union:
    case CsgOp::Merge:
      return std::any_of(in.begin(), in.end(), [](char c) { return c != 0; });
    case CsgOp::Intersection:
      return std::all_of(in.begin(), in.end(), [](char c) { return c != 0; });
    case CsgOp::Difference:
      return in[0] && std::none_of(in.begin() + 1, in.end(), [](char c) { return c != 0; });
  }
  return false;
}

}  // namespace

CsgNode::CsgNode(CsgOp op, std::vector<std::unique_ptr<Shape>> children, CsgSearch search)
    : op_(op), children_(std::move(children)), search_(search) {
  if (children_.empty()) throw std::invalid_argument("CSG node without children");
  solid_ =
      std::all_of(children_.begin(), children_.end(), [](const auto& c) { return c->isSolid(); });
  switch (op_) {
    case CsgOp::Union:
    case CsgOp::Merge:
      for (const auto& c : children_) bounds_.expand(c->bounds());
      break;
    case CsgOp::Intersection:
      bounds_ = boundsWithin(AABB::everything());
      break;
    case CsgOp::Difference:
      bounds_ = children_[0]->bounds();
      break;
  }

  std::vector<uint32_t> bounded;
  for (uint32_t i = 0; i < children_.size(); ++i) {
    AABB box = children_[i]->bounds();
    (box.isBounded() || box.empty() ? bounded : unbounded_).push_back(i);
  }
  bvh_ = Bvh(bounded.size(), [&](uint32_t k) { return children_[bounded[k]]->bounds(); });
  // The traversal reports positions in `bounded`; map them to child indices once.
  for (uint32_t k : bvh_.takeOrder()) slotChild_.push_back(bounded[k]);
}

AABB CsgNode::boundsWithin(const AABB& clip) const {
  switch (op_) {
    case CsgOp::Union:
    case CsgOp::Merge: {
      AABB box;
      for (const auto& c : children_) box.expand(c->boundsWithin(clip));
      return box;
    }
    case CsgOp::Intersection: {
      AABB box = clip;
      for (const auto& c : children_) box = AABB::meet(box, c->bounds());
      // A child unbounded alone (a cone, a hyperboloid) may be bounded within the box the
      // others leave (a slab of planes); once more, as a bound found may tighten another.
      for (int pass = 0; pass < 2 && !box.empty(); ++pass)
        for (const auto& c : children_) box = c->boundsWithin(box);
      return box;
    }
    case CsgOp::Difference:
      return children_[0]->boundsWithin(clip);
  }
  return AABB::meet(bounds(), clip);
}

template <class Visit>
void CsgNode::forEachCandidate(const Ray& ray, Visit&& visit) const {
  if (search_ == CsgSearch::EveryChild) {
    for (uint32_t i = 0; i < children_.size(); ++i) visit(i);
    return;
  }
  for (uint32_t i : unbounded_) visit(i);
  bvh_.all(ray, [&](uint32_t slot) { visit(slotChild_[slot]); });
}

namespace {

// Does a child's crossing agree with a change of the node's membership to `next`? A
// subtracted child bounds the result where it is crossed the other way; every other
// child where it is crossed the same way. Among coincident crossings only an agreeing
// one may bound the result, so the reported normal always faces out of the result.
bool agrees(CsgOp op, size_t child, bool entering, bool next) {
  bool subtracted = op == CsgOp::Difference && child > 0;
  return (entering != subtracted) == next;
}

}  // namespace

bool CsgNode::closestChildHit(const Ray& ray, Hit& hit) const {
  // The closest hit, except that hits within the coincidence window of the closest are
  // ties and the child written first wins them (docs/csg.md): the nearest hit alone would
  // let rounding pick the child pixel by pixel. Near ties are gathered by searching up to
  // the closest t plus its window. The hits kept are those within the window of the
  // closest so far, in a fixed buffer (no allocation per ray): a closer hit drops those
  // now outside its window, and when more than fit tie, the highest-numbered child gives
  // way, as it can never win.
  struct Candidate {
    Hit hit;
    uint32_t child;
  };
  std::array<Candidate, 8> near;
  size_t count = 0;
  double tMin = kInf;
  auto consider = [&](uint32_t i, Ray& r) {
    Hit h;
    if (!children_[i]->intersect(r, h)) return false;
    if (h.t < tMin) {
      tMin = h.t;
      const double limit = tMin + coincidenceWindow(r, tMin);
      size_t kept = 0;
      for (size_t k = 0; k < count; ++k)
        if (near[k].hit.t <= limit) near[kept++] = near[k];
      count = kept;
    }
    if (count < near.size()) {
      near[count++] = {h, i};
    } else {
      auto last = std::max_element(
          near.begin(), near.end(),
          [](const Candidate& a, const Candidate& b) { return a.child < b.child; });
      if (last->child > i) *last = {h, i};
    }
    r.tmax = std::min(r.tmax, tMin + coincidenceWindow(r, tMin));
    return true;
  };
  Ray r = ray;
  if (search_ == CsgSearch::EveryChild) {
    for (uint32_t i = 0; i < children_.size(); ++i) consider(i, r);
  } else {
    for (uint32_t i : unbounded_) consider(i, r);
    bvh_.closest(r, [&](uint32_t slot, Ray& rr) { return consider(slotChild_[slot], rr); });
  }
  const Candidate* best = nullptr;
  for (size_t k = 0; k < count; ++k)
    if (!best || near[k].child < best->child) best = &near[k];
  if (!best) return false;
  hit = best->hit;
  return true;
}

void CsgNode::crossings(const Ray& ray, CrossingList& out) const {
  // The result lies within the node's box: a ray that misses it has no crossings and is
  // outside, and no child is asked (an unbounded one, a plane or a poly cut to size by a
  // box, would otherwise be solved for every ray that reaches the node). Bounded children
  // are culled by the children's BVH already, so only a node with an unbounded child
  // pays for the test (it cost a glass lens of two spheres 5 % of its render).
  if (!unbounded_.empty() && bounds_.isBounded() && !bounds_.hit(ray, Vec3(1.0) / ray.d)) {
    out.startsInside = false;
    return;
  }
  // Gather every child's crossings, tagged with the child they belong to, in t order.
  using Tagged = CsgScratch::Tagged;
  const CsgScratchLease scratch;
  std::vector<Tagged>& all = scratch->all;
  std::vector<char>& in = scratch->in;
  in.assign(children_.size(), 0);
  CrossingList& list = scratch->list;
  // Children whose box the ray misses add no crossings and start outside.
  forEachCandidate(ray, [&](uint32_t i) {
    list.clear();
    children_[i]->crossings(ray, list);
    in[i] = list.startsInside;
    for (const Crossing& c : list.items) all.push_back({c, i});
  });
  // By distance, then by child, so the result never depends on the order in which the
  // BVH visited the children.
  std::sort(all.begin(), all.end(), [](const Tagged& a, const Tagged& b) {
    return a.c.hit.t < b.c.hit.t || (a.c.hit.t == b.c.hit.t && a.child < b.child);
  });

  bool state = combine(op_, in);
  out.startsInside = state;
  // Crossings within the coincidence window of a group's first one are coincident
  // surfaces: they are applied together and the membership is evaluated once, so a
  // surface flush with another (a subtrahend flush with the minuend's face, two equal
  // spheres) changes the result at most once. Where it changes, the agreeing crossing of
  // the child written first bounds the result (docs/csg.md).
  for (size_t i = 0; i < all.size();) {
    const double limit = all[i].c.hit.t + coincidenceWindow(ray, all[i].c.hit.t);
    size_t j = i;
    for (; j < all.size() && all[j].c.hit.t <= limit; ++j) in[all[j].child] = all[j].c.entering;
    bool next = combine(op_, in);
    if (next != state) {
      const Tagged* bound = nullptr;
      for (size_t k = i; k < j; ++k)
        if (agrees(op_, all[k].child, all[k].c.entering, next) &&
            (!bound || all[k].child < bound->child))
          bound = &all[k];
      if (!bound) bound = &all[i];  // unreachable for exact sets; keep the first one
      Crossing c = bound->c;
      c.entering = next;
      if (op_ == CsgOp::Difference && bound->child > 0) c.hit.flip = !c.hit.flip;
      out.items.push_back(c);
      state = next;
    }
    i = j;
  }
}

bool CsgNode::intersect(const Ray& ray, Hit& hit) const {
  // A union keeps the surfaces inside other children (as POV-Ray's union does).
  if (op_ == CsgOp::Union || !solid_) return closestChildHit(ray, hit);
  const CsgScratchLease scratch;
  CrossingList& list = scratch->result;
  crossings(ray, list);
  for (const Crossing& c : list.items) {
    if (!c.hidden && c.hit.t > ray.tmin && c.hit.t < ray.tmax) {
      hit = c.hit;
      return true;
    }
  }
  return false;
}

bool CsgNode::occluded(const Ray& ray) const {
  if (op_ == CsgOp::Union || !solid_) {
    if (search_ == CsgSearch::EveryChild)
      return std::any_of(children_.begin(), children_.end(),
                         [&](const auto& c) { return c->occluded(ray); });
    for (uint32_t i : unbounded_)
      if (children_[i]->occluded(ray)) return true;
    return bvh_.any(
        ray, [&](uint32_t slot, const Ray& r) { return children_[slotChild_[slot]]->occluded(r); });
  }
  Hit h;
  return intersect(ray, h);
}

bool CsgNode::inside(const Vec3& p) const {
  std::vector<char> in(children_.size());
  for (size_t i = 0; i < children_.size(); ++i) in[i] = children_[i]->inside(p);
  return combine(op_, in);
}

SurfaceInfo CsgNode::surface(const Ray& ray, const Hit& hit) const {
  // Hits carry their leaf; asking the CSG node is a programming error upstream.
  return hit.shape->surface(ray, hit);
}

size_t CsgNode::triangleCount() const {
  size_t n = 0;
  for (const auto& c : children_) n += c->triangleCount();
  return n;
}

}  // namespace lucent
