#include "quadric.h"

#include "implicit_surface.h"
#include "quadratic.h"
#include "span.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucent {

Quadric::Quadric(const QuadricCoefficients& q) {
  const double all[10] = {q.squares.x, q.squares.y, q.squares.z, q.mixed.x,  q.mixed.y,
                          q.mixed.z,   q.linear.x,  q.linear.y,  q.linear.z, q.constant};
  bool surface = false;
  for (int i = 0; i < 10; ++i) {
    if (!std::isfinite(all[i])) throw std::invalid_argument("quadric: coefficients must be finite");
    if (i < 9 && all[i] != 0.0) surface = true;
  }
  if (!surface) throw std::invalid_argument("quadric: every coefficient but the constant is 0");
  // Columns of the symmetric matrix (glm is column-major; symmetric anyway).
  m_ = Mat3(q.squares.x, 0.5 * q.mixed.x, 0.5 * q.mixed.y, 0.5 * q.mixed.x, q.squares.y,
            0.5 * q.mixed.z, 0.5 * q.mixed.y, 0.5 * q.mixed.z, q.squares.z);
  g_ = q.linear;
  j_ = q.constant;

  // Q = (p − c)ᵀM(p − c) + J − cᵀMc with Mc = −g/2 when M is invertible.
  const double det = glm::determinant(m_);
  const double scale = std::max({std::abs(m_[0][0]), std::abs(m_[1][1]), std::abs(m_[2][2]),
                                 std::abs(m_[0][1]), std::abs(m_[0][2]), std::abs(m_[1][2])});
  if (scale > 0.0 && std::abs(det) > 1e-12 * scale * scale * scale) {
    const Mat3 inv = glm::inverse(m_);
    centre_ = -0.5 * (inv * g_);
    // Positive definite (Sylvester): an ellipsoid, inside where (p−c)ᵀM(p−c) < k.
    const double m1 = m_[0][0], m2 = m_[0][0] * m_[1][1] - m_[0][1] * m_[0][1];
    if (m1 > 0.0 && m2 > 0.0 && det > 0.0) {
      const double k = glm::dot(centre_, m_ * centre_) - j_;
      if (k <= 0.0) {
        bounds_ = AABB();  // empty: Q ≥ 0 everywhere (a point at most)
      } else {
        // The ellipsoid's extent along axis i is √(k·(M⁻¹)ᵢᵢ); widened by a few roundings.
        Vec3 half(std::sqrt(k * inv[0][0]), std::sqrt(k * inv[1][1]), std::sqrt(k * inv[2][2]));
        half *= 1.0 + 1e-9;
        bounds_ = AABB{centre_ - half, centre_ + half};
      }
    }
  } else {
    boundCylinder();
  }
}

// A quadric with no term in one coordinate (x² + y² − 1: a cylinder along z) whose section
// across that axis is an ellipse: bounded across the axis as the ellipse, unbounded along
// it. Clipped and intersected cylinders (POV-Ray's Cylinder_Z of shapes_old.inc) then get
// a finite box from their other bounds.
void Quadric::boundCylinder() {
  for (int k = 0; k < 3; ++k) {
    if (m_[k][k] != 0.0 || g_[k] != 0.0) continue;
    if (sectionBounds(k, j_, bounds_)) return;
  }
}

bool Quadric::sectionBounds(int k, double constant, AABB& out) const {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  if (m_[k][i] != 0.0 || m_[k][j] != 0.0) return false;
  const double a = m_[i][i], b = m_[i][j], c = m_[j][j];
  const double det = a * c - b * b;
  if (!(a > 0.0 && det > 1e-12 * std::max(a, c) * std::max(a, c))) return false;
  // The section's centre and its extent, as the ellipsoid's in two dimensions.
  const double ii = c / det, ij = -b / det, jj = a / det;  // the inverse of [[a b] [b c]]
  const double ci = -0.5 * (ii * g_[i] + ij * g_[j]), cj = -0.5 * (ij * g_[i] + jj * g_[j]);
  const double level = a * ci * ci + 2.0 * b * ci * cj + c * cj * cj - constant;
  if (level <= 0.0) {
    out = AABB();  // empty: Q ≥ 0 everywhere
    return true;
  }
  const double hi = std::sqrt(level * ii) * (1.0 + 1e-9), hj = std::sqrt(level * jj) * (1.0 + 1e-9);
  out = AABB::everything();
  out.lo[i] = ci - hi;
  out.hi[i] = ci + hi;
  out.lo[j] = cj - hj;
  out.hi[j] = cj + hj;
  return true;
}

