// POV-Ray 3.7's slope pattern (pattern.cpp's slope_pattern, parstxtr.cpp's weights) against
// its formula worked out independently at chosen normals and points: the slope is
// 1 - angle(normal, direction) / pi, stretched by its range, mixed with the altitude by the
// vectors' lengths, wrapped into [0, 1) with 1 kept just below 1.
#include "render/patterns/pattern_surface.h"
#include "render/patterns/pattern_value.h"

#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace lucent;

namespace {

PatternSpec slopeSpec(const Vec3& direction) {
  PatternSpec s;
  s.type = PatternType::slope;
  s.slope.direction = direction;
  return s;
}

double valueOn(const PatternSpec& s, const Vec3& normal, const Vec3& p,
               const Vec3& world = Vec3(0.0)) {
  PatternSurface surface{glm::normalize(normal), world};
  const PatternSurfaceScope scope(true, surface);
  return patternValue(s, p);
}

// The angle between two vectors in degrees, from their cross and dot products.
double degreesBetween(const Vec3& a, const Vec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180.0 / kPi;
}

}  // namespace

TEST_CASE("slope is the angle of the normal to the direction, 0 to 180 degrees as 1 to 0",
          "[pattern][slope]") {
  const PatternSpec s = slopeSpec(Vec3(0.0, 1.0, 0.0));
  CHECK(valueOn(s, Vec3(1, 0, 0), Vec3(0.0)) == Approx(0.5).margin(1e-15));
  CHECK(valueOn(s, Vec3(0, -1, 0), Vec3(0.0)) == Approx(0.0).margin(1e-15));
  // Along the direction: exactly 1 in POV-Ray's formula, kept at 1 - 1e-10 so a map's top
  // entry shows instead of wrapping to its bottom.
  CHECK(valueOn(s, Vec3(0, 1, 0), Vec3(0.0)) == 1.0 - 1e-10);
  for (const Vec3 n : {Vec3(0.3, 0.8, -0.2), Vec3(-0.7, -0.1, 0.4), Vec3(0.0, 1.0, 1.0)}) {
    INFO(n.x << " " << n.y << " " << n.z);
    const double expected = 1.0 - degreesBetween(glm::normalize(n), Vec3(0, 1, 0)) / 180.0;
    CHECK(valueOn(s, n, Vec3(5.0, -3.0, 2.0)) == Approx(expected).margin(1e-14));
  }
  // The direction's length alone does not count, its sign does.
  CHECK(valueOn(slopeSpec(Vec3(0, -3, 0)), Vec3(0.3, 0.8, -0.2), Vec3(0.0)) ==
        Approx(degreesBetween(glm::normalize(Vec3(0.3, 0.8, -0.2)), Vec3(0, 1, 0)) / 180.0)
            .margin(1e-14));
}

TEST_CASE("slope without a surface is 0 as POV-Ray's", "[pattern][slope]") {
  CHECK(patternValue(slopeSpec(Vec3(0, 1, 0)), Vec3(1.0, 2.0, 3.0)) == 0.0);
}

TEST_CASE("slope's range stretches low..high over 0..1 and wraps what falls outside",
          "[pattern][slope]") {
  PatternSpec s = slopeSpec(Vec3(0, 1, 0));
  s.slope.low = 0.5;
  s.slope.high = 0.75;
  const Vec3 n(0.2, 0.9, 0.1);  // slope value in (0.75, 1): stretched above 1, wrapped
  const double raw = 1.0 - degreesBetween(glm::normalize(n), Vec3(0, 1, 0)) / 180.0;
  const double stretched = (raw - 0.5) / 0.25;
  REQUIRE(stretched > 1.0);
  CHECK(valueOn(s, n, Vec3(0.0)) == Approx(stretched - 1.0).margin(1e-13));
  // Below low: negative, wrapped to 1 + its fraction.
  const Vec3 m(0.3, -1.0, 0.0);
  const double belowM =
      (1.0 - degreesBetween(glm::normalize(m), Vec3(0, 1, 0)) / 180.0 - 0.5) / 0.25;
  REQUIRE(belowM < -1.0);
  CHECK(valueOn(s, m, Vec3(0.0)) == Approx(belowM - std::floor(belowM)).margin(1e-13));
  // Equal nonzero ends: ignored (POV-Ray warns "Zero slope range").
  s.slope.low = s.slope.high = 0.3;
  CHECK(valueOn(s, n, Vec3(0.0)) == Approx(raw).margin(1e-14));
}

