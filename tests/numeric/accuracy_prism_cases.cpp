// The prism's hard cases (docs/accuracy.md): a linear star prism with a hole, random rays,
// rays aimed at its vertices, rays along its side faces and rays grazing the cap's edges,
// each against a long-double reference (every side plane met by the line, its point tested
// on the segment; the caps by an even-odd test), built from the same exact double points.
#include "accuracy_cases.h"

#include "primitives/prism.h"

#include <algorithm>
#include <cmath>

namespace lucent::accuracy {

namespace {

using Polygon = std::vector<Vec2>;

class RefPolygonPrism final : public RefShape {
 public:
  RefPolygonPrism(std::vector<Polygon> polys, double h1, double h2)
      : polys_(std::move(polys)), h1_(h1), h2_(h2) {}

  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    std::vector<LRoot> roots;
    const LD dx = ray.d.x, dz = ray.d.z;
    for (const Polygon& pg : polys_)
      for (size_t i = 0; i < pg.size(); ++i) {
        const LD ax = pg[i].x, az = pg[i].y;
        const LD ex = (LD)pg[(i + 1) % pg.size()].x - ax, ez = (LD)pg[(i + 1) % pg.size()].y - az;
        const LD den = dx * ez - dz * ex;
        if (den == 0) continue;
        const LD wx = ax - ray.o.x, wz = az - ray.o.z;
        const LD t = (wx * ez - wz * ex) / den;
        const LD u = (wx * dz - wz * dx) / den;
        if (!(u >= 0 && u < 1)) continue;  // half-open: a vertex belongs to one edge
        const LD y = ray.o.y + t * ray.d.y;
        if (!(y >= h1_ && y <= h2_)) continue;
        const LD len = std::sqrt(ex * ex + ez * ez);
        // At a vertex (a vertical edge of the solid) either face's normal is right.
        roots.push_back({t, LVec(ez / len, 0, -ex / len), u > 1e-9L && u < 1 - 1e-9L});
      }
    if (ray.d.y != 0)
      for (LD h : {(LD)h1_, (LD)h2_}) {
        const LD t = (h - ray.o.y) / ray.d.y;
        if (insidePolygons(ray.o.x + t * dx, ray.o.z + t * dz))
          roots.push_back({t, LVec(0, h == (LD)h1_ ? -1 : 1, 0)});
      }
    std::sort(roots.begin(), roots.end(), [](const LRoot& a, const LRoot& b) { return a.t < b.t; });
    // Outward: against the line where it enters (even places), along it where it leaves.
    for (size_t i = 0; i < roots.size(); ++i) {
      const LD dn = roots[i].n.x * ray.d.x + roots[i].n.y * ray.d.y + roots[i].n.z * ray.d.z;
      if ((dn < 0) != (i % 2 == 0)) roots[i].n = -roots[i].n;
      out.push_back(roots[i]);
    }
  }

 private:
  bool insidePolygons(LD u, LD v) const {
    bool in = false;
    for (const Polygon& pg : polys_)
      for (size_t i = 0; i < pg.size(); ++i) {
        const LD ax = pg[i].x, az = pg[i].y, bx = pg[(i + 1) % pg.size()].x,
                 bz = pg[(i + 1) % pg.size()].y;
        if ((az <= v) == (bz <= v)) continue;
        const LD x = ax + (v - az) * (bx - ax) / (bz - az);
        if (x > u) in = !in;
      }
    return in;
  }

  std::vector<Polygon> polys_;
  double h1_, h2_;
};

PrismContour contour(const Polygon& pts) {
  PrismContour c;
  for (size_t i = 0; i < pts.size(); ++i) {
    PrismSegment s;
    s.p[0] = pts[i];
    s.p[1] = pts[(i + 1) % pts.size()];
    c.push_back(s);
  }
  return c;
}

CaseResult newCase(const std::string& name) { return makeCase("Prisms", name, 1e-14, 1e-12); }

}  // namespace

