// The mesh's BVH gives the same closest hit (t and triangle) and the same shadow answer
// as testing every triangle with the same watertight test, on closed meshes (rays through
// shared edges and vertices) and on triangle soups.
#include "random_items.h"

#include "primitives/triangle_mesh.h"
#include "primitives/watertight.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::testing;

namespace {

// A displaced, tessellated sphere: closed, outward oriented, with a vertex at each pole.
std::shared_ptr<MeshData> bumpySphere(int rings, int segments, Vec3 c, double r) {
  auto m = std::make_shared<MeshData>();
  auto point = [&](double th, double ph) {
    double bump = 1.0 + 0.08 * std::sin(7 * th) * std::cos(5 * ph);
    return c +
           r * bump * Vec3(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
  };
  m->positions.push_back(point(0, 0));
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j)
      m->positions.push_back(point(kPi * i / rings, 2 * kPi * j / segments));
  m->positions.push_back(point(kPi, 0));
  uint32_t south = uint32_t(m->positions.size() - 1);
  auto id = [&](int i, int j) { return uint32_t(1 + (i - 1) * segments + (j % segments)); };
  for (int j = 0; j < segments; ++j) {
    m->triangles.push_back({0, id(1, j + 1), id(1, j)});
    m->triangles.push_back({south, id(rings - 1, j), id(rings - 1, j + 1)});
  }
  for (int i = 1; i + 1 < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      m->triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j)});
      m->triangles.push_back({id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)});
    }
  m->closed = true;
  return m;
}

struct Brute {
  double t = kInf;
  int64_t tri = -1;
};

Brute bruteForce(const MeshData& m, const Ray& ray) {
  ShearedRay sr(ray);
  Brute b;
  for (size_t i = 0; i < m.triangles.size(); ++i) {
    const auto& tri = m.triangles[i];
    const Vec3 &p0 = m.positions[tri[0]], &p1 = m.positions[tri[1]], &p2 = m.positions[tri[2]];
    if (isDegenerateTriangle(p0, p1, p2)) continue;
    TriangleIntersection ti;
    if (intersectTriangle(sr, p0, p1, p2, ti) && ray.tmin < ti.t && ti.t < ray.tmax && ti.t < b.t)
      b = {ti.t, int64_t(i)};
  }
  return b;
}

void requireSameAsBruteForce(const std::shared_ptr<MeshData>& data, const std::vector<Ray>& rays) {
  TriangleMesh mesh(data, false);
  REQUIRE(mesh.bvh().itemCount() > 0);
  size_t hits = 0;
  for (Ray ray : rays) {
    Brute want = bruteForce(*data, ray);
    Hit got;
    bool found = mesh.intersect(ray, got);
    REQUIRE(found == (want.tri >= 0));
    if (!found) continue;
    ++hits;
    REQUIRE(got.t == want.t);
    if (int64_t(got.part) != want.tri) {  // a tie on a shared edge or vertex
      Brute again = bruteForce(*data, Ray(ray.o, ray.d, ray.tmin, std::nextafter(got.t, kInf)));
      REQUIRE(again.t == got.t);
    }
    // Shadow rays: blocked just past the hit, free just before it.
    ray.tmax = std::nextafter(got.t, kInf);
    REQUIRE(mesh.occluded(ray));
    ray.tmax = got.t;
    REQUIRE_FALSE(mesh.occluded(ray));
  }
  CHECK(hits > rays.size() / 10);
  CHECK(hits < rays.size());
}

}  // namespace

TEST_CASE("mesh BVH finds the brute-force closest triangle on a closed bumpy sphere",
          "[bvh][mesh]") {
  std::mt19937_64 rng(31);
  auto data = bumpySphere(40, 80, Vec3(0.1, -0.2, 0.3), 1.5);
  requireSameAsBruteForce(data, randomRays(rng, 10000, 2.0));
  // Rays aimed at the vertices: they cross shared edges and vertices exactly.
  std::vector<Ray> atVertices;
  for (size_t i = 0; i < data->positions.size(); i += 3) {
    Vec3 o = randomVec(rng, -4.0, 4.0);
    atVertices.emplace_back(o, data->positions[i] - o);
  }
  requireSameAsBruteForce(data, atVertices);
}

TEST_CASE("mesh BVH finds the brute-force closest triangle in a random soup", "[bvh][mesh]") {
  std::mt19937_64 rng(32);
  auto data = std::make_shared<MeshData>();
  std::uniform_real_distribution<double> size(0.01, 0.4);
  for (int i = 0; i < 4000; ++i) {
    Vec3 c = randomVec(rng, -3.0, 3.0);
    double s = size(rng);
    for (int k = 0; k < 3; ++k) data->positions.push_back(c + s * randomVec(rng, -1.0, 1.0));
    uint32_t b = uint32_t(3 * i);
    data->triangles.push_back({b, b + 1, b + 2});
  }
  // Zero-area triangles (a repeated vertex, three collinear points) are never hit.
  data->positions.push_back(Vec3(0, 0, 0));
  data->positions.push_back(Vec3(1, 1, 1));
  data->positions.push_back(Vec3(2, 2, 2));
  uint32_t n = uint32_t(data->positions.size());
  data->triangles.push_back({n - 3, n - 2, n - 1});
  data->triangles.push_back({n - 3, n - 3, n - 2});
  TriangleMesh mesh(data, false);
  CHECK(mesh.bvh().itemCount() == 4000);
  requireSameAsBruteForce(data, randomRays(rng, 10000, 3.0));
}