TEST_CASE("slope's altitude mixes the height in by the vectors' lengths", "[pattern][slope]") {
  // slopemt_37.pov's Vege2Rock: slope { -y*3, 0, 0.5 altitude y, 0.005, 0.400 }.
  PatternSpec s = slopeSpec(Vec3(0, -3, 0));
  s.slope.high = 0.5;
  s.slope.altitude = Vec3(0, 1, 0);
  s.slope.altitudeLow = 0.005;
  s.slope.altitudeHigh = 0.4;
  const Vec3 n(0.1, 0.95, 0.2), p(0.3, 0.1, -0.7);
  const double slope = degreesBetween(glm::normalize(n), Vec3(0, 1, 0)) / 180.0 / 0.5;
  const double height = (p.y - 0.005) / 0.395;
  CHECK(valueOn(s, n, p) == Approx(0.75 * slope + 0.25 * height).margin(1e-13));
  // The altitude is taken in pattern space (the point after the placement).
  s.placement.patternFromObject = glm::scale(Mat4(1.0), Vec3(1.0, 0.5, 1.0));
  const double half = (0.5 * p.y - 0.005) / 0.395;
  CHECK(valueOn(s, n, p) == Approx(0.75 * slope + 0.25 * half).margin(1e-13));
  // A tilted altitude: the height along its unit vector.
  s.placement = {};
  s.slope.altitude = Vec3(1, 1, 0);
  const double along = (p.x + p.y) / std::sqrt(2.0);
  const double sw = 3.0 / (3.0 + std::sqrt(2.0));
  CHECK(valueOn(s, n, p) == Approx(sw * slope + (1 - sw) * (along - 0.005) / 0.395).margin(1e-13));
}

TEST_CASE("slope with point_at measures the normal against the way to the point",
          "[pattern][slope]") {
  PatternSpec s = slopeSpec(Vec3(0, 10, 0));
  s.slope.pointAt = true;
  const Vec3 world(3.0, 2.0, -1.0), n(0.0, 0.0, 1.0);
  const Vec3 towards = Vec3(0, 10, 0) - world;
  const double expected = 1.0 - degreesBetween(n, glm::normalize(towards)) / 180.0;
  CHECK(valueOn(s, n, Vec3(7.0), world) == Approx(expected).margin(1e-14));
}

TEST_CASE("only a scene with a slope opens the surface scope", "[pattern][slope]") {
  Material plain;
  PatternTexture t;
  t.pattern.type = PatternType::bozo;
  plain.texture = t;
  CHECK_FALSE(usesPatternSurface(plain));
  Material mapped;
  PatternTexture sl;
  sl.pattern = slopeSpec(Vec3(0, 1, 0));
  MaterialMapEntry entry;
  entry.material.texture = sl;
  mapped.mapEntries.push_back(entry);
  CHECK(usesPatternSurface(mapped));
  Material nested;
  PatternTexture outer;
  outer.pattern.type = PatternType::gradient;
  TextureMapEntry e;
  e.texture = sl;
  outer.pigments.push_back(e);
  nested.layers.push_back(Material{});
  nested.layers.back().texture = outer;
  CHECK(usesPatternSurface(nested));
}

TEST_CASE("a bent normal is what later slopes at the hit read, until the hit's scope closes",
          "[pattern][slope]") {
  const PatternSpec s = slopeSpec(Vec3(0, 1, 0));
  PatternSurface outer{Vec3(0, 1, 0), Vec3(0.0)};
  const PatternSurfaceScope scope(true, outer);
  CHECK(patternValue(s, Vec3(0.0)) == 1.0 - 1e-10);
  {
    // A reflected ray's hit: its own surface, then the first one's again.
    PatternSurface inner{Vec3(1, 0, 0), Vec3(0.0)};
    const PatternSurfaceScope nested(true, inner);
    CHECK(patternValue(s, Vec3(0.0)) == Approx(0.5).margin(1e-15));
  }
  CHECK(patternValue(s, Vec3(0.0)) == 1.0 - 1e-10);
  // POV-Ray's PNormal: a normal pattern bent it, the slopes after it read the bent one.
  bendPatternSurface(Vec3(0, -1, 0));
  CHECK(patternValue(s, Vec3(0.0)) == Approx(0.0).margin(1e-15));
  // An inactive scope changes nothing.
  PatternSurface unused{Vec3(1, 0, 0), Vec3(0.0)};
  const PatternSurfaceScope inactive(false, unused);
  CHECK(currentPatternSurface() == &outer);
}
