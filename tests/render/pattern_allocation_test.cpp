// Pattern evaluation allocates nothing per ray (docs/patterns-noise.md): every pattern's value, its
// colour through a colour map, the block patterns, the normal perturbations and the sky are
// evaluated while a counting operator new (this file replaces the global one for the test
// executable, counting only while a Counting scope is open on the calling thread) watches.
#include "render/patterns/block_pattern.h"
#include "render/patterns/color_map.h"
#include "render/patterns/normal_perturbation.h"
#include "render/patterns/pattern_value.h"
#include "render/sky_color.h"

#include <catch2/catch.hpp>

// AddressSanitizer replaces operator new itself (and checks that what it allocated is freed
// by its delete), so under it this file replaces nothing and has no test: the plain build
// runs it.
#if !defined(__SANITIZE_ADDRESS__)

#include <cmath>
#include <cstdlib>
#include <new>

namespace {

thread_local bool counting = false;
thread_local long allocations = 0;

struct Counting {
  Counting() { allocations = 0, counting = true; }
  ~Counting() { counting = false; }
};

void* allocate(std::size_t n) {
  if (counting) ++allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}

}  // namespace

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

using namespace lucent;

TEST_CASE("pattern, colour-map, block, normal and sky evaluation allocate nothing",
          "[render][pattern]") {
  ColorMap map;
  map.entries = {
      {0.0, Color(0.1f)}, {0.4, Color(1.0f, 0.2f, 0.1f)}, {1.0, Color(0.0f, 0.3f, 1.0f)}};
  std::vector<PatternSpec> specs;
  for (int t = 0; t < kPatternTypeCount; ++t) {
    PatternSpec s;
    s.type = static_cast<PatternType>(t);
    s.placement.turbulence = Vec3(0.4);
    s.frequency = 2.0;
    specs.push_back(s);
  }
  HexagonSpec hexagon;
  BrickSpec brick;
  Sky sky;
  PatternTexture skyPattern;
  skyPattern.pattern.type = PatternType::gradient;
  skyPattern.map = map;
  sky.layers = {skyPattern};
  // One evaluation of each first: tables built on first use (noise, crackle) are built once
  // per process, not per ray.
  auto evaluateAll = [&](const Vec3& p) {
    double sum = 0.0;
    for (const PatternSpec& s : specs) {
      sum += patternValue(s, p);
      sum += patternColor(s, map, p).g;
      NormalSpec n;
      n.pattern = s;
      sum += perturbNormal(n, p, Vec3(0, 1, 0)).x;
    }
    sum += hexagonColor(hexagon, p).r + brickColor(brick, p).r;
    sum += skyColor(sky, glm::normalize(p + Vec3(0.1, 2.0, 0.0)), Color(0.0f)).b;
    return sum;
  };
  double warm = evaluateAll(Vec3(0.3, 0.2, 0.1));
  double sum = 0.0;
  {
    Counting scope;
    for (int i = 0; i < 200; ++i)
      sum += evaluateAll(Vec3(0.37 * i - 30.0, 0.11 * i, 5.0 - 0.23 * i));
    CHECK(allocations == 0);
  }
  CHECK(std::isfinite(sum + warm));
  // The counter counts: a vector that grows does allocate.
  {
    Counting scope;
    std::vector<int> grows(100);
    CHECK(allocations == 1);
  }
}

#endif  // !__SANITIZE_ADDRESS__
