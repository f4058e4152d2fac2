#include "shape_checks.h"

#include "csg/csg_node.h"
#include "csg/inverted.h"
#include "primitives/box.h"
#include "primitives/height_field.h"
#include "primitives/transform.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <vector>

using namespace lucent;
using namespace lucent::test;

namespace {

using LD = long double;

// The solid's floor for a water level: POV-Ray's offset of 0.001 / 65536 below it.
double floorOf(double water) { return water - 0.001 / 65536.0; }

std::shared_ptr<const HeightMap> grid(int w, int d, std::vector<uint16_t> v) {
  auto m = std::make_shared<HeightMap>();
  m->width = w;
  m->depth = d;
  m->values = std::move(v);
  return m;
}

// A 3 x 3 map: a ridge along z at x = 0.5, one raised corner.
std::shared_ptr<const HeightMap> ridge() {
  return grid(3, 3,
              {10000, 40000, 10000,  //
               10000, 40000, 10000,  //
               10000, 40000, 60000});
}

// Pseudo-random 9 x 7 heights.
std::shared_ptr<const HeightMap> rough() {
  std::vector<uint16_t> v;
  for (int z = 0; z < 7; ++z)
    for (int x = 0; x < 9; ++x)
      v.push_back(static_cast<uint16_t>((x * 7919 + z * 104729 + x * z * 31) % 60000 + 2000));
  return grid(9, 7, v);
}

struct Tri {
  LD p[3][3];  // (x, y, z) in object space
};

// The map's triangles, as POV-Ray splits the cells (the diagonal from (i+1, j) to (i, j+1)).
std::vector<Tri> triangles(const HeightMap& m) {
  std::vector<Tri> out;
  const LD sx = m.width - 1, sz = m.depth - 1;
  auto P = [&](int x, int z, LD* p) {
    p[0] = x / sx;
    p[1] = m.at(x, z) / 65536.0L;
    p[2] = z / sz;
  };
  for (int j = 0; j + 1 < m.depth; ++j)
    for (int i = 0; i + 1 < m.width; ++i) {
      Tri a, b;
      P(i, j, a.p[0]), P(i + 1, j, a.p[1]), P(i, j + 1, a.p[2]);
      P(i + 1, j + 1, b.p[0]), P(i, j + 1, b.p[1]), P(i + 1, j, b.p[2]);
      out.push_back(a);
      out.push_back(b);
    }
  return out;
}

// Ray-triangle by Cramer's rule in long double; t or NaN.
LD rayTriangle(const Ray& r, const Tri& t) {
  LD o[3] = {r.o.x, r.o.y, r.o.z}, d[3] = {r.d.x, r.d.y, r.d.z};
  LD e1[3], e2[3], s[3];
  for (int k = 0; k < 3; ++k)
    e1[k] = t.p[1][k] - t.p[0][k], e2[k] = t.p[2][k] - t.p[0][k], s[k] = o[k] - t.p[0][k];
  auto cross = [](const LD* a, const LD* b, LD* c) {
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
  };
  auto dot = [](const LD* a, const LD* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  LD p[3], q[3];
  cross(d, e2, p);
  const LD det = dot(e1, p);
  if (det == 0) return NAN;
  const LD u = dot(s, p) / det;
  cross(s, e1, q);
  const LD v = dot(d, q) / det;
  if (u < 0 || v < 0 || u + v > 1) return NAN;
  return dot(e2, q) / det;
}

// The surface height in long double, from the triangle over (x, z).
LD heightRef(const HeightMap& m, LD x, LD z) {
  const LD X = x * (m.width - 1), Z = z * (m.depth - 1);
  int i = std::min(static_cast<int>(std::floor(X)), m.width - 2),
      j = std::min(static_cast<int>(std::floor(Z)), m.depth - 2);
  i = std::max(i, 0), j = std::max(j, 0);
  const LD s = X - i, u = Z - j;
  auto h = [&](int a, int b) { return m.at(a, b) / 65536.0L; };
  if (s + u <= 1) return h(i, j) + (h(i + 1, j) - h(i, j)) * s + (h(i, j + 1) - h(i, j)) * u;
  return h(i + 1, j + 1) + (h(i, j + 1) - h(i + 1, j + 1)) * (1 - s) +
         (h(i + 1, j) - h(i + 1, j + 1)) * (1 - u);
}

// The first boundary point of the solid {(x, z) in the square, water <= y < height} after
// tmin: every triangle hit at or above the water, every wall and floor point under the surface.
LD firstHitRef(const HeightMap& m, LD water, const Ray& r) {
  LD best = INFINITY;
  for (const Tri& t : triangles(m)) {
    const LD th = rayTriangle(r, t);
    if (!(th > r.tmin && th < r.tmax)) continue;
    if (r.o.y + th * LD(r.d.y) < water) continue;
    best = std::min(best, th);
  }
  auto consider = [&](LD th) {
    if (!(th > r.tmin && th < r.tmax)) return;
    const LD x = r.o.x + th * LD(r.d.x), y = r.o.y + th * LD(r.d.y), z = r.o.z + th * LD(r.d.z);
    const LD eps = 1e-15L;
    if (x < -eps || x > 1 + eps || z < -eps || z > 1 + eps || y < water - eps) return;
    // Strictly under the surface (where the solid is thinner than rounding, it has no wall).
    if (y < heightRef(m, std::clamp<LD>(x, 0, 1), std::clamp<LD>(z, 0, 1)) - 1e-12L)
      best = std::min(best, th);
  };
  for (int a : {0, 2})
    if (r.d[a] != 0)
      for (LD plane : {0.0L, 1.0L}) consider((plane - r.o[a]) / LD(r.d[a]));
  if (r.d.y != 0) consider((water - r.o.y) / LD(r.d.y));
  return best;
}

void checkAgainstReference(const HeightField& hf, const HeightMap& m, double water, uint64_t seed,
                           int rays, int* hitsOut) {
  Rng rng(seed);
  int hits = 0, wrong = 0;
  for (int i = 0; i < rays; ++i) {
    Ray ray = randomRayAt(rng, hf.bounds());
    const LD ref = firstHitRef(m, water, ray);
    Hit h;
    const bool got = hf.intersect(ray, h);
    if (std::isinf(ref)) {
      if (got) ++wrong;
      continue;
    }
    ++hits;
    if (!got || std::abs(h.t - ref) > 1e-11L * (1 + std::abs(ref))) {
      ++wrong;
      if (wrong < 4)
        UNSCOPED_INFO("ray " << i << " t " << (got ? h.t : -1.0) << " reference " << double(ref));
    }
  }
  CHECK(wrong == 0);
  *hitsOut = hits;
}

}  // namespace

TEST_CASE("height field: hits are exact ray-triangle intersections on small maps",
          "[primitives][height-field]") {
  int hits = 0;
  HeightField a(ridge(), false, 0.0);
  checkAgainstReference(a, *ridge(), floorOf(0.0), 11, 4000, &hits);
  CHECK(hits > 1500);
  HeightField b(rough(), false, 0.0);
  checkAgainstReference(b, *rough(), floorOf(0.0), 12, 4000, &hits);
  CHECK(hits > 1500);
  HeightField c(rough(), true, 0.45);
  checkAgainstReference(c, *rough(), floorOf(0.45), 13, 4000, &hits);
  CHECK(hits > 1000);
}

TEST_CASE("height field: the grid's layout is POV-Ray's", "[primitives][height-field]") {
  HeightField hf(ridge(), false, 0.0);
  // Grid point (x, z) at (x / (W - 1), h / 65536, z / (H - 1)).
  CHECK(hf.height(0.5, 0.0) == 40000 / 65536.0);
  CHECK(hf.height(1.0, 1.0) == 60000 / 65536.0);
  CHECK(hf.height(0.0, 0.5) == 10000 / 65536.0);
  // Cell (1, 1) is split along the diagonal from (2, 1) to (1, 2): at its centre the
  // height is the mean of those two corners, not of (1, 1) and (2, 2).
  CHECK(hf.height(0.75, 0.75) == Approx((40000 + 10000) / 2 / 65536.0).epsilon(1e-14));
  // A ray straight down onto a grid point.
  Hit h;
  REQUIRE(hf.intersect(Ray(Vec3(1.0, 2.0, 1.0), Vec3(0.0, -1.0, 0.0)), h));
  CHECK(h.t == Approx(2.0 - 60000 / 65536.0).epsilon(1e-15));
  CHECK(hf.bounds().hi.y == 60000 / 65536.0);
  CHECK(hf.bounds().lo.y == floorOf(0.0));
}

TEST_CASE("height field: a horizontal ray crosses walls and the ridge in order",
          "[primitives][height-field]") {
  HeightField hf(ridge(), false, 0.0);
  // At y = 0.3 (19660.8 raw) and z = 0.25 the section rises from 10000 / 65536 at x = 0 to
  // 40000 / 65536 at x = 0.5 and falls back to 10000 / 65536 at x = 1 (the raised corner is
  // outside this row of cells' lower triangles... check both halves of the section).
  const double y = 0.3;
  Ray ray(Vec3(-1.0, y, 0.1), Vec3(1.0, 0.0, 0.0));
  CrossingList cl;
  hf.crossings(ray, cl);
  REQUIRE(cl.items.size() == 2);
  CHECK_FALSE(cl.startsInside);
  // Enters the ridge's side where the height reaches y, leaves on the other side.
  const double h0 = 10000 / 65536.0, h1 = 40000 / 65536.0;
  const double xIn = 0.5 * (y - h0) / (h1 - h0);
  CHECK(cl.items[0].entering);
  CHECK(cl.items[0].hit.t == Approx(1.0 + xIn).epsilon(1e-14));
  CHECK_FALSE(cl.items[1].entering);
  CHECK(cl.items[1].hit.t == Approx(1.0 + 1.0 - xIn).epsilon(1e-14));
  // Lower, at y = 0.1 (under the edges): in through the wall at x = 0, out at x = 1.
  CrossingList low;
  hf.crossings(Ray(Vec3(-1.0, 0.1, 0.1), Vec3(1.0, 0.0, 0.0)), low);
  REQUIRE(low.items.size() == 2);
  CHECK(low.items[0].hit.t == 1.0);
  CHECK(low.items[0].hit.part == HeightField::kWallX0);
  CHECK(low.items[1].hit.t == 2.0);
  CHECK(low.items[1].hit.part == HeightField::kWallX1);
  SurfaceInfo si = hf.surface(Ray(Vec3(-1.0, 0.1, 0.1), Vec3(1.0, 0.0, 0.0)), low.items[0].hit);
  CHECK(si.ng == Vec3(-1.0, 0.0, 0.0));
}

TEST_CASE("height field: an open field has neither walls nor floor, as POV-Ray's",
          "[primitives][height-field]") {
  HeightField hf(ridge(), false, 0.0, true);
  CHECK_FALSE(hf.isSolid());
  // Under the edges (y = 0.1): the closed field's walls at x = 0 and 1; the open one has
  // nothing there, and above them the ridge's two sides, each entering.
  Hit h;
  CHECK_FALSE(hf.intersect(Ray(Vec3(-1.0, 0.1, 0.1), Vec3(1.0, 0.0, 0.0)), h));
  CrossingList low;
  hf.crossings(Ray(Vec3(-1.0, 0.1, 0.1), Vec3(1.0, 0.0, 0.0)), low);
  CHECK(low.items.empty());
  const double y = 0.3, h0 = 10000 / 65536.0, h1 = 40000 / 65536.0;
  const double xIn = 0.5 * (y - h0) / (h1 - h0);
  CrossingList cl;
  hf.crossings(Ray(Vec3(-1.0, y, 0.1), Vec3(1.0, 0.0, 0.0)), cl);
  REQUIRE(cl.items.size() == 2);
  CHECK(cl.items[0].hit.t == Approx(1.0 + xIn).epsilon(1e-14));
  CHECK(cl.items[1].hit.t == Approx(2.0 - xIn).epsilon(1e-14));
  CHECK(cl.items[0].entering);
  CHECK(cl.items[1].entering);
  // From below: the underside of the surface, not the floor.
  REQUIRE(hf.intersect(Ray(Vec3(0.5, -1.0, 0.5), Vec3(0.0, 1.0, 0.0)), h));
  CHECK(h.t == Approx(1.0 + h1).epsilon(1e-14));
  HeightField closed(ridge(), false, 0.0);
  REQUIRE(closed.intersect(Ray(Vec3(0.5, -1.0, 0.5), Vec3(0.0, 1.0, 0.0)), h));
  CHECK(h.part == HeightField::kFloor);
}

TEST_CASE("height field: a field flat at its highest point is hit wherever a ray comes down",
          "[primitives][height-field]") {
  // The box's top is the surface itself: rounding may put a ray's entry just below it,
  // which must still be the surface (open or closed), never a miss or the box's top face.
  const double level = 13107 / 65536.0;
  for (bool open : {true, false}) {
    HeightField hf(grid(4, 4, std::vector<uint16_t>(16, 13107)), false, 0.0, open);
    int tried = 0;
    for (int a = 0; a < 40; ++a)
      for (int b = 0; b < 40; ++b) {
        const Vec3 target(0.0123 + a * 0.0244, level, 0.0071 + b * 0.0247);
        const Vec3 from(target.x - 0.7 + 0.013 * b, 2.0 + 0.01 * a, target.z - 1.3 + 0.02 * a);
        const Ray ray(from, target - from);
        Hit h;
        INFO("open " << open << ", target " << target.x << " " << target.z);
        REQUIRE(hf.intersect(ray, h));
        CHECK(h.t == Approx(1.0).epsilon(1e-12));
        CHECK(h.part < HeightField::kWallX0);
        const SurfaceInfo si = hf.surface(ray, h);
        CHECK(si.ng.y == Approx(1.0));
        ++tried;
      }
    CHECK(tried == 1600);
  }
}

TEST_CASE("height field: inside is below the surface, above the water, within the square",
          "[primitives][height-field]") {
  HeightField hf(rough(), false, 0.2);
  Rng rng(5);
  for (int i = 0; i < 5000; ++i) {
    const Vec3 p(uniform(rng, -0.2, 1.2), uniform(rng, -0.1, 1.1), uniform(rng, -0.2, 1.2));
    const bool square = p.x >= 0 && p.x <= 1 && p.z >= 0 && p.z <= 1;
    const bool expected =
        square && p.y >= floorOf(0.2) && p.y < double(heightRef(*rough(), p.x, p.z));
    if (square && std::abs(p.y - double(heightRef(*rough(), p.x, p.z))) < 1e-12) continue;
    CHECK(hf.inside(p) == expected);
  }
}

TEST_CASE("height field: the water level removes what lies below it",
          "[primitives][height-field]") {
  // Heights 10000 at the edges, 40000 along the ridge: a water level at 0.3 leaves the ridge.
  HeightField hf(ridge(), false, 0.3);
  Hit h;
  // Straight down at x = 0.1: the surface there is below the water; nothing is hit.
  CHECK_FALSE(hf.intersect(Ray(Vec3(0.1, 2.0, 0.5), Vec3(0.0, -1.0, 0.0)), h));
  // On the ridge: the surface.
  REQUIRE(hf.intersect(Ray(Vec3(0.5, 2.0, 0.5), Vec3(0.0, -1.0, 0.0)), h));
  CHECK(h.t == Approx(2.0 - 40000 / 65536.0).epsilon(1e-14));
  // From below, on the ridge: the floor at the water level.
  REQUIRE(hf.intersect(Ray(Vec3(0.5, -1.0, 0.5), Vec3(0.0, 1.0, 0.0)), h));
  CHECK(h.t == Approx(1.0 + floorOf(0.3)).epsilon(1e-14));
  CHECK(h.part == HeightField::kFloor);
  CHECK_THROWS_AS(HeightField(ridge(), false, 60000 / 65536.0), std::invalid_argument);
}

TEST_CASE("height field: flat and smooth normals", "[primitives][height-field]") {
  // A tilted plane h = 8000 + 6000 x + 3000 z (raw) over a 4 x 4 grid: every face normal and
  // every vertex normal is the plane's (up to POV-Ray's 16-bit quantisation).
  std::vector<uint16_t> v;
  for (int z = 0; z < 4; ++z)
    for (int x = 0; x < 4; ++x) v.push_back(static_cast<uint16_t>(8000 + 6000 * x + 3000 * z));
  auto m = grid(4, 4, v);
  const Vec3 plane = glm::normalize(Vec3(-6000.0 * 3 / 65536.0, 1.0, -3000.0 * 3 / 65536.0));
  // POV-Ray stores the vertex normal of its raw space (x, h, z) as shorts, 32767 n
  // truncated: here n.y = 1 / 6708.2 becomes 4 / 32767 (not 4.88), which tilts the
  // smooth normal by 0.06 radians. Lucent keeps that, to shade as POV-Ray does.
  const Vec3 raw = glm::normalize(Vec3(-6000.0, 1.0, -3000.0));
  const Vec3 q(static_cast<short>(32767 * raw.x), static_cast<short>(32767 * raw.y),
               static_cast<short>(32767 * raw.z));
  REQUIRE(q.y == 4.0);
  const Vec3 quantised = glm::normalize(Vec3(q.x * 3, q.y * 65536.0, q.z * 3));
  HeightField flat(m, false, 0.0), smooth(m, true, 0.0);
  Rng rng(9);
  int n = 0;
  for (int i = 0; i < 500; ++i) {
    Ray ray(Vec3(uniform(rng, 0.05, 0.95), 2.0, uniform(rng, 0.05, 0.95)),
            Vec3(uniform(rng, -0.1, 0.1), -1.0, uniform(rng, -0.1, 0.1)));
    Hit h;
    if (!flat.intersect(ray, h)) continue;
    ++n;
    SurfaceInfo a = flat.surface(ray, h);
    CHECK(glm::length(a.ng - plane) < 1e-12);
    Hit hs;
    REQUIRE(smooth.intersect(ray, hs));
    SurfaceInfo b = smooth.surface(ray, hs);
    CHECK(glm::length(b.ns - quantised) < 1e-12);
    CHECK(glm::length(b.ng - plane) < 1e-12);
  }
  CHECK(n > 400);
  // On a ridge, a smooth normal varies across a cell and is the vertex normal at a vertex.
  HeightField r(ridge(), true, 0.0);
  Hit h1;
  Ray down(Vec3(0.5, 2.0, 0.5), Vec3(0.0, -1.0, 0.0));
  REQUIRE(r.intersect(down, h1));
  const Vec3 top = r.surface(down, h1).ns;
  CHECK(top.y > 0.99);  // the ridge's crest: the two slopes' normals cancel in x
  Ray side(Vec3(0.25, 2.0, 0.5), Vec3(0.0, -1.0, 0.0));
  REQUIRE(r.intersect(side, h1));
  const Vec3 s = r.surface(side, h1).ns;
  const Vec3 f = r.surface(side, h1).ng;
  CHECK(s.x < 0.0);
  CHECK(s.y > f.y);  // between the crest's and the slope's
}

TEST_CASE("height field: edge-on rays along grid lines and diagonals",
          "[primitives][height-field]") {
  auto m = rough();
  HeightField hf(m, false, 0.0);
  // Rays in the vertical planes of the grid lines x = i / 8 and z = j / 6, and along the
  // cells' diagonals, compared with the reference.
  int checked = 0;
  for (int i = 0; i <= 8; ++i)
    for (double slope : {-0.7, -0.2, 0.0}) {
      Ray ray(Vec3(i / 8.0, 1.2, -0.5), Vec3(0.0, slope - 0.1, 1.0));
      const LD ref = firstHitRef(*m, floorOf(0.0), ray);
      Hit h;
      const bool got = hf.intersect(ray, h);
      REQUIRE(got == !std::isinf(ref));
      if (got) CHECK(std::abs(h.t - ref) <= 1e-12L * (1 + ref));
      ++checked;
    }
  for (int j = 0; j <= 6; ++j) {
    Ray ray(Vec3(-0.5, 1.0, j / 6.0), Vec3(1.0, -0.6, 0.0));
    const LD ref = firstHitRef(*m, floorOf(0.0), ray);
    Hit h;
    REQUIRE(hf.intersect(ray, h) == !std::isinf(ref));
    if (!std::isinf(ref)) CHECK(std::abs(h.t - ref) <= 1e-12L * (1 + ref));
    ++checked;
  }
  // Along the diagonal X + Z = k of the grid (x = X / 8, z = Z / 6).
  for (int k = 1; k < 14; ++k) {
    const Vec3 o(k / 8.0 + 0.25 / 8.0, 1.5, -0.25 / 6.0);
    Ray ray(o, Vec3(-1.0 / 8.0, -0.3, 1.0 / 6.0));
    const LD ref = firstHitRef(*m, floorOf(0.0), ray);
    Hit h;
    REQUIRE(hf.intersect(ray, h) == !std::isinf(ref));
    if (!std::isinf(ref)) CHECK(std::abs(h.t - ref) <= 1e-12L * (1 + ref));
    CrossingList cl;
    hf.crossings(Ray(ray.o, ray.d, -kInf, kInf), cl);
    CHECK(cl.items.size() % 2 == 0);
    for (size_t c = 0; c < cl.items.size(); ++c) CHECK(cl.items[c].entering == (c % 2 == 0));
    ++checked;
  }
  CHECK(checked == 27 + 7 + 13);
}

TEST_CASE("height field: inverse inside a CSG difference is the intersection",
          "[primitives][height-field][csg]") {
  auto m = rough();
  auto box = [] { return std::make_unique<Box>(Vec3(0.2, 0.1, 0.2), Vec3(0.8, 0.9, 0.8)); };
  // box - inverse(hf) = box ∩ hf
  std::vector<std::unique_ptr<Shape>> a;
  a.push_back(box());
  a.push_back(std::make_unique<Inverted>(std::make_unique<HeightField>(m, false, 0.0)));
  CsgNode diff(CsgOp::Difference, std::move(a));
  std::vector<std::unique_ptr<Shape>> b;
  b.push_back(box());
  b.push_back(std::make_unique<HeightField>(m, false, 0.0));
  CsgNode both(CsgOp::Intersection, std::move(b));
  Rng rng(31);
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    Ray ray = randomRayAt(rng, AABB(Vec3(0.2, 0.1, 0.2), Vec3(0.8, 0.9, 0.8)));
    CrossingList x, y;
    diff.crossings(ray, x);
    both.crossings(ray, y);
    REQUIRE(x.items.size() == y.items.size());
    for (size_t k = 0; k < x.items.size(); ++k) {
      CHECK(x.items[k].hit.t == y.items[k].hit.t);
      CHECK(x.items[k].entering == y.items[k].entering);
    }
    Hit h;
    if (diff.intersect(ray, h)) {
      ++hits;
      const Vec3 p = ray.at(h.t);
      // The hit lies on the box or on the surface, within the other.
      const bool onSurface = std::abs(p.y - double(heightRef(*m, p.x, p.z))) < 1e-9;
      CHECK((onSurface || (p.y < double(heightRef(*m, p.x, p.z)) + 1e-9)));
    }
  }
  CHECK(hits > 500);
}

