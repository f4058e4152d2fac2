// The text shape's hard cases (docs/accuracy.md): the glyphs o, 8 and e of DejaVu Sans (line
// and quadratic segments, holes), random rays, rays aimed into the holes, rays in the glyph
// plane along a segment's tangent (just inside or outside the edge) and rays through the
// joins of segments, each against a long-double reference: every segment's quadratic solved
// in closed form and polished by Newton steps, the caps by an even-odd count over the same
// curves; built from the same double control points the shape uses.
#include "accuracy_cases.h"

#include "primitives/text.h"
#include "primitives/text_outline.h"

#include <algorithm>
#include <cmath>

namespace lucent::accuracy {

namespace {

struct LSeg {
  int degree;
  LD x[3], y[3];
  LD X(LD s) const {
    return degree == 1 ? x[0] + s * (x[1] - x[0])
                       : (1 - s) * (1 - s) * x[0] + 2 * s * (1 - s) * x[1] + s * s * x[2];
  }
  LD Y(LD s) const {
    return degree == 1 ? y[0] + s * (y[1] - y[0])
                       : (1 - s) * (1 - s) * y[0] + 2 * s * (1 - s) * y[1] + s * s * y[2];
  }
  LD dX(LD s) const {
    return degree == 1 ? x[1] - x[0] : 2 * ((1 - s) * (x[1] - x[0]) + s * (x[2] - x[1]));
  }
  LD dY(LD s) const {
    return degree == 1 ? y[1] - y[0] : 2 * ((1 - s) * (y[1] - y[0]) + s * (y[2] - y[1]));
  }
};

// Roots in [0, 1) of p·X(s) + q·Y(s) + r = 0, polished by Newton steps.
void segmentRoots(const LSeg& g, LD p, LD q, LD r, std::vector<LD>& out) {
  auto f = [&](LD s) { return p * g.X(s) + q * g.Y(s) + r; };
  auto df = [&](LD s) { return p * g.dX(s) + q * g.dY(s); };
  LD a = 0, b, c = f(0);
  if (g.degree == 1) {
    b = f(1) - c;
  } else {
    a = p * (g.x[0] - 2 * g.x[1] + g.x[2]) + q * (g.y[0] - 2 * g.y[1] + g.y[2]);
    b = 2 * (p * (g.x[1] - g.x[0]) + q * (g.y[1] - g.y[0]));
  }
  std::vector<LD> s;
  if (std::fabs(a) <= 1e-30L * (std::fabs(b) + std::fabs(c))) {
    if (b != 0) s.push_back(-c / b);
  } else {
    const LD disc = b * b - 4 * a * c;
    if (disc < 0) return;
    const LD qq = -0.5L * (b + (b < 0 ? -1 : 1) * std::sqrt(disc));
    s.push_back(qq / a);
    s.push_back(qq != 0 ? c / qq : qq / a);
  }
  for (LD v : s) {
    for (int k = 0; k < 3; ++k) {
      const LD d = df(v);
      if (d == 0) break;
      v -= f(v) / d;
    }
    if (v >= 0 && v < 1) out.push_back(v);
  }
}

class RefText final : public RefShape {
 public:
  RefText(const TextOutline& o, double h) : h_(h) {
    for (const PlacedGlyph& g : o.glyphs)
      for (const PrismContour& c : g.contours)
        for (const PrismSegment& s : c) {
          LSeg l{s.degree, {}, {}};
          for (int i = 0; i <= s.degree; ++i) {
            l.x[i] = s.p[i].x;
            l.y[i] = s.p[i].y;
          }
          segs_.push_back(l);
        }
  }

  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    std::vector<LRoot> roots;
    const LD dx = ray.d.x, dy = ray.d.y;
    if (dx != 0 || dy != 0)
      for (const LSeg& g : segs_) {
        std::vector<LD> ss;
        segmentRoots(g, dy, -dx, dx * ray.o.y - dy * ray.o.x, ss);
        for (LD s : ss) {
          const LD t =
              std::fabs(dx) > std::fabs(dy) ? (g.X(s) - ray.o.x) / dx : (g.Y(s) - ray.o.y) / dy;
          const LD z = ray.o.z + t * ray.d.z;
          if (!(z >= 0 && z <= h_)) continue;
          const LD tx = g.dX(s), ty = g.dY(s), len = std::sqrt(tx * tx + ty * ty);
          roots.push_back({t, LVec(ty / len, -tx / len, 0), s > 1e-9L && s < 1 - 1e-9L && len > 0});
        }
      }
    if (ray.d.z != 0)
      for (LD h : {(LD)0, (LD)h_}) {
        const LD t = (h - ray.o.z) / ray.d.z;
        if (inside(ray.o.x + t * dx, ray.o.y + t * dy))
          roots.push_back({t, LVec(0, 0, h == 0 ? -1 : 1)});
      }
    std::sort(roots.begin(), roots.end(), [](const LRoot& a, const LRoot& b) { return a.t < b.t; });
    for (size_t i = 0; i < roots.size(); ++i) {
      const LD dn = roots[i].n.x * ray.d.x + roots[i].n.y * ray.d.y + roots[i].n.z * ray.d.z;
      if ((dn < 0) != (i % 2 == 0)) roots[i].n = -roots[i].n;
      out.push_back(roots[i]);
    }
  }

