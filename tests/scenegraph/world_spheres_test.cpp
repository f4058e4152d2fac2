// The world keeps spheres under similarity transforms in world space (sphere_image.h):
// it must give the same closest hit as testing every Instance through its own
// object-space test, and secondary rays leaving such spheres must not re-hit them.
#include "../primitives/random_items.h"
#include "tests/test_effort.h"
#include "world_helpers.h"

#include "primitives/offset.h"
#include "scenegraph/world.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <sstream>

using namespace lucent;
using namespace lucent::testing;
using lucent::test::effortCount;

namespace {

std::unique_ptr<Node> sphereNode(const Vec3& center, double radius, const Mat4& parentFromNode) {
  auto n = std::make_unique<Node>();
  n->kind = NodeKind::Shape;
  n->element = "sphere";
  n->shape = SphereSpec{center, radius};
  n->parentFromNode = parentFromNode;
  return n;
}

Vec3 randomUnitVec(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  for (;;) {
    Vec3 v(g(rng), g(rng), g(rng));
    if (glm::length(v) > 1e-3) return glm::normalize(v);
  }
}

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// How a sphere is placed: by its centre alone, by a similarity (translation, rotation,
// uniform scale, sometimes mirrored), or by a non-uniform scale (stays an Instance).
enum class Placing { Identity, Similarity, NonUniform };

// A field of `count` spheres inside a cube of half-size `extent` around `at`, each placed
// as `placing(i)` says; every shape element goes through the real makeShape (Sphere).
template <class Placing_>
Scene sphereField(std::mt19937_64& rng, int count, const Vec3& at, double extent,
                  Placing_&& placing) {
  Scene scene;
  for (int i = 0; i < count; ++i) {
    Vec3 c = at + Vec3(uniform(rng, -extent, extent), uniform(rng, -extent, extent),
                       uniform(rng, -extent, extent));
    double r = extent * uniform(rng, 0.005, 0.05);
    switch (placing(i)) {
      case Placing::Identity:
        scene.root->children.push_back(sphereNode(c, r, Mat4(1.0)));
        break;
      case Placing::Similarity: {
        // The object-space sphere sits off the object's origin, so the rotation and
        // the scale move its centre as well.
        double s = std::exp(uniform(rng, -2.0, 2.0));
        Vec3 local = randomUnitVec(rng) * (r / s);
        Mat4 m = glm::translate(Mat4(1.0), c) *
                 glm::rotate(Mat4(1.0), uniform(rng, -kPi, kPi), randomUnitVec(rng)) *
                 glm::scale(Mat4(1.0), Vec3(i % 5 == 0 ? -s : s, s, s)) *
                 glm::translate(Mat4(1.0), -local);
        scene.root->children.push_back(sphereNode(local, r / s, m));
        break;
      }
      case Placing::NonUniform: {
        Mat4 m = glm::translate(Mat4(1.0), c) *
                 glm::rotate(Mat4(1.0), uniform(rng, -kPi, kPi), randomUnitVec(rng)) *
                 glm::scale(Mat4(1.0), Vec3(1.0, uniform(rng, 0.3, 0.9), 1.0));
        scene.root->children.push_back(sphereNode(Vec3(0.0), r, m));
        break;
      }
    }
  }
  return scene;
}

// The cosine between the ray and the normal of `shape` where the ray meets it at t.
double cosineAt(const Shape& shape, const Ray& ray, double t) {
  Hit h;
  h.t = t;
  h.shape = &shape;
  SurfaceInfo s = shape.surface(ray, h);
  return std::abs(glm::dot(glm::normalize(ray.d), s.ng));
}

struct Comparison {
  size_t hits = 0, exact = 0, grazingOrTie = 0;
  double worstRelative = 0.0;  // |Δt|·|d|·cos / magnitude, over the compared hits
  std::string example;
};

// World against brute force. Same hit or miss, same object, and t within the rounding
// bound: both distances solve the same sphere up to `error` (sphere_image.h, at most a
// few hundred units of rounding of the coordinates' magnitude) and their own rounding,
// so |Δt|·|d| <= 1e-14·magnitude / cos θ, θ the angle to the normal (the largest seen
// is about 6e-16, a few units of rounding of the magnitude). Rays within about
// 1e-4 of grazing (cos θ < 1e-4), and ties between two spheres (their distances closer
// than that bound), may legitimately pick the other answer; they are counted and must
// stay rare.
Comparison compare(const World& world, const std::vector<Ray>& rays, double magnitude) {
  Comparison c;
  for (const Ray& ray : rays) {
    Hit want = bruteForce(world, ray), got;
    bool found = world.intersect(ray, got);
    if (found) ++c.hits;
    const double len = glm::length(ray.d);
    if (found == want.found() && (!found || got.shape == want.shape)) {
      if (!found) continue;
      if (got.t == want.t) ++c.exact;
      double cosine = cosineAt(*want.shape, ray, want.t);
      if (cosine < 1e-4) {
        ++c.grazingOrTie;
        continue;
      }
      double rel = std::abs(got.t - want.t) * len * cosine / magnitude;
      c.worstRelative = std::max(c.worstRelative, rel);
      continue;
    }
    // A different answer: only a tie or a grazing ray may give one.
    bool excused = false;
    if (found && want.found()) {
      excused = std::abs(got.t - want.t) * len <= 1e-14 * magnitude / 1e-4 ||
                cosineAt(*want.shape, ray, want.t) < 1e-4 ||
                cosineAt(*got.shape, ray, got.t) < 1e-4;
    } else {
      const Hit& h = found ? got : want;
      excused = cosineAt(*h.shape, ray, h.t) < 1e-4;
    }
    if (excused) {
      ++c.grazingOrTie;
    } else if (c.example.empty()) {
      std::ostringstream s;
      s.precision(17);
      s << "ray o=(" << ray.o.x << "," << ray.o.y << "," << ray.o.z << ") d=(" << ray.d.x << ","
        << ray.d.y << "," << ray.d.z << "): world " << (found ? got.t : -1.0) << ", brute force "
        << (want.found() ? want.t : -1.0);
      c.example = s.str();
    }
  }
  return c;
}

}  // namespace

