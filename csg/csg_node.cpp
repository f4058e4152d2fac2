#include "csg_node.h"

#include <algorithm>
#include <stdexcept>

namespace lucent {

const char* csgOpName(CsgOp op) {
  switch (op) {
    case CsgOp::Union: return "union";
    case CsgOp::Merge: return "merge";
    case CsgOp::Intersection: return "intersection";
    case CsgOp::Difference: return "difference";
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

CsgNode::CsgNode(CsgOp op, std::vector<std::unique_ptr<Shape>> children)
    : op_(op), children_(std::move(children)) {
  if (children_.empty()) throw std::invalid_argument("CSG node without children");
  solid_ = std::all_of(children_.begin(), children_.end(),
                       [](const auto& c) { return c->isSolid(); });
  switch (op_) {
    case CsgOp::Union:
    case CsgOp::Merge:
      for (const auto& c : children_) bounds_.expand(c->bounds());
      break;
    case CsgOp::Intersection:
      bounds_ = children_[0]->bounds();
      for (const auto& c : children_) bounds_ = AABB::meet(bounds_, c->bounds());
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

template <class Visit>
void CsgNode::forEachCandidate(const Ray& ray, Visit&& visit) const {
  for (uint32_t i : unbounded_) visit(i);
  bvh_.all(ray, [&](uint32_t slot) { visit(slotChild_[slot]); });
}

bool CsgNode::closestChildHit(const Ray& ray, Hit& hit) const {
  Ray r = ray;
  bool found = false;
  for (uint32_t i : unbounded_) {
    if (children_[i]->intersect(r, hit)) {
      r.tmax = hit.t;
      found = true;
    }
  }
  bool inTree = bvh_.closest(r, [&](uint32_t slot, Ray& rr) {
    if (!children_[slotChild_[slot]]->intersect(rr, hit)) return false;
    rr.tmax = hit.t;
    return true;
  });
  return found || inTree;
}

void CsgNode::crossings(const Ray& ray, CrossingList& out) const {
  // Gather every child's crossings, tagged with the child they belong to, in t order.
  struct Tagged { Crossing c; size_t child; };
  std::vector<Tagged> all;
  std::vector<char> in(children_.size(), 0);
  CrossingList list;
  // Children whose box the ray misses add no crossings and start outside.
  forEachCandidate(ray, [&](uint32_t i) {
    list.clear();
    children_[i]->crossings(ray, list);
    in[i] = list.startsInside;
    for (const Crossing& c : list.items) all.push_back({c, i});
  });
  // By distance, then by child, so coincident crossings are grouped the same way whatever
  // order the BVH visited the children in.
  std::stable_sort(all.begin(), all.end(), [](const Tagged& a, const Tagged& b) {
    return a.c.hit.t < b.c.hit.t || (a.c.hit.t == b.c.hit.t && a.child < b.child);
  });

  bool state = combine(op_, in);
  out.startsInside = state;
  // Crossings at the same t are applied together (coincident surfaces), so a change of
  // membership is reported once; the first child's surface of the group bounds the result.
  for (size_t i = 0; i < all.size();) {
    size_t j = i;
    for (; j < all.size() && all[j].c.hit.t == all[i].c.hit.t; ++j)
      in[all[j].child] = all[j].c.entering;
    bool next = combine(op_, in);
    if (next != state) {
      Crossing c = all[i].c;
      c.entering = next;
      if (op_ == CsgOp::Difference && all[i].child > 0) c.hit.flip = !c.hit.flip;
      out.items.push_back(c);
      state = next;
    }
    i = j;
  }
}

bool CsgNode::intersect(const Ray& ray, Hit& hit) const {
  // A union keeps the surfaces inside other children (as POV-Ray's union does).
  if (op_ == CsgOp::Union || !solid_) return closestChildHit(ray, hit);
  CrossingList list;
  crossings(ray, list);
  for (const Crossing& c : list.items) {
    if (c.hit.t > ray.tmin && c.hit.t < ray.tmax) {
      hit = c.hit;
      return true;
    }
  }
  return false;
}

bool CsgNode::occluded(const Ray& ray) const {
  if (op_ == CsgOp::Union || !solid_) {
    for (uint32_t i : unbounded_)
      if (children_[i]->occluded(ray)) return true;
    return bvh_.any(ray, [&](uint32_t slot, const Ray& r) {
      return children_[slotChild_[slot]]->occluded(r);
    });
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
