// The analytic shapes' hard cases (sphere, cylinder, cone, torus, box, and instances of
// them), each measured against its long-double reference by the harness. The bounds set
// here are what the tests assert; docs/accuracy.md explains them.
#include "accuracy_cases.h"

#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

#include "primitives/box.h"
#include "primitives/cone.h"
#include "primitives/cylinder.h"
#include "primitives/instance.h"
#include "primitives/offset.h"
#include "primitives/sphere.h"
#include "primitives/torus.h"

namespace lucent::accuracy {

namespace {

// A shape, its reference and where rays should be aimed at it.
struct Subject {
  std::string name;
  std::shared_ptr<const Shape> shape;
  std::shared_ptr<RefShape> ref;
  double size;  // the object's extent (for the perturbation and for distances)
  AABB aim;     // the box rays are aimed into
};

Subject makeSubject(std::string name, std::shared_ptr<const Shape> shape,
                    std::shared_ptr<RefShape> ref) {
  AABB b = shape->bounds();
  double size = glm::length(b.extent());
  return {std::move(name), std::move(shape), std::move(ref), size, b};
}

Mat4 translate(const Vec3& v) { return glm::translate(Mat4(1.0), v); }
Mat4 scale(const Vec3& s) { return glm::scale(Mat4(1.0), s); }

// A shape placed by worldFromObject, with its reference placed by the same matrix.
Subject instanced(std::string name, std::shared_ptr<const Shape> shape,
                  std::shared_ptr<RefShape> ref, const Mat4& worldFromObject) {
  auto t = Transform::fromMatrix(worldFromObject);
  if (!t) throw std::logic_error("accuracy: singular test transform for " + name);
  return makeSubject(std::move(name), std::make_shared<Instance>(std::move(shape), *t, 0),
                     refInstance(std::move(ref), worldFromObject));
}

// The five analytic solids at scale k around c, in their own coordinates (the torus is
// always centred at the origin, so it is moved to c through an Instance unless c = 0).
std::vector<Subject> solids(double k, const Vec3& c) {
  const Vec3 base = c - k * Vec3(0.2, 0.8, 0.1), cap = c + k * Vec3(0.1, 0.9, 0.3);
  const Vec3 lo = c - k * Vec3(1, 0.5, 0.25), hi = c + k * Vec3(0.5, 1, 0.75);
  std::vector<Subject> s = {
      makeSubject("sphere", std::make_shared<Sphere>(c, k), refSphere(c, k)),
      makeSubject("cylinder", std::make_shared<Cylinder>(base, cap, 0.5 * k, false),
                  refCylinder(base, cap, 0.5 * k)),
      makeSubject("cone", std::make_shared<Cone>(base, 0.7 * k, cap, 0.1 * k, false),
                  refCone(base, 0.7 * k, cap, 0.1 * k)),
      makeSubject("box", std::make_shared<Box>(lo, hi), refBox(lo, hi)),
  };
  if (c == Vec3(0.0))
    s.push_back(makeSubject("torus", std::make_shared<Torus>(k, 0.25 * k), refTorus(k, 0.25 * k)));
  else
    s.push_back(instanced("torus (translated instance)", std::make_shared<Torus>(k, 0.25 * k),
                          refTorus(k, 0.25 * k), translate(c)));
  return s;
}

// The unit sphere and torus at the origin, placed at c with size k through an Instance.
std::vector<Subject> instancedSolids(double k, const Vec3& c) {
  Mat4 m = translate(c) * scale(Vec3(k));
  return {
      instanced("sphere (instance)", std::make_shared<Sphere>(Vec3(0.0), 1.0),
                refSphere(Vec3(0.0), 1.0), m),
      instanced("torus (instance)", std::make_shared<Torus>(1.0, 0.25), refTorus(1.0, 0.25), m)};
}

// A ray from a random point at `dist` sizes from the aim box's centre towards a random
// point of the box, with a random speed (directions are never unit in Lucent's tests).
Ray aimedRay(Rng& rng, const Subject& s, double dist) {
  Vec3 c = s.aim.center();
  Vec3 o = c + dist * s.size * randomUnit(rng);
  Vec3 target(uniform(rng, s.aim.lo.x, s.aim.hi.x), uniform(rng, s.aim.lo.y, s.aim.hi.y),
              uniform(rng, s.aim.lo.z, s.aim.hi.z));
  return Ray(o, (target - o) * uniform(rng, 0.5, 2.0));
}

CaseResult newCase(const std::string& group, const std::string& name, double boundRelT,
                   double boundAngle) {
  CaseResult r;
  r.group = group;
  r.name = name;
  r.boundRelT = boundRelT;
  r.boundAngle = boundAngle;
  return r;
}

// The bounds of the unit-scale cases, asserted on the crossings at least 6° from grazing.
// t: a root computed in double from exact data by a backward-stable method is within a
// few u·κ (u = 2^-53), κ <= 1/|cos θ| <= 10 there; 1e-14 (90 u) leaves room for each
// shape's chain of operations and still catches the loss of 2 bits. Normal: it comes
// from the hit point, which t's error moves along the ray by up to 1e-14·|t·d| (|t·d| <=
// 7.5 units here), turning the normal by that times the curvature (up to 1/0.1 at the
// narrow end of the cones): 7.5e-13, so 1e-12.
constexpr double kUnitT = 1e-14;
constexpr double kUnitN = 1e-12;

// A point on a surface, its outward normal (or, on an edge, a direction between the two
// faces' normals: a line perpendicular to it grazes the edge).
struct SurfacePoint {
  Vec3 p, n;
};

// A line tangent to the surface at sp (direction w ⟂ n), moved off it along n by
// side·δ·size, δ log-uniform in [1e-16, 1e-1]: half graze from outside, half cut a thin
// chord. The origin is 2 to 5 sizes back along the line.
Ray grazingRay(Rng& rng, const SurfacePoint& sp, double size) {
  Vec3 w = randomPerpendicular(rng, sp.n);
  double side = rng() % 2 ? 1.0 : -1.0;
  Vec3 q = sp.p + side * logUniform(rng, -16.0, -1.0) * size * sp.n;
  return Ray(q - uniform(rng, 2.0, 5.0) * size * w, w * uniform(rng, 0.5, 2.0));
}

// A point on the rim circle of radius r around c, the centre of an end disc whose
// outward normal is a (a cylinder's rim): the edge "normal" halfway between the side's
// radial direction u and a.
SurfacePoint rimPoint(Rng& rng, const Vec3& c, const Vec3& a, double r) {
  Vec3 u = randomPerpendicular(rng, a);
  return {c + r * u, glm::normalize(u + a)};
}

}  // namespace

// Random rays at unit scale, for comparison with the hard cases.
std::vector<CaseResult> baselineCases(double effort) {
  std::vector<CaseResult> out;
  Rng rng(1001);
  for (const Subject& s : solids(1.0, Vec3(0.25, -0.5, 0.125))) {
    CaseResult r = newCase("Unit scale, random rays (for comparison)", s.name, kUnitT, kUnitN);
    for (int i = 0; i < rayCount(4000, effort); ++i)
      measureRay(r, *s.shape, *s.ref, aimedRay(rng, s, 3.0), s.size);
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<CaseResult> grazingCases(double effort) {
  const std::string group = "Grazing and tangent rays";
  std::vector<CaseResult> out;
  const int n = rayCount(4000, effort);

  {  // Sphere: tangent lines at random points, moved off by 1e-16 .. 1e-1 of the radius.
    Rng rng(1101);
    const Vec3 c(0.25, -0.5, 0.125);
    Sphere sphere(c, 1.0);
    auto ref = refSphere(c, 1.0);
    CaseResult r = newCase(group, "sphere", kUnitT, kUnitN);
    for (int i = 0; i < n; ++i) {
      Vec3 nrm = randomUnit(rng);
      measureRay(r, sphere, *ref, grazingRay(rng, {c + nrm, nrm}, 1.0), 2.0);
    }
    out.push_back(std::move(r));
  }
  {  // Cylinder: tangent to the side (also along its lines) and grazing the rims.
    Rng rng(1102);
    const Vec3 base(0.1, -0.4, 0.2), cap(0.4, 0.7, 0.5);
    const double rad = 0.5;
    Cylinder cyl(base, cap, rad, false);
    auto ref = refCylinder(base, cap, rad);
    const Vec3 a = glm::normalize(cap - base);
    CaseResult r = newCase(group, "cylinder (side and rims)", kUnitT, kUnitN);
    for (int i = 0; i < n; ++i) {
      SurfacePoint sp;
      if (i % 3 != 2) {
        Vec3 u = randomPerpendicular(rng, a);
        sp = {base + uniform(rng, 0.0, 1.0) * (cap - base) + rad * u, u};
      } else {
        sp = i % 2 ? rimPoint(rng, base, -a, rad) : rimPoint(rng, cap, a, rad);
      }
      measureRay(r, cyl, *ref, grazingRay(rng, sp, 1.5), 1.5);
    }
    out.push_back(std::move(r));
  }
  {  // Cones, truncated and pointed: tangent to the side and grazing the rims.
    Rng rng(1103);
    const Vec3 base(-0.2, -0.3, 0.1), cap(0.3, 0.9, -0.2);
    const Vec3 a = glm::normalize(cap - base);
    const double rBase = 0.6, h = glm::length(cap - base);
    CaseResult r = newCase(group, "cone (side and rims)", kUnitT, kUnitN);
    for (double rCap : {0.15, 0.0}) {
      Cone cone(base, rBase, cap, rCap, false);
      auto ref = refCone(base, rBase, cap, rCap);
      const double k = (rCap - rBase) / h;
      for (int i = 0; i < n / 2; ++i) {
        Vec3 u = randomPerpendicular(rng, a);
        Vec3 side = glm::normalize(u - k * a);
        SurfacePoint sp;
        if (i % 3 < 2) {
          // Up to where the radius is a fifth of the base's: the apex has rows of its own.
          double z = uniform(rng, 0.0, rCap > 0.0 ? h : 0.8 * h);
          sp = {base + z * a + (rBase + k * z) * u, side};
        } else if (i % 6 == 2 || rCap == 0.0) {
          sp = {base + rBase * u, glm::normalize(side - a)};  // the base's rim
        } else {
          sp = {cap + rCap * u, glm::normalize(side + a)};  // the cap's rim
        }
        measureRay(r, cone, *ref, grazingRay(rng, sp, 1.5), 1.5);
      }
    }
    out.push_back(std::move(r));
    // Lines passing the apex of the pointed cone at a distance δ in a random direction.
    // cone.cpp forms the side's quadratic relative to the apex, where the side's function
    // x² + y² − r(z)² has a zero gradient: its terms keep their relative precision down
    // to the rounding of the line itself, which carrying the ray into the cone's frame
    // leaves at about u·(distance from the origin) ≈ 1e-15. Below that the decision is
    // rounding's (reported by the table, not asserted).
    Cone cone(base, rBase, cap, 0.0, false);
    auto ref = refCone(base, rBase, cap, 0.0);
    // t keeps its precision up to the apex (the clear rows' bound is 10x the worst
    // measured, as everywhere here). The normal turns by t's error over the distance from the axis,
    // so near the apex it is not bounded.
    CaseResult apart = newCase(group, "cone: lines passing the apex 1e-7 to 1e-1 away", 1e-13, 0.0);
    CaseResult close =
        newCase(group, "cone: lines passing the apex 1e-13 to 1e-7 away", 1e-13, 0.0);
    CaseResult rounding =
        newCase(group, "cone: lines passing within 1e-16 to 1e-13 of the apex", 0.0, 0.0);
    rounding.decisionsAsserted = false;
    for (int i = 0; i < n; ++i) {
      Vec3 off = randomUnit(rng), w = randomPerpendicular(rng, off);
      bool near = i % 2;
      double delta = near ? logUniform(rng, -16.0, -7.0) : logUniform(rng, -7.0, -1.0);
      Vec3 q = cap + delta * 1.5 * off;
      Ray ray(q - uniform(rng, 2.0, 5.0) * 1.5 * w, w * uniform(rng, 0.5, 2.0));
      measureRay(!near ? apart : delta * 1.5 >= 1e-13 ? close : rounding, cone, *ref, ray, 1.5);
    }
    out.push_back(std::move(apart));
    out.push_back(std::move(close));
    out.push_back(std::move(rounding));
  }
  {  // Torus: tangent lines at random points of the surface (elliptic outside, hyperbolic
     // on the inner half, where the tangent plane cuts the surface).
    Rng rng(1104);
    const double R = 1.0, rr = 0.25;
    Torus torus(R, rr);
    auto ref = refTorus(R, rr);
    CaseResult r = newCase(group, "torus (tangent at random points)", kUnitT, kUnitN);
    for (int i = 0; i < n / 2; ++i) {
      double th = uniform(rng, -kPi, kPi), ph = uniform(rng, -kPi, kPi);
      Vec3 radial(std::cos(ph), 0.0, std::sin(ph));
      Vec3 nrm = std::cos(th) * radial + Vec3(0.0, std::sin(th), 0.0);
      measureRay(r, torus, *ref, grazingRay(rng, {R * radial + rr * nrm, nrm}, 1.0), 2.5);
    }
    out.push_back(std::move(r));
    // Lines over the top circle (ρ = R, y = r) at height r·(1 ± δ): they touch the torus
    // at two points at once, where the quartic has two double roots.
    CaseResult top =
        newCase(group, "torus (over the top circle: two tangent points)", kUnitT, kUnitN);
    for (int i = 0; i < n / 2; ++i) {
      double b = uniform(rng, -0.95, 0.95);
      double y = rr * (1.0 + (rng() % 2 ? 1.0 : -1.0) * logUniform(rng, -16.0, -1.0));
      double phi = uniform(rng, -kPi, kPi);
      Vec3 along(std::cos(phi), 0.0, std::sin(phi)), across(-std::sin(phi), 0.0, std::cos(phi));
      Ray ray(Vec3(0.0, y, 0.0) + b * across - 3.0 * along, along * uniform(rng, 0.5, 2.0));
      measureRay(top, torus, *ref, ray, 2.5);
    }
    out.push_back(std::move(top));
  }
  {  // Torus: through the hole (tilted lines through the disc ρ < R − r, y = 0), and
     // parallel to the axis at every distance from it, on the axis itself and within δ of
     // the tube's inner and outer equators (tangent there).
    Rng rng(1105);
    const double R = 1.0, rr = 0.3;
    Torus torus(R, rr);
    auto ref = refTorus(R, rr);
    CaseResult hole = newCase("Torus hole and axis", "torus: through the hole", kUnitT, kUnitN);
    CaseResult axis = newCase("Torus hole and axis", "torus: parallel to the axis", kUnitT, kUnitN);
    for (int i = 0; i < n / 2; ++i) {
      double rho = uniform(rng, 0.0, R - rr), phi = uniform(rng, -kPi, kPi);
      Vec3 through(rho * std::cos(phi), 0.0, rho * std::sin(phi));
      Vec3 dir = glm::normalize(Vec3(uniform(rng, -1.5, 1.5), -1.0, uniform(rng, -1.5, 1.5)));
      measureRay(hole, torus, *ref, Ray(through - 3.0 * dir, dir * uniform(rng, 0.5, 2.0)), 2.6);

      int kind = i % 4;
      double d = kind == 0   ? uniform(rng, 0.0, 1.5)
                 : kind == 1 ? (R + rr) * (1.0 + (rng() % 2 ? 1 : -1) * logUniform(rng, -16, -1))
                 : kind == 2 ? (R - rr) * (1.0 + (rng() % 2 ? 1 : -1) * logUniform(rng, -16, -1))
                             : (i % 16 == 3 ? 0.0 : logUniform(rng, -12, -1));
      phi = uniform(rng, -kPi, kPi);
      double sgn = rng() % 2 ? 1.0 : -1.0;
      Ray ray(Vec3(d * std::cos(phi), -3.0 * sgn, d * std::sin(phi)),
              Vec3(0.0, sgn * uniform(rng, 0.5, 2.0), 0.0));
      measureRay(axis, torus, *ref, ray, 2.6);
    }
    out.push_back(std::move(hole));
    out.push_back(std::move(axis));
  }
  return out;
}

std::vector<CaseResult> farAndScaledCases(double effort) {
  std::vector<CaseResult> out;
  const int n = rayCount(2000, effort);
  {
    // Unit objects 1e5 from the origin. Their points' coordinates are ~1e5, so a point
    // (and with it the normal of a unit object) is known only to ~1e5·ε ≈ 1e-11 absolute;
    // t itself stays a few ε relative because every shape first subtracts its own
    // position (exact for nearby coordinates, Sterbenz's lemma).
    const Vec3 c(1e5, -3e4, 2e4);
    std::vector<Subject> subjects = solids(1.0, c);
    subjects.push_back(instancedSolids(1.0, c)[0]);
    const std::string nearby = "Unit objects 1e5 from the origin, camera nearby (3 units away)";
    const std::string origin = "Unit objects 1e5 from the origin, camera at the origin";
    Rng rng(1201);
    // t as at unit scale. Normal, camera nearby: the hit point's coordinates (~1e5) carry
    // 1e5·u ≈ 1.1e-11 of rounding, times the curvature (up to 10 at the cone's cap): 2e-10.
    for (const Subject& s : subjects) {
      CaseResult r = newCase(nearby, s.name, kUnitT, 2e-10);
      for (int i = 0; i < n; ++i) measureRay(r, *s.shape, *s.ref, aimedRay(rng, s, 3.0), s.size);
      out.push_back(std::move(r));
    }
    // Camera at the origin: t ≈ 1e5, so t's bound 1e-14 allows 1e-9 of position along the
    // ray, times the curvature (up to 10): 1e-8.
    for (const Subject& s : subjects) {
      CaseResult r = newCase(origin, s.name, kUnitT, 1e-8);
      for (int i = 0; i < n; ++i) {
        Ray ray = aimedRay(rng, s, 0.0);  // a target in the object
        Vec3 target = ray.o + ray.d;
        measureRay(r, *s.shape, *s.ref, Ray(Vec3(0.0), target * uniform(rng, 0.5, 2.0)), s.size);
      }
      out.push_back(std::move(r));
    }
  }
  for (double k : {1e-4, 1e4}) {
    // The same scene scaled: every relative error must stay what it is at unit scale.
    const std::string group = k < 1 ? "Scene scaled by 1e-4" : "Scene scaled by 1e4";
    const Vec3 off = k * Vec3(0.3, -0.2, 0.1);
    std::vector<Subject> subjects;
    for (Subject& s : solids(k, off))
      if (s.name != "torus (translated instance)") subjects.push_back(std::move(s));
    subjects.push_back(solids(k, Vec3(0.0)).back());  // the torus, centred in its own space
    for (Subject& s : instancedSolids(k, off)) subjects.push_back(std::move(s));
    Rng rng(k < 1 ? 1202 : 1203);
    for (const Subject& s : subjects) {
      CaseResult r = newCase(group, s.name, kUnitT, kUnitN);  // relative errors are scale-free
      for (int i = 0; i < n; ++i) measureRay(r, *s.shape, *s.ref, aimedRay(rng, s, 3.0), s.size);
      out.push_back(std::move(r));
    }
  }
  return out;
}

namespace {

// Snell refraction of unit d through unit n (n against d) with relative index eta, or the
// mirror direction under total internal reflection.
Vec3 refractOrReflect(const Vec3& d, const Vec3& n, double eta) {
  double c = -glm::dot(d, n);
  double k = 1.0 - eta * eta * (1.0 - c * c);
  if (k < 0.0) return d + 2.0 * c * n;
  return eta * d + (eta * c - std::sqrt(k)) * n;
}

// A random unit direction on the side `side` of n whose |cos| to n lies in [lo, hi].
Vec3 directionOnSide(Rng& rng, const Vec3& n, double side, double lo, double hi) {
  double c = uniform(rng, lo, hi);
  Vec3 t = randomPerpendicular(rng, n);
  return side * c * n + std::sqrt(1.0 - c * c) * t;
}

}  // namespace

std::vector<CaseResult> secondaryRayCases(double effort) {
  // Rays leaving a surface from offsetRayOrigin (Lucent's one strategy against
  // self-intersection) in mirror, refracted, random and shallow directions, out of the
  // solid and into it. The reference sees the offset origin exactly: every crossing it
  // lists is real, and the surface just left lies behind. So any extra crossing is a
  // re-hit, counted wrong; rounding never excuses one (Perturb::DirectionOnly).
  const std::string group = "Secondary rays leaving a surface (must never re-hit it)";
  struct Setting {
    double k;
    Vec3 at;
  };
  const Setting settings[] = {{1.0, Vec3(0.25, -0.5, 0.125)},
                              {1e-4, Vec3(1e-4, 2e-4, -3e-4)},
                              {1e4, Vec3(-2e4, 1e4, 5e3)},
                              {1.0, Vec3(1e5, -3e4, 2e4)}};
  // Also through a non-uniform, mirrored, sheared instance 1e3 away.
  Mat4 warp = translate(Vec3(1e3, -2e3, 500.0)) *
              glm::rotate(Mat4(1.0), 0.7, glm::normalize(Vec3(1, 2, 3))) *
              scale(Vec3(3.0, 0.5, -1.5));
  warp[1][0] += 0.4;
  const int n = rayCount(1500, effort);
  std::vector<CaseResult> out;
  const std::vector<Subject> units = solids(1.0, Vec3(0.0));  // named as the cases are
  for (size_t which = 0; which < units.size(); ++which) {
    // No error bounds: a crossing just ahead of the origin (a short chord near a rim) has
    // a t of any smallness, whose relative error is the origin's own rounding over it.
    CaseResult r = newCase(group, units[which].name, 0.0, 0.0);
    Rng rng(1300 + which);
    std::vector<Subject> subjects;
    for (const Setting& st : settings) subjects.push_back(solids(st.k, st.at)[which]);
    const Subject& unit = units[which];
    subjects.push_back(instanced(unit.name + " (warped instance)", unit.shape, unit.ref, warp));
    for (const Subject& s : subjects) {
      for (int i = 0, tries = 0; i < n && tries < 20 * n; ++tries) {
        Ray primary = aimedRay(rng, s, 3.0);
        Hit h;
        if (!s.shape->intersect(primary, h)) continue;
        ++i;
        SurfaceInfo si = s.shape->surface(primary, h);
        Vec3 d = glm::normalize(primary.d);
        double cosIn = glm::dot(d, si.ng);
        if (cosIn == 0.0) continue;
        Vec3 facing = cosIn < 0.0 ? si.ng : -si.ng;
        const Vec3 dirs[] = {
            d - 2.0 * glm::dot(d, facing) * facing,                      // mirror
            refractOrReflect(d, facing, cosIn < 0.0 ? 1.0 / 1.5 : 1.5),  // refracted
            directionOnSide(rng, si.ng, 1.0, 0.05, 1.0),                 // out of the solid
            directionOnSide(rng, si.ng, -1.0, 0.05, 1.0),                // into it
            directionOnSide(rng, si.ng, 1.0, 1e-4, 0.05),                // shallow, out
            directionOnSide(rng, si.ng, -1.0, 1e-4, 0.05),               // shallow, in
        };
        for (const Vec3& w0 : dirs) {
          Vec3 w = glm::normalize(w0);
          if (glm::dot(w, si.ng) == 0.0) continue;
          Ray ray(offsetRayOrigin(si.p, si.pError, si.ng, w), w * uniform(rng, 0.5, 2.0));
          measureRay(r, *s.shape, *s.ref, ray, s.size, Perturb::DirectionOnly);
        }
      }
    }
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<CaseResult> zeroDirectionCases(double effort) {
  // Directions with one or two components exactly 0 (axis-aligned rays are common: an
  // orthographic camera looking down an axis). Slab tests meet ±inf and 0·inf here.
  // Half of the box's rays run exactly in a face plane or along an edge line.
  const std::string group = "Rays with zero direction components";
  std::vector<CaseResult> out;
  const int n = rayCount(3000, effort);
  std::vector<Subject> subjects = solids(1.0, Vec3(0.0));
  // An upright cylinder and cone too: rays along the axis and in the cap planes.
  subjects.push_back(
      makeSubject("cylinder (axis along y)",
                  std::make_shared<Cylinder>(Vec3(0, -1, 0), Vec3(0, 1, 0), 0.5, false),
                  refCylinder(Vec3(0, -1, 0), Vec3(0, 1, 0), 0.5)));
  subjects.push_back(
      makeSubject("cone (axis along y)",
                  std::make_shared<Cone>(Vec3(0, -1, 0), 0.75, Vec3(0, 1, 0), 0.0, false),
                  refCone(Vec3(0, -1, 0), 0.75, Vec3(0, 1, 0), 0.0)));
  Rng rng(1401);
  for (const Subject& s : subjects) {
    CaseResult r = newCase(group, s.name, kUnitT, kUnitN);
    for (int i = 0; i < n; ++i) {
      Vec3 d(0.0);
      int axis = int(rng() % 3);
      d[axis] = (rng() % 2 ? 1.0 : -1.0) * uniform(rng, 0.5, 2.0);
      if (i % 2) d[(axis + 1) % 3] = uniform(rng, -2.0, 2.0);  // one zero component
      Vec3 target(uniform(rng, s.aim.lo.x, s.aim.hi.x), uniform(rng, s.aim.lo.y, s.aim.hi.y),
                  uniform(rng, s.aim.lo.z, s.aim.hi.z));
      if (s.name == "box" && i % 4 < 2) {
        // Snap the coordinates across the ray to the box's planes: in a face plane, or
        // exactly along an edge.
        for (int k = 0; k < 3; ++k)
          if (d[k] == 0.0 && rng() % 2) target[k] = rng() % 2 ? s.aim.lo[k] : s.aim.hi[k];
      }
      measureRay(r, *s.shape, *s.ref, Ray(target - 3.0 * s.size * d, d), s.size);
    }
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<CaseResult> nearSingularCases(double effort) {
  // Instances whose matrices are close to singular: a factor 1e-7 squashes a shape to a
  // wafer, a shear of 1e3 stretches it to a needle. Rays are carried into object space by
  // the inverse (double, computed once per instance); the reference uses the long double
  // inverse of the same double matrix.
  const std::string group = "Near-singular transforms through Instance";
  Mat4 shear(1.0);
  shear[1][0] = 1e3;  // x' = x + 1000·y
  Mat4 shearRot = glm::rotate(Mat4(1.0), 0.3, glm::normalize(Vec3(1, -2, 0.5))) * shear;
  Mat4 shearZ(1.0);
  shearZ[0][2] = -700.0;  // z' = z − 700·x
  // t: as at unit scale (the trip into object space rounds the ray's data by a few u of
  // their own size, which the map carries back unchanged in relative terms). Normal: a
  // shear with condition number κ ≈ 1e6 amplifies the rounding of the object-space normal
  // and of the normal matrix by up to κ: 256·u·κ ≈ 2.8e-8. A diagonal scale does not
  // amplify the direction errors of a normal (each component is scaled by one factor),
  // but its analysis gives no bound sharper than the shear's (κ = 1e7); its rows assert
  // 1e-10 as a regression guard, 10× the largest error measured with 4× the tests' rays.
  struct Item {
    std::string name;
    std::shared_ptr<const Shape> shape;
    std::shared_ptr<RefShape> ref;
    Mat4 m;
    double boundAngle;
  };
  const Vec3 base(0, -0.5, 0), cap(0, 0.5, 0);
  const double kShearN = 256.0 * kMachineEps * 1e6;
  std::vector<Item> items = {
      {"sphere, scale(1e-7 1 1)", std::make_shared<Sphere>(Vec3(0.0), 1.0),
       refSphere(Vec3(0.0), 1.0), scale(Vec3(1e-7, 1, 1)), 1e-10},
      {"box, scale(1e-7 1 1), rotated", std::make_shared<Box>(Vec3(-1.0), Vec3(1.0)),
       refBox(Vec3(-1.0), Vec3(1.0)),
       glm::rotate(Mat4(1.0), 0.5, glm::normalize(Vec3(1, 1, 0))) * scale(Vec3(1e-7, 1, 1)), 1e-10},
      {"torus, scale(1 1e-7 1)", std::make_shared<Torus>(1.0, 0.25), refTorus(1.0, 0.25),
       scale(Vec3(1, 1e-7, 1)), 1e-10},
      {"cylinder, shear x += 1000 y", std::make_shared<Cylinder>(base, cap, 0.5, false),
       refCylinder(base, cap, 0.5), shear, kShearN},
      {"sphere, shear x += 1000 y, rotated", std::make_shared<Sphere>(Vec3(0.0), 1.0),
       refSphere(Vec3(0.0), 1.0), shearRot, kShearN},
      {"cone, shear z −= 700 x", std::make_shared<Cone>(base, 0.5, cap, 0.0, false),
       refCone(base, 0.5, cap, 0.0), shearZ, kShearN},
  };
  std::vector<CaseResult> out;
  const int n = rayCount(3000, effort);
  Rng rng(1501);
  for (const Item& it : items) {
    Subject s = instanced(it.name, it.shape, it.ref, it.m);
    CaseResult r = newCase(group, it.name, kUnitT, it.boundAngle);
    // Aimed at points of the object (its world box is mostly empty for a sheared shape),
    // from 2 world sizes away.
    const AABB ob = it.shape->bounds();
    for (int i = 0; i < n; ++i) {
      Vec3 inObject(uniform(rng, ob.lo.x, ob.hi.x), uniform(rng, ob.lo.y, ob.hi.y),
                    uniform(rng, ob.lo.z, ob.hi.z));
      Vec3 target = Vec3(it.m * Vec4(inObject, 1.0));
      Vec3 o = target + 2.0 * s.size * randomUnit(rng);
      measureRay(r, *s.shape, *s.ref, Ray(o, (target - o) * uniform(rng, 0.5, 2.0)), s.size);
    }
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<CaseResult> allCases(double effort) {
  std::vector<CaseResult> all;
  for (auto family : {baselineCases, grazingCases, farAndScaledCases, secondaryRayCases,
                      zeroDirectionCases, nearSingularCases, superellipsoidCases, quadricCases,
                      blobCases, prismCases, latheCases, isosurfaceCases, textCases, sorCases,
                      sweepCases, ovusCases, heightFieldCases, meshCases, meshAlongEdgeCases}) {
    std::vector<CaseResult> part = family(effort);
    all.insert(all.end(), part.begin(), part.end());
  }
  return all;
}

}  // namespace lucent::accuracy