TEST_CASE(
    "spheres under similarity transforms, kept in world space, give the brute-force closest hit",
    "[bvh][world][sphere]") {
  struct Setting {
    Vec3 at;
    double extent;
  };
  const Setting settings[] = {{Vec3(0.0), 10.0}, {Vec3(1e5, -3e4, 2e4), 10.0}, {Vec3(0.0), 1e-3}};
  for (const Setting& st : settings) {
    std::mt19937_64 rng(71);
    Scene scene = sphereField(rng, 1500, st.at, st.extent, [](int i) {
      return i % 2 ? Placing::Similarity : Placing::Identity;
    });
    World world(scene);
    REQUIRE(world.inlineSphereCount() == 1500);
    std::vector<Ray> rays = randomRays(rng, effortCount(100000), st.extent);
    for (Ray& r : rays) r.o += st.at;
    double magnitude = glm::length(st.at) + 3.0 * st.extent;
    Comparison c = compare(world, rays, magnitude);
    INFO("at " << st.at.x << " extent " << st.extent << ": " << c.hits << " hits, " << c.exact
               << " exactly equal, " << c.grazingOrTie << " grazing or tied, worst "
               << c.worstRelative << "; " << c.example);
    CHECK(c.example.empty());
    CHECK(c.hits > rays.size() / 10);
    CHECK(c.grazingOrTie < 10);
    CHECK(c.worstRelative <= 1e-14);
  }
}

