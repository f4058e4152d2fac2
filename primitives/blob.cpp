#include "blob.h"

#include "polynomial.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucent {

namespace {

using Piece = Blob::Piece;

bool finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The vectors whose squared length is the piece's r² at o + t·d: w + t·dv.
void radialLine(const Piece& p, const Vec3& w, const Vec3& d, Vec3& wr, Vec3& dr) {
  if (p.kind == Piece::Ball) {
    wr = w;
    dr = d;
  } else {
    wr = w - glm::dot(p.axis, w) * p.axis;
    dr = d - glm::dot(p.axis, d) * p.axis;
  }
}

// Where |w + t·dv|² < r2, from the line's closest approach (no cancellation far away).
Interval radialInterval(const Vec3& w, const Vec3& dv, double r2) {
  double dd = glm::dot(dv, dv);
  if (!(dd > 0.0)) return glm::dot(w, w) < r2 ? Interval::everything() : Interval();
  double tc = -glm::dot(w, dv) / dd;
  Vec3 pc = w + tc * dv;
  double h2 = (r2 - glm::dot(pc, pc)) / dd;
  if (!(h2 > 0.0)) return {};
  double h = std::sqrt(h2);
  return {tc - h, tc + h};
}

// Where z0 + t·zd lies in [zlo, zhi].
Interval slabInterval(double z0, double zd, double zlo, double zhi) {
  if (zd == 0.0) return (zlo <= z0 && z0 <= zhi) ? Interval::everything() : Interval();
  double a = (zlo - z0) / zd, b = (zhi - z0) / zd;
  if (a > b) std::swap(a, b);
  return {a, b};
}

// A point and a direction of the blob's space in the piece's own.
Vec3 localPoint(const Piece& p, const Vec3& pt) {
  return p.local ? p.toLocal * pt + p.localOffset : pt;
}
Vec3 localVector(const Piece& p, const Vec3& v) { return p.local ? p.toLocal * v : v; }

// The interval of the line o + t·d inside the piece's support.
Interval pieceInterval(const Piece& p, const Ray& ray) {
  const Vec3 o = localPoint(p, ray.o), d = localVector(p, ray.d);
  Vec3 w = o - p.c, wr, dr;
  radialLine(p, w, d, wr, dr);
  Interval I = radialInterval(wr, dr, p.r2);
  if (I.empty()) return I;
  if (p.axis == Vec3(0.0)) return I;
  double z0 = glm::dot(p.axis, o - p.base), zd = glm::dot(p.axis, d);
  return I.intersect(slabInterval(z0, zd, p.zlo, p.zhi));
}

// r² of the point w = p − c within the piece, or -1 outside the piece's part of space;
// `radial` in the piece's space.
double pieceRadius2(const Piece& p, const Vec3& blobPoint, Vec3& radial) {
  const Vec3 pt = localPoint(p, blobPoint);
  if (p.axis != Vec3(0.0)) {
    double z = glm::dot(p.axis, pt - p.base);
    if (!(z >= p.zlo && z < p.zhi)) return -1.0;
  }
  Vec3 w = pt - p.c;
  radial = p.kind == Piece::Body ? w - glm::dot(p.axis, w) * p.axis : w;
  return glm::dot(radial, radial);
}

// Gives the pieces [begin, end) of one component the component's transform and returns
// the bounds of its support box carried into the blob's space.
AABB placeComponent(const Mat4& transform, const AABB& box, std::vector<Piece>::iterator begin,
                    std::vector<Piece>::iterator end) {
  const Mat3 linear(transform);
  const double det = glm::determinant(linear);
  double size = 0.0;
  for (int i = 0; i < 3; ++i) size = std::max(size, glm::length(linear[i]));
  bool finiteMatrix = true;
  for (int i = 0; i < 4; ++i) finiteMatrix = finiteMatrix && finite(Vec3(transform[i]));
  if (!finiteMatrix || !(std::abs(det) > 1e-12 * size * size * size))
    throw std::invalid_argument("blob: a component's transform must be finite and invertible");
  const Mat3 toLocal = glm::inverse(linear);
  const Vec3 offset = -(toLocal * Vec3(transform[3]));
  for (auto p = begin; p != end; ++p) {
    p->local = true;
    p->toLocal = toLocal;
    p->localOffset = offset;
  }
  AABB placed;
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner((k & 1) ? box.hi.x : box.lo.x, (k & 2) ? box.hi.y : box.lo.y,
                      (k & 4) ? box.hi.z : box.lo.z);
    const Vec3 q = Vec3(transform * Vec4(corner, 1.0));
    placed = k == 0 ? AABB(q, q) : AABB::join(placed, AABB(q, q));
  }
  return placed;
}

struct Event {
  double t;
  int piece;
  bool enter;
};

}  // namespace

