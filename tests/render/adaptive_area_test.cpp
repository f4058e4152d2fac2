// The adaptive area-light sampler on synthetic shadows: which grid points it traces and
// what it averages them to (POV-Ray's recursive quadrant means).
#include "render/adaptive_area.h"

#include <catch2/catch.hpp>

#include <functional>
#include <set>
#include <utility>
#include <vector>

using namespace lucent;

namespace {

// A synthetic shadow: the transmittance at each grid point, and the points asked for.
struct Shadow {
  explicit Shadow(std::function<float(int, int)> v) : value(std::move(v)) {}
  std::function<float(int, int)> value;
  std::set<std::pair<int, int>> traced;
  int rays = 0;

  Color estimate(AdaptiveAreaSampler& sampler, int nu, int nv, int levels,
                 const Color& radiance = Color(1.0f)) {
    return sampler.average(nu, nv, levels, radiance, [&](int a, int b) {
      ++rays;
      traced.insert({a, b});
      return Color(value(a, b));
    });
  }
};

// POV-Ray's 1-D weights of a fully subdivided axis of n points (2 to 5 measured by
// rendering with POV-Ray 3.7, as povray/pov_lights.cpp notes; 6 and 9 by its halving rule).
std::vector<double> fullWeights(int n) {
  switch (n) {
    case 2:
      return {0.5, 0.5};
    case 3:
      return {0.25, 0.5, 0.25};
    case 4:
      return {0.25, 0.25, 0.25, 0.25};
    case 5:
      return {1 / 8.0, 2 / 8.0, 2 / 8.0, 2 / 8.0, 1 / 8.0};
    case 6:
      return {1 / 8.0, 2 / 8.0, 1 / 8.0, 1 / 8.0, 2 / 8.0, 1 / 8.0};
    case 9:
      return {1 / 16.0, 2 / 16.0, 2 / 16.0, 2 / 16.0, 2 / 16.0,
              2 / 16.0, 2 / 16.0, 2 / 16.0, 1 / 16.0};
  }
  return {};
}

}  // namespace

TEST_CASE("adaptive area light: a fully visible light costs its 4 corners", "[render][adaptive]") {
  AdaptiveAreaSampler sampler;
  Shadow lit{[](int, int) { return 1.0f; }};
  CHECK(lit.estimate(sampler, 9, 9, 0) == Color(1.0f));
  CHECK(lit.rays == 4);
  CHECK(lit.traced == std::set<std::pair<int, int>>{{0, 0}, {8, 0}, {0, 8}, {8, 8}});

  // Each forced level splits every rectangle once more: 3 x 3, then 5 x 5 points.
  Shadow one{[](int, int) { return 1.0f; }};
  CHECK(one.estimate(sampler, 9, 9, 1) == Color(1.0f));
  CHECK(one.rays == 9);
  Shadow two{[](int, int) { return 1.0f; }};
  two.estimate(sampler, 9, 9, 2);
  CHECK(two.rays == 25);
  // A fully shadowed light as well.
  Shadow dark{[](int, int) { return 0.0f; }};
  CHECK(dark.estimate(sampler, 17, 5, 0) == Color(0.0f));
  CHECK(dark.rays == 4);
}

TEST_CASE("adaptive area light: an edge across the light is subdivided only near the edge",
          "[render][adaptive]") {
  // Columns a < 3 are blocked, a >= 3 see the light: the edge lies between 2 and 3.
  AdaptiveAreaSampler sampler;
  Shadow edge{[](int a, int) { return a < 3 ? 0.0f : 1.0f; }};
  Color c = edge.estimate(sampler, 9, 9, 0);
  // Columns 2, 3 and 4 bracket the edge at every level and are traced in full; column 0 at
  // the rows of the blocked rectangles it bounds (every 2nd), column 8 every 4th.
  std::set<std::pair<int, int>> expected;
  for (int b = 0; b <= 8; ++b)
    for (int a : {2, 3, 4}) expected.insert({a, b});
  for (int b = 0; b <= 8; b += 2) expected.insert({0, b});
  for (int b = 0; b <= 8; b += 4) expected.insert({8, b});
  CHECK(edge.traced == expected);
  CHECK(edge.rays == 35);  // each point once, of 81
  // Wherever it stopped the shadow is constant, so the estimate is the full grid's
  // trapezoid mean: (2·5 + 1)/16 of the columns see the light (the plain mean is 6/9).
  CHECK(c.r == Approx(11.0 / 16.0).epsilon(1e-6));
}

TEST_CASE("adaptive area light: subdivided to the full grid it is POV-Ray's weighted mean",
          "[render][adaptive]") {
  AdaptiveAreaSampler sampler;
  for (auto [nu, nv] : {std::pair{2, 2}, {3, 3}, {4, 4}, {5, 9}, {9, 3}, {2, 5}, {6, 4}}) {
    CAPTURE(nu, nv);
    // Values all different, so that any wrong weight shows.
    auto value = [nu = nu](int a, int b) { return 0.01f * float(1 + a + nu * b * b); };
    Shadow s{value};
    Color c = s.estimate(sampler, nu, nv, 20);
    CHECK(s.rays == nu * nv);
    std::vector<double> wu = fullWeights(nu), wv = fullWeights(nv);
    double expected = 0.0;
    for (int b = 0; b < nv; ++b)
      for (int a = 0; a < nu; ++a) expected += wu[a] * wv[b] * value(a, b);
    CHECK(c.r == Approx(expected).epsilon(1e-5));
  }
}

TEST_CASE("adaptive area light: corners differ when the light they pass differs by more than 0.1",
          "[render][adaptive]") {
  // A grey step of 0.02 over three channels: 0.06 of white light, 0.12 of a light twice as bright.
  AdaptiveAreaSampler sampler;
  auto step = [](int a, int) { return a < 4 ? 1.0f : 0.98f; };
  Shadow dim{step};
  dim.estimate(sampler, 9, 9, 0);
  CHECK(dim.rays == 4);
  Shadow bright{step};
  bright.estimate(sampler, 9, 9, 0, Color(2.0f));
  CHECK(bright.rays > 4);
  // One coloured channel alone: 0.15 in red is enough.
  Shadow red{[](int a, int) { return a < 4 ? 1.0f : 0.85f; }};
  red.estimate(sampler, 9, 9, 0, Color(1.0f, 0.0f, 0.0f));
  CHECK(red.rays > 4);
}

TEST_CASE("adaptive area light: each estimate traces afresh", "[render][adaptive]") {
  // The sampler keeps its grid memo between estimates; an old value must never be reused.
  AdaptiveAreaSampler sampler;
  Shadow first{[](int, int) { return 1.0f; }};
  CHECK(first.estimate(sampler, 5, 5, 3) == Color(1.0f));
  Shadow second{[](int, int) { return 0.25f; }};
  CHECK(second.estimate(sampler, 5, 5, 3) == Color(0.25f));
  CHECK(second.rays == 25);
  // A larger grid after a smaller one.
  Shadow larger{[](int a, int) { return a == 16 ? 0.0f : 1.0f; }};
  larger.estimate(sampler, 17, 17, 0);
  CHECK(larger.traced.count({16, 16}) == 1);
  CHECK(larger.traced.count({15, 16}) == 1);  // the edge at the last column is resolved
}