TEST_CASE("height field: camera rays over a 5 x 5 map with a zero border",
          "[primitives][height-field]") {
  const int img[5][5] = {{0, 0, 0, 0, 0},
                         {0, 90, 200, 40, 0},
                         {0, 250, 120, 180, 0},
                         {0, 30, 160, 60, 0},
                         {0, 0, 0, 0, 0}};
  std::vector<uint16_t> v;
  for (int z = 0; z < 5; ++z)
    for (int x = 0; x < 5; ++x) v.push_back(static_cast<uint16_t>(img[4 - z][x] * 257));
  auto m = grid(5, 5, v);
  HeightField hf(m, false, 0.0);
  const Vec3 eye(0.5, 2.0, -1.2);
  int hits = 0, wrong = 0;
  for (int a = 0; a <= 200; ++a)
    for (int b = 0; b <= 200; ++b) {
      const Vec3 target(a / 200.0, 0.05, b / 200.0);
      Ray ray(eye, target - eye);
      const LD ref = firstHitRef(*m, floorOf(0.0), ray);
      Hit h;
      const bool got = hf.intersect(ray, h);
      if (!std::isinf(ref)) ++hits;
      if (got != !std::isinf(ref) || (got && std::abs(h.t - ref) > 1e-12L * (1 + ref))) {
        if (++wrong < 5)
          UNSCOPED_INFO("target " << a << " " << b << " got " << got << " " << h.t << " ref "
                                  << double(ref));
      }
    }
  CHECK(wrong == 0);
  CHECK(hits > 20000);
}

