#include "box.h"
#include "pov_uv.h"

#include <stdexcept>
#include <utility>

namespace lucent {

Box::Box(const Vec3& a, const Vec3& b) : lo_(glm::min(a, b)), hi_(glm::max(a, b)) {
  if (!isFinite(a) || !isFinite(b)) throw std::invalid_argument("box: corners must be finite");
}

bool Box::span(const Ray& ray, Span& out) const {
  // Kay–Kajiya slabs over the whole line. Division (not multiplication by a reciprocal)
  // keeps each plane distance correctly rounded; an axis the ray runs parallel to either
  // excludes the line or does not constrain it (closed box: a ray in a face plane is in).
  out = Span();
  out.tIn = -kInf;
  out.tOut = kInf;
  for (int a = 0; a < 3; ++a) {
    if (ray.d[a] == 0.0) {
      if (ray.o[a] < lo_[a] || ray.o[a] > hi_[a]) return false;
      continue;
    }
    double tLo = (lo_[a] - ray.o[a]) / ray.d[a];
    double tHi = (hi_[a] - ray.o[a]) / ray.d[a];
    uint32_t fNear = 2 * a, fFar = 2 * a + 1;
    if (tLo > tHi) {
      std::swap(tLo, tHi);
      std::swap(fNear, fFar);
    }
    if (tLo > out.tIn) {
      out.tIn = tLo;
      out.partIn = fNear;
    }
    if (tHi < out.tOut) {
      out.tOut = tHi;
      out.partOut = fFar;
    }
  }
  return out.tIn <= out.tOut;
}

bool Box::intersect(const Ray& ray, Hit& hit) const {
  Span s;
  return span(ray, s) && intersectSpan(s, ray, this, hit);
}

void Box::crossings(const Ray& ray, CrossingList& out) const {
  Span s;
  if (!span(ray, s)) s = Span();
  crossingsOfSpan(s, ray, this, out);
}

bool Box::inside(const Vec3& p) const {
  if (closedFaces_)
    return lo_.x <= p.x && p.x <= hi_.x && lo_.y <= p.y && p.y <= hi_.y && lo_.z <= p.z &&
           p.z <= hi_.z;
  return lo_.x < p.x && p.x < hi_.x && lo_.y < p.y && p.y < hi_.y && lo_.z < p.z && p.z < hi_.z;
}

SurfaceInfo Box::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo s;
  int axis = static_cast<int>(hit.part / 2);
  bool maxSide = (hit.part & 1) != 0;
  Vec3 p = ray.at(hit.t);
  // Reproject: the face's own coordinate is exact, the others are clamped into the face
  // (the true hit lies in it), which can only shrink their error. Those came from the ray
  // equation with a t of relative error gamma(2): gamma(5)·(|o| + |t·d|) bounds them.
  Vec3 err = gamma(5) * (glm::abs(ray.o) + glm::abs(hit.t * ray.d));
  p = glm::clamp(p, lo_, hi_);
  p[axis] = maxSide ? hi_[axis] : lo_[axis];
  err[axis] = 0.0;
  s.p = p;
  s.pError = err;
  s.ng = Vec3(0.0);
  s.ng[axis] = maxSide ? 1.0 : -1.0;
  s.ns = s.ng;

  // Face (u,v): the face seen from outside, u to the right, v up (see box.h).
  Vec3 e = hi_ - lo_;
  auto frac = [&](int i, bool fromMax) {
    if (!(e[i] > 0.0)) return 0.0;
    return fromMax ? (hi_[i] - p[i]) / e[i] : (p[i] - lo_[i]) / e[i];
  };
  switch (axis) {
    case 0:  // ±x: right is ∓z, up is +y
      s.uv = Vec2(frac(2, maxSide), frac(1, false));
      break;
    case 1:  // +y: right +x, up −z; −y: right +x, up +z
      s.uv = Vec2(frac(0, false), frac(2, maxSide));
      break;
    default:  // ±z: right is ±x, up is +y
      s.uv = Vec2(frac(0, !maxSide), frac(1, false));
      break;
  }
  s.hasUV = true;
  return s;
}

// POV-Ray's box: its cube map (boxes.cpp's picture), each face a quarter of u and a third
// of v, from the point's fractions across the box in POV-Ray's space, where z is negated:
// Lucent's min-z face is POV-Ray's max-z face and the z fraction runs from Lucent's max z.
bool Box::povUV(const SurfaceInfo& s, const Hit& hit, Vec2& uv) const {
  const Vec3 e = hi_ - lo_;
  auto frac = [&](double num, double den) { return den > 0.0 ? num / den : 0.0; };
  const double px = frac(s.p.x - lo_.x, e.x), py = frac(s.p.y - lo_.y, e.y);
  const double pz = frac(hi_.z - s.p.z, e.z);
  const int axis = static_cast<int>(hit.part / 2);
  const bool maxSide = (hit.part & 1) != 0;
  if (axis == 0) {
    uv = maxSide ? Vec2(0.75 - pz / 4.0, 1.0 / 3.0 + py / 3.0)
                 : Vec2(pz / 4.0, 1.0 / 3.0 + py / 3.0);
  } else if (axis == 1) {
    uv = maxSide ? Vec2(0.25 + px / 4.0, 1.0 - pz / 3.0) : Vec2(0.25 + px / 4.0, pz / 3.0);
  } else if (maxSide) {  // POV-Ray's min-z face
    uv = Vec2(1.0 - px / 4.0, 1.0 / 3.0 + py / 3.0);
  } else {  // POV-Ray's max-z face
    uv = Vec2(0.25 + px / 4.0, 1.0 / 3.0 + py / 3.0);
  }
  return true;
}

}  // namespace lucent