AABB Quadric::boundsWithin(const AABB& clip) const {
  AABB box = AABB::meet(bounds_, clip);
  for (int k = 0; k < 3 && !box.empty(); ++k) {
    const double lo = box.lo[k], hi = box.hi[k];
    if (!(std::isfinite(lo) && std::isfinite(hi))) continue;
    // The smallest a·t² + b·t over [lo, hi]: at an end, or at the vertex of an upward
    // parabola; lowered by the rounding of its terms, so the section is never too small.
    const double a = m_[k][k], b = g_[k];
    double least = std::min(a * lo * lo + b * lo, a * hi * hi + b * hi);
    if (a > 0.0) {
      const double vertex = -b / (2.0 * a);
      if (vertex > lo && vertex < hi) least = std::min(least, -b * b / (4.0 * a));
    }
    const double t = std::max(std::abs(lo), std::abs(hi));
    least -= 1e-12 * (std::abs(a) * t * t + std::abs(b) * t + std::abs(j_));
    AABB section;
    if (sectionBounds(k, j_ + least, section)) box = AABB::meet(box, section);
  }
  return box;
}

double Quadric::value(const Vec3& p) const { return glm::dot(p, m_ * p) + glm::dot(g_, p) + j_; }

Vec3 Quadric::gradient(const Vec3& p) const { return 2.0 * (m_ * p) + g_; }

int Quadric::lineCrossings(const Ray& ray, double t[2], bool entering[2],
                           bool& startsInside) const {
  // Shift the origin along the ray to its closest approach to the centre: s = s0 + u.
  const double dd = glm::dot(ray.d, ray.d);
  const double s0 = dd > 0.0 ? glm::dot(centre_ - ray.o, ray.d) / dd : 0.0;
  const Vec3 o = ray.o + s0 * ray.d;
  const Vec3 md = m_ * ray.d;
  const double a = glm::dot(ray.d, md);
  const double h = glm::dot(o, md) + 0.5 * glm::dot(g_, ray.d);
  const double c = value(o);
  int n = 0;
  auto polish = [&](double u) {
    // One Newton step on Q itself, unless the slope is too flat to trust.
    const double s = s0 + u;
    const Vec3 p = ray.o + s * ray.d;
    const double slope = glm::dot(gradient(p), ray.d);
    const double step = slope != 0.0 ? value(p) / slope : 0.0;
    return std::abs(step) <= 1e-6 * (1.0 + std::abs(u)) ? s - step : s;
  };
  if (a != 0.0) {
    double u0, u1;
    const double disc = h * h - a * c;
    if (!solveQuadratic(a, h, c, disc, u0, u1) || !(u0 < u1)) {
      // No root or a double one: the sign of a holds on the whole line (but at a point).
      startsInside = a < 0.0;
      return 0;
    }
    t[0] = polish(u0);
    t[1] = polish(u1);
    if (t[1] < t[0]) std::swap(t[0], t[1]);
    entering[0] = a > 0.0;
    entering[1] = !entering[0];
    startsInside = a < 0.0;
    n = 2;
  } else if (h != 0.0) {
    t[0] = polish(-c / (2.0 * h));
    entering[0] = h < 0.0;  // Q decreases along the ray
    startsInside = !entering[0];
    n = 1;
  } else {
    startsInside = c < 0.0;  // Q is constant along the line
  }
  return n;
}

bool Quadric::intersect(const Ray& ray, Hit& hit) const {
  double t[2];
  bool entering[2], startsInside;
  const int n = lineCrossings(ray, t, entering, startsInside);
  const SurfaceRoot roots[2] = {{t[0]}, {t[1]}};
  return intersectRoots(roots, n, ray, this, hit);
}

void Quadric::crossings(const Ray& ray, CrossingList& out) const {
  double t[2];
  bool entering[2], inside;
  const int n = lineCrossings(ray, t, entering, inside);
  crossingsOfLine(t, entering, n, inside, ray, this, out);
}

SurfaceInfo Quadric::surface(const Ray& ray, const Hit& hit) const {
  const Vec3 p = ray.at(hit.t);
  return implicitSurface(ray, hit, p, gradient(p));
}

}  // namespace lucent