Blob::Blob(double threshold, std::vector<BlobComponent> components) : threshold_(threshold) {
  if (!(threshold > 0.0) || !std::isfinite(threshold))
    throw std::invalid_argument("blob: the threshold must be a positive number");
  if (components.empty()) throw std::invalid_argument("blob: needs at least one component");
  bool any = false;
  for (const BlobComponent& c : components) {
    if (!(c.radius > 0.0) || !std::isfinite(c.radius) || !std::isfinite(c.strength) ||
        !finite(c.a) || !finite(c.b))
      throw std::invalid_argument(
          "blob: a component needs a finite radius > 0, strength and position");
    double r2 = c.radius * c.radius;
    AABB box;
    const size_t first = pieces_.size();
    if (c.kind == BlobComponent::Sphere) {
      pieces_.push_back({Piece::Ball, c.a, c.a, Vec3(0.0), -kInf, kInf, r2, c.strength});
      box = AABB(c.a - Vec3(c.radius), c.a + Vec3(c.radius));
    } else {
      Vec3 axis = c.b - c.a;
      double len = glm::length(axis);
      if (!(len > 0.0)) throw std::invalid_argument("blob: a cylinder's base and cap must differ");
      axis /= len;
      pieces_.push_back({Piece::Body, c.a, c.a, axis, 0.0, len, r2, c.strength});
      pieces_.push_back({Piece::Ball, c.a, c.a, axis, -kInf, 0.0, r2, c.strength});
      pieces_.push_back({Piece::Ball, c.b, c.a, axis, len, kInf, r2, c.strength});
      box = AABB(glm::min(c.a, c.b) - Vec3(c.radius), glm::max(c.a, c.b) + Vec3(c.radius));
    }
    if (c.transform != Mat4(1.0)) {
      box = placeComponent(c.transform, box, pieces_.begin() + static_cast<long>(first),
                           pieces_.end());
    }
    for (size_t i = first; i < pieces_.size(); ++i)
      pieces_[i].component = static_cast<uint32_t>(componentCount_);
    ++componentCount_;
    // Only positive components can lift the field above the threshold.
    if (c.strength > 0.0) {
      bounds_ = any ? AABB::join(bounds_, box) : box;
      any = true;
    }
  }
  if (!any) bounds_ = AABB(components[0].a, components[0].a);  // empty solid: nothing is inside
  scale_ =
      std::max({maxComponent(glm::abs(bounds_.lo)), maxComponent(glm::abs(bounds_.hi)), 1e-300});
}

double Blob::field(const Vec3& p) const {
  double f = 0.0;
  for (const Piece& pc : pieces_) {
    Vec3 radial;
    double q = pieceRadius2(pc, p, radial);
    if (q < 0.0 || q >= pc.r2) continue;
    double g = 1.0 - q / pc.r2;
    f += pc.s * g * g;
  }
  return f;
}

void Blob::componentFields(const Vec3& p, std::vector<double>& out) const {
  out.assign(componentCount_, 0.0);
  for (const Piece& pc : pieces_) {
    Vec3 radial;
    double q = pieceRadius2(pc, p, radial);
    if (q < 0.0 || q >= pc.r2) continue;
    double g = 1.0 - q / pc.r2;
    out[pc.component] += std::abs(pc.s * g * g);
  }
}

Vec3 Blob::gradient(const Vec3& p) const {
  Vec3 grad(0.0);
  for (const Piece& pc : pieces_) {
    Vec3 radial;
    double q = pieceRadius2(pc, p, radial);
    if (q < 0.0 || q >= pc.r2) continue;
    double g = 1.0 - q / pc.r2;
    const Vec3 localGrad = (-4.0 * pc.s * g / pc.r2) * radial;
    grad += pc.local ? glm::transpose(pc.toLocal) * localGrad : localGrad;
  }
  return grad;
}

