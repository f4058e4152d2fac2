// Shapes written in the test itself (a sphere and a half-space), so the world's and the
// CSG node's acceleration can be checked without the real primitives.
#pragma once

#include "primitives/shape.h"

#include <atomic>

namespace lucent::testing {

class MockSphere final : public Shape {
 public:
  MockSphere(Vec3 c, double r) : c_(c), r_(r) {}
  const char* kind() const override { return "sphere"; }
  AABB bounds() const override { return {c_ - Vec3(r_), c_ + Vec3(r_)}; }
  bool isSolid() const override { return true; }

  bool intersect(const Ray& ray, Hit& hit) const override {
    double t0, t1;
    if (!roots(ray, t0, t1)) return false;
    for (double t : {t0, t1})
      if (t > ray.tmin && t < ray.tmax) {
        hit.t = t;
        hit.shape = this;
        hit.part = 0;
        return true;
      }
    return false;
  }
  void crossings(const Ray& ray, CrossingList& out) const override {
    double t0, t1;
    if (!roots(ray, t0, t1)) return;
    out.startsInside = t0 < ray.tmin && ray.tmin < t1;
    for (int k = 0; k < 2; ++k) {
      double t = k ? t1 : t0;
      if (t >= ray.tmin && t <= ray.tmax) {
        Crossing c;
        c.hit.t = t;
        c.hit.shape = this;
        c.entering = k == 0;
        out.items.push_back(c);
      }
    }
  }
  bool inside(const Vec3& p) const override { return glm::length(p - c_) < r_; }
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override {
    SurfaceInfo s;
    s.p = ray.at(hit.t);
    s.ng = s.ns = glm::normalize(s.p - c_);
    return s;
  }

 private:
  // Roots around the line's closest point to the centre (Ray Tracing Gems, ch. 7).
  bool roots(const Ray& ray, double& t0, double& t1) const {
    Vec3 oc = ray.o - c_;
    double a = glm::dot(ray.d, ray.d);
    double tc = -glm::dot(oc, ray.d) / a;
    Vec3 l = oc + tc * ray.d;
    double disc = r_ * r_ - glm::dot(l, l);
    if (disc <= 0) return false;
    double h = std::sqrt(disc / a);
    t0 = tc - h;
    t1 = tc + h;
    return true;
  }
  Vec3 c_;
  double r_;
};

// The points with n·x < offset: unbounded, as a plane is.
class MockHalfSpace final : public Shape {
 public:
  MockHalfSpace(Vec3 n, double offset) : n_(n), offset_(offset) {}
  const char* kind() const override { return "plane"; }
  AABB bounds() const override { return AABB::everything(); }
  bool isSolid() const override { return true; }
  bool intersect(const Ray& ray, Hit& hit) const override {
    double t = crossing(ray);
    if (!(t > ray.tmin && t < ray.tmax)) return false;
    hit.t = t;
    hit.shape = this;
    return true;
  }
  void crossings(const Ray& ray, CrossingList& out) const override {
    out.startsInside = inside(ray.at(ray.tmin));
    double t = crossing(ray);
    if (t >= ray.tmin && t <= ray.tmax) {
      Crossing c;
      c.hit.t = t;
      c.hit.shape = this;
      c.entering = glm::dot(n_, ray.d) < 0;
      out.items.push_back(c);
    }
  }
  bool inside(const Vec3& p) const override { return glm::dot(n_, p) < offset_; }
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override {
    SurfaceInfo s;
    s.p = ray.at(hit.t);
    s.ng = s.ns = n_;
    return s;
  }

 private:
  double crossing(const Ray& ray) const {
    double dn = glm::dot(n_, ray.d);
    return dn == 0.0 ? kInf : (offset_ - glm::dot(n_, ray.o)) / dn;
  }
  Vec3 n_;
  double offset_;
};

}  // namespace lucent::testing
