// The height field's hard cases (docs/accuracy.md): a 9 x 7 grid of varied heights with a
// water level, random rays, rays edge-on in the vertical planes of its grid lines and of
// its cells' diagonals, and rays along its grid edges just above or below them, each
// against a long-double reference built from the same 16-bit heights: every triangle's
// plane met by the line, its point kept when that triangle owns it (one owner for every
// point of the square, so a shared edge is crossed once), the walls and the floor where
// they lie under the surface.
#include "accuracy_cases.h"

#include "primitives/height_field.h"

#include <algorithm>
#include <cmath>

namespace lucent::accuracy {

namespace {

class RefHeightField final : public RefShape {
 public:
  RefHeightField(std::shared_ptr<const HeightMap> m, double floor)
      : m_(std::move(m)), floor_(floor) {}

  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    std::vector<LRoot> roots;
    const int W = m_->width, H = m_->depth;
    const LD sx = W - 1, sz = H - 1;
    for (int j = 0; j + 1 < H; ++j)
      for (int i = 0; i + 1 < W; ++i)
        for (int upper = 0; upper < 2; ++upper) {
          // The plane y = a + b X + c Z over grid coordinates X = x sx, Z = z sz.
          LD a, b, c;
          if (!upper) {
            const LD y1 = h(i, j), y2 = h(i + 1, j), y3 = h(i, j + 1);
            b = y2 - y1, c = y3 - y1, a = y1 - b * i - c * j;
          } else {
            const LD y4 = h(i + 1, j + 1), y3 = h(i, j + 1), y2 = h(i + 1, j);
            b = y4 - y3, c = y4 - y2, a = y4 - b * (i + 1) - c * (j + 1);
          }
          const LD den = ray.d.y - b * sx * ray.d.x - c * sz * ray.d.z;
          if (den == 0) continue;
          const LD t = (a + b * sx * ray.o.x + c * sz * ray.o.z - ray.o.y) / den;
          const LD X = (ray.o.x + t * ray.d.x) * sx, Z = (ray.o.z + t * ray.d.z) * sz;
          if (!(X >= 0 && X <= sx && Z >= 0 && Z <= sz)) continue;
          if (owner(X, Z) != 2 * (j * (W - 1) + i) + upper) continue;
          if (ray.o.y + t * ray.d.y < floor_) continue;
          LVec n(-b * sx, 1, -c * sz);
          // On a cell's edge or diagonal (or at the square's rim) either face's normal is right.
          auto near = [](LD v) { return std::abs(v - std::round(v)) < 1e-9L; };
          const bool edge = near(X) || near(Z) || near(X + Z);
          roots.push_back({t, n / std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z), !edge});
        }
    auto wall = [&](int axis, LD plane, const LVec& n) {
      if (ray.d[axis] == 0) return;
      const LD t = (plane - ray.o[axis]) / ray.d[axis];
      LVec p = ray.at(t);
      p[axis] = plane;  // on the wall's plane exactly, not a rounding off it
      if (!(p.x >= 0 && p.x <= 1 && p.z >= 0 && p.z <= 1)) return;
      if (axis != 1 && !(p.y >= floor_)) return;
      // Where the wall or the floor meets the surface either normal is right.
      const LD above = height(p.x * sx, p.z * sz) - p.y;
      // So does a wall at the square's corner edges.
      auto rim = [](LD v) { return std::abs(v) < 1e-12L || std::abs(v - 1) < 1e-12L; };
      const bool corner = axis != 1 && rim(axis == 0 ? p.z : p.x);
      if (above > 0) roots.push_back({t, n, above > 1e-9L && !corner});
    };
    wall(0, 0, LVec(-1, 0, 0));
    wall(0, 1, LVec(1, 0, 0));
    wall(2, 0, LVec(0, 0, -1));
    wall(2, 1, LVec(0, 0, 1));
    wall(1, floor_, LVec(0, -1, 0));
    std::sort(roots.begin(), roots.end(), [](const LRoot& x, const LRoot& y) { return x.t < y.t; });
    out.insert(out.end(), roots.begin(), roots.end());
  }

 private:
  LD h(int x, int z) const { return m_->at(x, z) / 65536.0L; }
  int owner(LD X, LD Z) const {
    const int i = std::min(static_cast<int>(std::floor(X)), m_->width - 2);
    const int j = std::min(static_cast<int>(std::floor(Z)), m_->depth - 2);
    return 2 * (j * (m_->width - 1) + i) + ((X - i) + (Z - j) > 1 ? 1 : 0);
  }
  LD height(LD X, LD Z) const {
    const int i = std::min(static_cast<int>(std::floor(X)), m_->width - 2);
    const int j = std::min(static_cast<int>(std::floor(Z)), m_->depth - 2);
    const LD s = X - i, u = Z - j;
    if (s + u <= 1) return h(i, j) + (h(i + 1, j) - h(i, j)) * s + (h(i, j + 1) - h(i, j)) * u;
    return h(i + 1, j + 1) + (h(i, j + 1) - h(i + 1, j + 1)) * (1 - s) +
           (h(i + 1, j) - h(i + 1, j + 1)) * (1 - u);
  }