 private:
  // Even-odd: the crossings of the curves by the ray from (u, v) towards +x.
  bool inside(LD u, LD v) const {
    bool in = false;
    for (const LSeg& g : segs_) {
      std::vector<LD> ss;
      segmentRoots(g, 0, 1, -v, ss);
      for (LD s : ss)
        if (g.X(s) > u) in = !in;
    }
    return in;
  }

  std::vector<LSeg> segs_;
  LD h_;
};

CaseResult newCase(const std::string& name) { return makeCase("Text", name, 1e-13, 1e-11); }

}  // namespace

std::vector<CaseResult> textCases(double effort) {
  const double h = 0.3;
  const TextOutline o = textOutline(defaultFontFile(), "o8e", Vec2(0.0));
  std::vector<std::vector<PrismContour>> glyphs;
  for (const PlacedGlyph& g : o.glyphs) glyphs.push_back(g.contours);
  const Text text(glyphs, h);
  const RefText ref(o, h);
  const AABB b = text.bounds();
  const double size = 2.0;
  const int n = rayCount(1500, effort);
  std::vector<CaseResult> out;
  auto inBox = [&](Rng& rng) {
    return Vec3(uniform(rng, b.lo.x, b.hi.x), uniform(rng, b.lo.y, b.hi.y), uniform(rng, 0, h));
  };
  {
    Rng rng(2101);
    CaseResult r = newCase("o, 8 and e (DejaVu Sans): random rays");
    for (int i = 0; i < n; ++i) {
      const Vec3 target = inBox(rng), orig = target + 3.0 * randomUnit(rng);
      measureRay(r, text, ref, Ray(orig, (target - orig) * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r));
  }
  // The counters: o's at the middle of its box; 8's two and e's eye near their glyphs'
  // middles, by the glyphs' own boxes (the rays spread around them).
  {
    Rng rng(2102);
    CaseResult r = newCase("o, 8 and e: rays into the holes, steep and shallow");
    for (int i = 0; i < n; ++i) {
      const PlacedGlyph& g = o.glyphs[size_t(i % 3)];
      AABB gb;
      for (const PrismContour& c : g.contours)
        for (const PrismSegment& s : c)
          for (int k = 0; k <= s.degree; ++k) gb.expand(Vec3(s.p[k].x, s.p[k].y, 0));
      const double fy = i % 3 == 1 ? (rng() % 2 ? 0.27 : 0.73) : i % 3 == 2 ? 0.68 : 0.5;
      const Vec3 target(gb.lo.x + 0.5 * (gb.hi.x - gb.lo.x) + uniform(rng, -0.05, 0.05),
                        gb.lo.y + fy * (gb.hi.y - gb.lo.y) + uniform(rng, -0.03, 0.03),
                        uniform(rng, 0, h));
      Vec3 d = randomUnit(rng);
      if (i % 2) d.z = std::copysign(3.0, d.z);  // steep: mostly through the hole
      measureRay(r, text, ref, Ray(target - 3.0 * d, d * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r));
  }
  {
    Rng rng(2103);
    CaseResult r = newCase(
        "o, 8 and e: along a glyph's edge (a segment's tangent), 1e-16 to 1e-1 inside or outside");
    std::vector<PrismSegment> segs;
    for (const PlacedGlyph& g : o.glyphs)
      for (const PrismContour& c : g.contours) segs.insert(segs.end(), c.begin(), c.end());
    for (int i = 0; i < n; ++i) {
      const PrismSegment& s = segs[size_t(rng() % segs.size())];
      const double u = uniform(rng, 0.02, 0.98);
      Vec2 p, t;
      if (s.degree == 1) {
        p = s.p[0] + u * (s.p[1] - s.p[0]);
        t = s.p[1] - s.p[0];
      } else {
        p = (1 - u) * (1 - u) * s.p[0] + 2 * u * (1 - u) * s.p[1] + u * u * s.p[2];
        t = 2.0 * ((1 - u) * (s.p[1] - s.p[0]) + u * (s.p[2] - s.p[1]));
      }
      t = glm::normalize(t);
      const Vec2 nrm(t.y, -t.x);
      const Vec2 q = p + (rng() % 2 ? 1 : -1) * logUniform(rng, -16, -1) * nrm;
      const Vec3 d(t.x, t.y, (i / 2) % 2 ? uniform(rng, -0.3, 0.3) : 0.0);
      const Vec3 at(q.x, q.y, uniform(rng, 0.02, h - 0.02));
      measureRay(r, text, ref, Ray(at - 2.0 * d, d * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r));
  }
  {
    Rng rng(2104);
    CaseResult r = newCase("o, 8 and e: rays through the joins of segments");
    std::vector<Vec2> joins;
    for (const PlacedGlyph& g : o.glyphs)
      for (const PrismContour& c : g.contours)
        for (const PrismSegment& s : c) joins.push_back(s.p[0]);
    for (int i = 0; i < n; ++i) {
      const Vec2 v = joins[size_t(rng() % joins.size())];
      const Vec3 target(v.x, v.y, uniform(rng, 0.02, h - 0.02));
      const Vec3 orig = target + 3.0 * randomUnit(rng);
      measureRay(r, text, ref, Ray(orig, (target - orig) * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace lucent::accuracy