TEST_CASE("spheres placed by their centre give exactly the hits of their Instances",
          "[bvh][world][sphere]") {
  std::mt19937_64 rng(72);
  Scene scene =
      sphereField(rng, 2000, Vec3(-40.0, 3.0, 7.0), 10.0, [](int) { return Placing::Identity; });
  World world(scene);
  REQUIRE(world.inlineSphereCount() == 2000);
  size_t hits = 0;
  for (Ray ray : randomRays(rng, effortCount(100000), 10.0)) {
    ray.o += Vec3(-40.0, 3.0, 7.0);
    Hit want = bruteForce(world, ray), got;
    REQUIRE(world.intersect(ray, got) == want.found());
    REQUIRE(world.occluded(ray) == want.found());
    if (!want.found()) continue;
    ++hits;
    REQUIRE(got.t == want.t);
    REQUIRE(got.shape == want.shape);
    REQUIRE(got.part == want.part);
    REQUIRE(got.b1 == want.b1);
    REQUIRE(got.b2 == want.b2);
    REQUIRE(got.flip == want.flip);
    // The surface is the Instance's, so it is the same too.
    SurfaceInfo a = got.shape->surface(ray, got), b = want.shape->surface(ray, want);
    REQUIRE(a.p == b.p);
    REQUIRE(a.pError == b.pError);
    REQUIRE(world.occluded(Ray(ray.o, ray.d, ray.tmin, got.t * (1.0 + 1e-9))));
    REQUIRE_FALSE(world.occluded(Ray(ray.o, ray.d, ray.tmin, got.t * (1.0 - 1e-9))));
  }
  CHECK(hits > size_t(effortCount(10000)));
}

TEST_CASE("spheres under non-uniform scales stay Instances, beside spheres kept in world space",
          "[bvh][world][sphere]") {
  std::mt19937_64 rng(73);
  Scene scene = sphereField(rng, 1200, Vec3(0.0), 10.0, [](int i) {
    return i % 3 == 0 ? Placing::NonUniform
                      : (i % 3 == 1 ? Placing::Similarity : Placing::Identity);
  });
  World world(scene);
  CHECK(world.inlineSphereCount() == 800);
  CHECK(world.bvh().itemCount() == 1200);
  std::vector<Ray> rays = randomRays(rng, effortCount(100000), 10.0);
  Comparison c = compare(world, rays, 30.0);
  INFO(c.hits << " hits, " << c.exact << " exactly equal, " << c.grazingOrTie
              << " grazing or tied, worst " << c.worstRelative << "; " << c.example);
  CHECK(c.example.empty());
  CHECK(c.grazingOrTie < 10);
  CHECK(c.worstRelative <= 1e-14);
  // Hits on the squashed spheres come from their Instances' own test: exactly equal.
  size_t squashed = 0;
  for (const Ray& ray : rays) {
    Hit want = bruteForce(world, ray), got;
    if (!world.intersect(ray, got) || !want.found()) continue;
    const Instance* inst = world.leaf(got).instance;
    REQUIRE(got.shape == inst);
    if (inst->transform().isIdentity()) continue;
    Mat3 l(inst->transform().worldFromObject());
    if (std::abs(glm::length(l[0]) - glm::length(l[1])) < 1e-6) continue;  // a similarity
    ++squashed;
    REQUIRE(got.shape == want.shape);
    REQUIRE(got.t == want.t);
  }
  CHECK(squashed > 1000);
}