std::vector<CaseResult> prismCases(double effort) {
  // A five-pointed star (outer radius 1, inner 0.45) with a pentagonal hole, y from 0 to 1.
  Polygon star, hole;
  for (int k = 0; k < 10; ++k) {
    const double r = k % 2 ? 0.45 : 1.0, a = kPi / 2 + k * kPi / 5;
    star.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  for (int k = 0; k < 5; ++k) {
    const double a = kPi / 2 + (2 * k + 1) * kPi / 5;
    hole.emplace_back(0.22 * std::cos(a), 0.22 * std::sin(a));
  }
  const Prism prism({contour(star), contour(hole)}, 0.0, 1.0);
  const RefPolygonPrism ref({star, hole}, 0.0, 1.0);
  const double size = 2.5;
  const int n = rayCount(1200, effort);
  std::vector<CaseResult> out;
  {
    Rng rng(1901);
    CaseResult r = newCase("star with a hole: random rays");
    for (int i = 0; i < n; ++i) {
      Vec3 o = 3.0 * randomUnit(rng);
      Vec3 target(uniform(rng, -1, 1), uniform(rng, 0, 1), uniform(rng, -1, 1));
      measureRay(r, prism, ref, Ray(o, (target - o) * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r));
  }
  {
    Rng rng(1902);
    CaseResult r = newCase("star with a hole: rays through vertices (outer, inner, the hole's)");
    for (int i = 0; i < n; ++i) {
      const Polygon& pg = i % 3 == 2 ? hole : star;
      const Vec2 v = pg[size_t(rng() % pg.size())];
      Vec3 target(v.x, uniform(rng, 0.05, 0.95), v.y);
      Vec3 o = target + 3.0 * randomUnit(rng);
      measureRay(r, prism, ref, Ray(o, (target - o) * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r));
  }
  {
    Rng rng(1903);
    CaseResult r = newCase("star with a hole: along side faces, 1e-16 to 1e-1 inside or outside");
    for (int i = 0; i < n; ++i) {
      const Polygon& pg = i % 3 == 2 ? hole : star;
      const size_t k = size_t(rng() % pg.size());
      const Vec2 a = pg[k], b = pg[(k + 1) % pg.size()];
      const Vec2 e = glm::normalize(b - a), nrm(e.y, -e.x);
      const double off = (rng() % 2 ? 1 : -1) * logUniform(rng, -16, -1);
      const Vec2 q = a + uniform(rng, 0, 1) * (b - a) + off * nrm;
      // In the face's plane (up to the offset), tilted in y or not.
      Vec3 d(e.x, (i / 3) % 2 ? uniform(rng, -0.5, 0.5) : 0.0, e.y);
      Vec3 p(q.x, uniform(rng, 0.05, 0.95), q.y);
      measureRay(r, prism, ref, Ray(p - 3.0 * d, d * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r));
  }
  {
    Rng rng(1904);
    CaseResult r =
        newCase("star with a hole: grazing the caps' edges, 1e-16 to 1e-1 above or below");
    for (int i = 0; i < n; ++i) {
      const Polygon& pg = i % 3 == 2 ? hole : star;
      const size_t k = size_t(rng() % pg.size());
      const Vec2 a = pg[k], b = pg[(k + 1) % pg.size()];
      const Vec2 q = a + uniform(rng, 0, 1) * (b - a);
      const double h = (rng() % 2 ? 1.0 : 0.0) + (rng() % 2 ? 1 : -1) * logUniform(rng, -16, -1);
      const double phi = uniform(rng, 0, 2 * kPi);
      Vec3 d(std::cos(phi), (i / 3) % 2 ? 1e-9 : 0.0, std::sin(phi));
      Vec3 p(q.x, h, q.y);
      measureRay(r, prism, ref, Ray(p - 3.0 * d, d * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace lucent::accuracy
