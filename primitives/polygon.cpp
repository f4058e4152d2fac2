#include "polygon.h"

#include "span.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace lucent {

namespace {

// POV-Ray's tolerances: a point this close to the first of its outline (in each
// coordinate) closes it; lengths squared below it are no direction; distances from the
// plane above it make the polygon not flat.
constexpr double kClose = 1e-10;
constexpr double kPlane = 1e-10;

bool near(const Vec3& a, const Vec3& b) {
  return std::abs(a.x - b.x) < kClose && std::abs(a.y - b.y) < kClose &&
         std::abs(a.z - b.z) < kClose;
}

// The plane's frame as POV-Ray spans it; false when the points lie on one line.
bool frame(const std::vector<Vec3>& p, Vec3& u, Vec3& v, Vec3& n) {
  const Vec3 o = p[0];
  size_t i = 1;
  for (; i < p.size(); ++i) {
    u = p[i] - o;
    if (glm::dot(u, u) > kClose) break;
  }
  if (i >= p.size()) return false;
  for (++i; i < p.size(); ++i) {
    v = p[i] - o;
    n = glm::cross(u, v);
    if (glm::dot(v, v) > kClose && glm::dot(n, n) > kClose) break;
  }
  if (i >= p.size()) return false;
  // The in-plane axes as POV-Ray takes them: u at right angles to v, v to n and u (the
  // inside test depends on them only for points exactly level with a corner).
  u = glm::normalize(glm::cross(v, n));
  v = glm::normalize(glm::cross(n, u));
  n = glm::normalize(n);
  return true;
}

}  // namespace

PolygonOutline polygonOutline(const std::vector<Vec3>& points) {
  PolygonOutline out;
  out.points = points;
  if (points.empty()) return out;
  std::vector<Vec3>& p = out.points;
  // Walk the outlines: each ends at the point that repeats its first.
  size_t first = 0;
  bool closed = false;
  for (size_t i = 1; i < p.size(); ++i) {
    closed = false;
    if (near(p[first], p[i])) {
      p[i] = p[first];
      closed = true;
      first = ++i;  // the next outline's first point (the loop steps past it)
    }
  }
  if (!closed) {
    p.push_back(p[std::min(first, p.size() - 1)]);
    out.closedLast = true;
  }
  return out;
}

std::string polygonProblem(const std::vector<Vec3>& p) {
  if (p.size() < 3) return "a polygon needs at least three points";
  Vec3 u, v, n;
  if (!frame(p, u, v, n)) return "the points lie on one line, so the polygon has no area";
  for (size_t i = 0; i < p.size(); ++i) {
    const double d = glm::dot(p[i] - p[0], n);
    if (std::abs(d) > kPlane)
      return fmt::format(
          "the points do not lie in one plane (point {} is {:.3g} from the plane of the first "
          "points; POV-Ray ignores such a polygon)",
          i + 1, std::abs(d));
  }
  return "";
}

Polygon::Polygon(const std::vector<Vec3>& p) {
  const std::string problem = polygonProblem(p);
  if (!problem.empty()) throw std::invalid_argument("polygon: " + problem);
  for (const Vec3& q : p)
    if (!isFinite(q)) throw std::invalid_argument("polygon: a point is not finite");
  frame(p, u_, v_, n_);
  o_ = p[0];
  for (const Vec3& q : p) {
    points_.emplace_back(glm::dot(q - o_, u_), glm::dot(q - o_, v_));
    bounds_.expand(q);
  }
  // The edges, outline by outline: after an edge that returns to its outline's first
  // point a new outline starts at the next point, unless fewer than two points follow
  // (then, as in POV-Ray, the edge goes on to the next point).
  const int count = static_cast<int>(p.size());
  int a = 0, first = 0;
  for (int i = 1; i < count;) {
    edges_.emplace_back(a, i);
    if (i < count - 2 && p[static_cast<size_t>(i)] == p[static_cast<size_t>(first)]) {
      a = first = i + 1;
      i += 2;
    } else {
      a = i++;
    }
  }
}

bool Polygon::insideOutline(double x, double y) const {
  // Even-odd: count the edges that a ray from (x, y) towards +x crosses. An edge end at
  // height y counts as above the ray (half-open), so a ray through a corner counts it once.
  bool inside = false;
  for (const auto& [ia, ib] : edges_) {
    const Vec2 a = points_[static_cast<size_t>(ia)];
    const Vec2 b = points_[static_cast<size_t>(ib)];
    const bool aAbove = a.y >= y, bAbove = b.y >= y;
    if (aAbove == bAbove) continue;
    // The crossing lies at or right of x when the sign of the cross product of the edge
    // (from b) and (x, y) − b agrees with the direction the edge runs in y.
    const bool right = ((b.y - y) * (a.x - b.x) >= (b.x - x) * (a.y - b.y)) == bAbove;
    if (right) inside = !inside;
  }
  return inside;
}

bool Polygon::root(const Ray& ray, double& t) const {
  const double denom = glm::dot(n_, ray.d);
  if (!(std::abs(denom) >= 1e-10 * glm::length(ray.d))) return false;
  t = glm::dot(n_, o_ - ray.o) / denom;
  if (!std::isfinite(t)) return false;
  const Vec3 q = ray.at(t) - o_;
  return insideOutline(glm::dot(q, u_), glm::dot(q, v_));
}

bool Polygon::intersect(const Ray& ray, Hit& hit) const {
  SurfaceRoot r;
  return root(ray, r.t) && intersectRoots(&r, 1, ray, this, hit);
}

void Polygon::crossings(const Ray& ray, CrossingList& out) const {
  SurfaceRoot r;
  const int n = root(ray, r.t) ? 1 : 0;
  crossingsOfRoots(&r, n, ray, this, out);
}

SurfaceInfo Polygon::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo s;
  // Projected onto the plane, as a disc is: error of the size of |p| and |o|.
  Vec3 r = ray.at(hit.t) - o_;
  r -= glm::dot(r, n_) * n_;
  s.p = o_ + r;
  s.pError = gamma(6) * (glm::abs(r) + glm::abs(o_)) + gamma(1) * glm::abs(s.p);
  s.ng = n_;
  s.ns = n_;
  return s;
}

}  // namespace lucent