template <class Emit>
bool Blob::walk(const Ray& ray, double lo, double hi, Emit&& emit) const {
  Interval box = bounds_.slab(Ray(ray.o, ray.d, lo, hi), Vec3(1.0) / ray.d);
  if (box.empty()) return false;
  thread_local std::vector<Event> events;
  thread_local std::vector<int> active;
  events.clear();
  active.clear();
  for (int i = 0; i < static_cast<int>(pieces_.size()); ++i) {
    Interval I = pieceInterval(pieces_[i], ray).intersect(box);
    if (!(I.lo < I.hi)) continue;
    events.push_back({I.lo, i, true});
    events.push_back({I.hi, i, false});
  }
  std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.t < b.t; });

  bool state = false, startsInside = false;
  size_t e = 0;
  while (e < events.size()) {
    double ta = events[e].t;
    for (; e < events.size() && events[e].t == ta; ++e) {
      if (events[e].enter) active.push_back(events[e].piece);
      else active.erase(std::find(active.begin(), active.end(), events[e].piece));
    }
    if (e == events.size()) break;
    double tb = events[e].t;
    bool first = ta == lo;  // the point at lo: its side is this piece's sign, no crossing
    auto sync = [&](bool sign, double t) {
      if (sign == state) return true;
      state = sign;
      if (first) {
        startsInside = sign;
        return true;
      }
      return emit(t, sign);
    };

    // The field on this piece as a quartic in u = t − tm, and a bound on its maximum.
    double tm = 0.5 * (ta + tb), h = 0.5 * (tb - ta);
    double c[5] = {-threshold_, 0.0, 0.0, 0.0, 0.0}, cAbs[5] = {threshold_, 0.0, 0.0, 0.0, 0.0};
    double maxField = 0.0;
    Vec3 om = ray.o + tm * ray.d;
    for (int i : active) {
      const Piece& pc = pieces_[i];
      Vec3 wr, dr;
      radialLine(pc, localPoint(pc, om) - pc.c, localVector(pc, ray.d), wr, dr);
      double ww = glm::dot(wr, wr) / pc.r2;
      double al = 1.0 - ww, be = -2.0 * glm::dot(wr, dr) / pc.r2, ga = -glm::dot(dr, dr) / pc.r2;
      double s = pc.s, as = std::abs(s), A = 1.0 + ww;
      c[0] += s * al * al;
      c[1] += s * 2.0 * al * be;
      c[2] += s * (be * be + 2.0 * al * ga);
      c[3] += s * 2.0 * be * ga;
      c[4] += s * ga * ga;
      cAbs[0] += as * A * A;
      cAbs[1] += 2.0 * as * A * std::abs(be);
      cAbs[2] += as * (be * be + 2.0 * A * std::abs(ga));
      cAbs[3] += 2.0 * as * std::abs(be * ga);
      cAbs[4] += as * ga * ga;
      if (s > 0.0) {
        // g = al + be·u + ga·u² is concave (ga <= 0): its maximum on [-h, h].
        double u = ga < 0.0 ? std::clamp(-be / (2.0 * ga), -h, h) : (be >= 0.0 ? h : -h);
        double g = std::min(1.0, al + u * (be + u * ga) + 4.0 * kMachineEps * A);
        maxField += s * g * g;
      }
    }
    if (maxField < threshold_ * (1.0 - 8.0 * kMachineEps)) {
      if (!sync(false, ta)) return startsInside;
      continue;
    }
    int n = 4;
    while (n > 0 && std::abs(c[n]) <= gamma(16) * cAbs[n]) --n;
    if (!sync(evalPolynomial(c, n, -h) > 0.0, ta)) return startsInside;
    if (n == 0) continue;
    PolynomialRoot roots[4];
    int count = polynomialRoots(c, cAbs, n, -h, h, roots);
    for (int k = 0; k < count; ++k) {
      if (roots[k].touching) continue;  // a tangent: the solid is touched, not entered
      state = !state;
      if (!emit(tm + roots[k].x, state)) return startsInside;
    }
    first = false;
    if (!sync(evalPolynomial(c, n, h) > 0.0, tb)) return startsInside;
  }
  return startsInside;
}

bool Blob::intersect(const Ray& ray, Hit& hit) const {
  bool found = false;
  walk(ray, ray.tmin, ray.tmax, [&](double t, bool) {
    if (!(ray.tmin < t && t < ray.tmax)) return true;
    hit.t = t;
    hit.shape = this;
    hit.part = 0;
    found = true;
    return false;
  });
  return found;
}

void Blob::crossings(const Ray& ray, CrossingList& out) const {
  out.startsInside = walk(ray, ray.tmin, ray.tmax, [&](double t, bool entering) {
    Crossing c;
    c.hit.t = t;
    c.hit.shape = this;
    c.entering = entering;
    out.items.push_back(c);
    return true;
  });
}

SurfaceInfo Blob::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo s;
  s.p = ray.at(hit.t);
  Vec3 g = gradient(s.p);
  double gl = glm::length(g);
  // The point's rounding, plus its distance from the surface: the field's error over the
  // gradient's length (capped where the gradient vanishes, at a saddle where fields merge).
  double fieldError = gamma(64) * threshold_;
  for (const Piece& pc : pieces_) fieldError += gamma(64) * std::abs(pc.s);
  double off = gl > 0.0 ? std::min(fieldError / gl, 1e-6 * scale_) : 1e-6 * scale_;
  s.pError = gamma(32) * (glm::abs(ray.o) + glm::abs(hit.t * ray.d) + Vec3(scale_)) + Vec3(off);
  s.ng = gl > 0.0 ? -g / gl : -glm::normalize(ray.d);
  s.ns = s.ng;
  return s;
}

}  // namespace lucent