namespace {

struct Leaving {
  int primaries = 0, secondaries = 0, rehits = 0;
  std::string example;
};

// `count` random hits on the world's spheres, found by the world, and from each two rays
// leaving the surface (offsetRayOrigin with the Instance's pError), one outwards and one
// inwards, 3 degrees or more clear of grazing. Outwards a sphere is never met again;
// inwards only across its chord, far from the origin of the ray.
Leaving leaveSpheres(const World& world, std::mt19937_64& rng, int count) {
  Leaving out;
  for (int tries = 0; out.primaries < count && tries < 20 * count; ++tries) {
    const Instance* target = world.leaves()[size_t(tries) % world.leaves().size()].instance;
    AABB box = target->bounds();
    Vec3 aim =
        box.center() +
        0.5 * box.extent() * Vec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    Vec3 o = aim + 3.0 * glm::length(box.extent()) * randomUnitVec(rng);
    Ray primary(o, (aim - o) * uniform(rng, 0.25, 4.0));
    Hit h;
    if (!world.intersect(primary, h)) continue;
    const Instance& leaf = *world.leaf(h).instance;
    REQUIRE(h.shape == &leaf);
    SurfaceInfo si = leaf.surface(primary, h);
    if (std::abs(glm::dot(glm::normalize(primary.d), si.ng)) < 0.05) continue;
    ++out.primaries;
    double size = glm::length(leaf.bounds().extent());
    for (double side : {1.0, -1.0}) {
      Vec3 w = randomUnitVec(rng);
      if (glm::dot(w, si.ng) * side < 0.0) w = -w;
      if (glm::dot(w, si.ng) * side < 0.05) continue;
      ++out.secondaries;
      Ray ray(offsetRayOrigin(si.p, si.pError, si.ng, w), w * uniform(rng, 0.5, 2.0));
      Hit again;
      if (!world.intersect(ray, again) || again.shape != &leaf) continue;
      double dist = again.t * glm::length(ray.d);
      if (side < 0.0 && dist >= 1e-6 * size) continue;
      ++out.rehits;
      if (out.example.empty()) {
        std::ostringstream s;
        s.precision(17);
        s << "re-hit at distance " << dist << " from p=(" << si.p.x << "," << si.p.y << ","
          << si.p.z << "), " << (side > 0 ? "outwards" : "inwards");
        out.example = s.str();
      }
    }
  }
  return out;
}

}  // namespace

TEST_CASE("secondary rays never re-hit a sphere kept in world space (rotated, scaled, far away)",
          "[bvh][world][sphere][offset]") {
  const Vec3 ats[] = {Vec3(0.0), Vec3(3e5, -1e5, 2e5), Vec3(-7e3, 2e3, 1e3)};
  for (const Vec3& at : ats) {
    std::mt19937_64 rng(74);
    Scene scene = sphereField(rng, 300, at, 1.0, [](int) { return Placing::Similarity; });
    World world(scene);
    REQUIRE(world.inlineSphereCount() == 300);
    Leaving l = leaveSpheres(world, rng, 20000);
    INFO("at " << at.x << ": " << l.primaries << " hits, " << l.secondaries << " secondary rays; "
               << l.example);
    CHECK(l.primaries == 20000);
    CHECK(l.rehits == 0);
  }
}

TEST_CASE("secondary rays never re-hit a sphere whose transform is only nearly a similarity",
          "[bvh][world][sphere][offset]") {
  // A scale of 1 + 6e-15 along y: still accepted as a similarity (sphere_image.h), but
  // the world copy differs from the exact image, a slightly stretched ellipsoid, by about
  // 2e-15 to 4e-15 of the radius, more than the sphere's own pError at the origin. Only
  // the copy's error, added to pError (Instance::widenSurfaceError), keeps the rays'
  // origins outside the copy.
  for (double stretch : {6e-15, -6e-15}) {
    Scene scene;
    Mat4 m = glm::scale(Mat4(1.0), Vec3(1.0, 1.0 + stretch, 1.0));
    scene.root->children.push_back(sphereNode(Vec3(0.0), 1.0, m));
    scene.root->children.push_back(sphereNode(Vec3(0.0), 1.0, glm::rotate(m, 0.5, Vec3(1, 2, 3))));
    // Two objects, so both go into the BVH (a lone object is tested directly).
    scene.root->children[1]->parentFromNode =
        glm::translate(Mat4(1.0), Vec3(5.0, 0.0, 0.0)) * scene.root->children[1]->parentFromNode;
    World world(scene);
    REQUIRE(world.inlineSphereCount() == 2);
    std::mt19937_64 rng(75);
    Leaving l = leaveSpheres(world, rng, 20000);
    INFO("stretch " << stretch << ": " << l.primaries << " hits, " << l.secondaries
                    << " secondary rays; " << l.example);
    CHECK(l.primaries == 20000);
    CHECK(l.rehits == 0);
  }
}