TEST_CASE("height field: smooth normals are blended in world space, as POV-Ray blends them",
          "[primitives][height-field]") {
  HeightField hf(rough(), true, 0.0);
  Mat4 m(1.0);
  m[0][0] = 2.0;
  m[1][1] = 0.5;
  m[2][2] = 3.0;
  const Transform t = *Transform::fromMatrix(m);
  // Straight down onto a point inside cell (2, 3) of the 9 x 7 grid.
  const double X = 2.3, Z = 3.6;
  Ray ray(Vec3(X / 8.0, 2.0, Z / 6.0), Vec3(0.0, -1.0, 0.0));
  Hit h;
  REQUIRE(hf.intersect(ray, h));
  Vec3 ns;
  REQUIRE(hf.worldShadingNormal(ray, h, t, ns));
  // The corners' normals (smoothNormal at a grid point is that point's normal), each taken
  // to world space, then blended bilinearly.
  auto corner = [&](int x, int z) {
    Ray r(Vec3(x / 8.0, 2.0, z / 6.0), Vec3(0.0, -1.0, 0.0));
    Hit c;
    REQUIRE(hf.intersect(r, c));
    return t.normalToWorld(hf.surface(r, c).ns);
  };
  const double x = X - 2, z = Z - 3;
  const Vec3 expected = glm::normalize((1 - z) * ((1 - x) * corner(2, 3) + x * corner(3, 3)) +
                                       z * ((1 - x) * corner(2, 4) + x * corner(3, 4)));
  CHECK(glm::length(ns - expected) < 1e-12);
  // Not the object-space blend taken to world space.
  CHECK(glm::length(ns - t.normalToWorld(hf.surface(ray, h).ns)) > 1e-4);
  // A flat field has no world-space blend.
  HeightField flat(rough(), false, 0.0);
  REQUIRE(flat.intersect(ray, h));
  CHECK_FALSE(flat.worldShadingNormal(ray, h, t, ns));
}

TEST_CASE("height field: an all-zero map is refused, as the parser refuses it by name",
          "[primitives][height-field]") {
  // A black image leaves nothing above water level 0; the scene parser says so at the
  // water-level attribute (tests/bad/cases.txt), and the shape itself refuses rather than
  // build a solid of zero thickness.
  CHECK_THROWS_AS(HeightField(grid(4, 4, std::vector<uint16_t>(16, 0)), false, 0.0),
                  std::invalid_argument);
  CHECK_THROWS_AS(HeightField(grid(4, 4, std::vector<uint16_t>(16, 0)), true, 0.0),
                  std::invalid_argument);
  std::vector<uint16_t> one(16, 0);
  one[5] = 1;
  CHECK_NOTHROW(HeightField(grid(4, 4, one), false, 0.0));
}