  std::shared_ptr<const HeightMap> m_;
  LD floor_;
};

CaseResult newCase(const std::string& name) {
  return makeCase("Height fields", name, 1e-14, 1e-12);
}

}  // namespace

std::vector<CaseResult> heightFieldCases(double effort) {
  auto m = std::make_shared<HeightMap>();
  m->width = 9;
  m->depth = 7;
  for (int z = 0; z < 7; ++z)
    for (int x = 0; x < 9; ++x)
      m->values.push_back(
          static_cast<uint16_t>((x * 7919 + z * 104729 + x * z * 31) % 60000 + 2000));
  const double water = 0.15;
  const HeightField hf(m, false, water);
  const RefHeightField ref(m, water - 0.001 / 65536.0);
  const double size = 1.5;
  const int n = rayCount(1200, effort);
  std::vector<CaseResult> out;
  {
    Rng rng(2101);
    CaseResult r = newCase("9 x 7 grid with a water level: random rays");
    for (int i = 0; i < n; ++i) {
      Vec3 o = Vec3(0.5, 0.5, 0.5) + 2.0 * randomUnit(rng);
      Vec3 target(uniform(rng, 0, 1), uniform(rng, 0, 1), uniform(rng, 0, 1));
      measureRay(r, hf, ref, Ray(o, (target - o) * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r));
  }
  {
    Rng rng(2102);
    CaseResult r = newCase("edge-on in the vertical planes of grid lines (x = i / 8, z = j / 6)");
    for (int i = 0; i < n; ++i) {
      const bool alongZ = i % 2 == 0;
      const double line = alongZ ? double(rng() % 9) / 8.0 : double(rng() % 7) / 6.0;
      const double s = uniform(rng, -1, 1), y = uniform(rng, 0, 1.2);
      Vec3 o = alongZ ? Vec3(line, y, -0.5) : Vec3(-0.5, y, line);
      Vec3 d = alongZ ? Vec3(0.0, s, 1.0) : Vec3(1.0, s, 0.0);
      if (i % 4 >= 2) d = -d, o = alongZ ? Vec3(line, y, 1.5) : Vec3(1.5, y, line);
      measureRay(r, hf, ref, Ray(o, d * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r));
  }
  {
    Rng rng(2103);
    CaseResult r = newCase("edge-on in the vertical planes of the cells' diagonals");
    for (int i = 0; i < n; ++i) {
      const int k = 1 + int(rng() % 13);  // X + Z = k in grid units
      const double X0 = std::min(8.0, double(k)), Z0 = k - X0;
      const Vec3 p(X0 / 8.0, uniform(rng, 0, 1.2), Z0 / 6.0);
      const Vec3 dir(-1.0 / 8.0, uniform(rng, -0.5, 0.5), 1.0 / 6.0);
      measureRay(r, hf, ref, Ray(p - 2.0 * dir, dir * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r));
  }
  {
    Rng rng(2104);
    CaseResult r = newCase("along grid edges, 1e-16 to 1e-1 above or below");
    // Parallel to two faces and within rounding of them: where such a ray touches the
    // surface (at a vertex, entering and leaving at once) is ill-conditioned; the row
    // reports the errors, asserting the decisions only.
    r.boundRelT = 0.0;
    r.boundAngle = 0.0;
    for (int i = 0; i < n; ++i) {
      const bool alongZ = i % 2 == 0;
      const int a = int(rng() % (alongZ ? 9 : 7)), b = int(rng() % (alongZ ? 6 : 8));
      const int x0 = alongZ ? a : b, z0 = alongZ ? b : a, x1 = alongZ ? a : b + 1,
                z1 = alongZ ? b + 1 : a;
      const Vec3 p0(x0 / 8.0, m->at(x0, z0) / 65536.0, z0 / 6.0),
          p1(x1 / 8.0, m->at(x1, z1) / 65536.0, z1 / 6.0);
      const double off = (rng() % 2 ? 1 : -1) * logUniform(rng, -16, -1);
      const Vec3 d = p1 - p0;
      const Vec3 q = p0 + uniform(rng, 0, 1) * d + Vec3(0.0, off, 0.0);
      measureRay(r, hf, ref, Ray(q - 2.0 * d, d * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace lucent::accuracy
