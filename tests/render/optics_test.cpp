// Snell, Fresnel, Beer–Lambert, lights: the formulas against closed forms.
#include "render/optics.h"
#include "render/light_sample.h"

#include <catch2/catch.hpp>

using namespace lucent;

TEST_CASE("refraction through a slab leaves parallel, displaced by t sin(i-r)/cos r",
          "[render][optics]") {
  const double n = 1.5, thickness = 0.8;
  for (double degrees : {5.0, 30.0, 60.0, 85.0}) {
    const double i = radians(degrees);
    const Vec3 d(std::sin(i), 0.0, -std::cos(i));
    const Vec3 up(0, 0, 1);  // slab faces are z = 0 and z = -thickness, normals facing +z
    Vec3 inside, out;
    REQUIRE(refract(d, up, 1.0 / n, inside));
    // Snell: sin i = n sin r.
    const double r = std::asin(std::sin(i) / n);
    CHECK(std::asin(inside.x) == Approx(r).epsilon(1e-12));
    // Leaving through the bottom face: the normal facing the ray is +z again.
    REQUIRE(refract(inside, up, n, out));
    CHECK(out.x == Approx(d.x).epsilon(1e-12));
    CHECK(out.z == Approx(d.z).epsilon(1e-12));
    // Follow the path: enter at the origin, leave at z = -thickness.
    const Vec3 exitPoint = inside * (thickness / -inside.z);
    // Perpendicular distance between the exit ray's line and the incident line.
    const Vec3 offset = exitPoint - glm::dot(exitPoint, d) * d;
    CHECK(glm::length(offset) == Approx(thickness * std::sin(i - r) / std::cos(r)).epsilon(1e-12));
  }
}

TEST_CASE("total internal reflection beyond the critical angle", "[render][optics]") {
  const double n = 1.5;
  const double critical = std::asin(1.0 / n);  // 41.81 degrees
  const Vec3 n_(0, 0, 1);
  auto leaving = [](double angle) { return Vec3(std::sin(angle), 0.0, -std::cos(angle)); };
  Vec3 t;
  CHECK(refract(leaving(critical - 1e-6), n_, n, t));
  CHECK(t.z == Approx(-std::cos(radians(90.0))).margin(2e-3));  // grazing exit
  CHECK_FALSE(refract(leaving(critical + 1e-6), n_, n, t));
  CHECK_FALSE(refract(leaving(radians(60.0)), n_, n, t));
  CHECK(fresnelDielectric(std::cos(critical + 1e-6), n, 1.0) == 1.0);
  CHECK(fresnelDielectric(std::cos(radians(60.0)), n, 1.0) == 1.0);
}

TEST_CASE("Fresnel at normal incidence is ((n-1)/(n+1))^2 from either side", "[render][optics]") {
  for (double n : {1.33, 1.5, 2.4}) {
    double expected = std::pow((n - 1.0) / (n + 1.0), 2.0);
    CHECK(fresnelDielectric(1.0, 1.0, n) == Approx(expected).epsilon(1e-14));
    CHECK(fresnelDielectric(1.0, n, 1.0) == Approx(expected).epsilon(1e-14));
  }
  CHECK(fresnelDielectric(0.7, 1.5, 1.5) == 0.0);          // no interface, no reflection
  CHECK(fresnelDielectric(0.0, 1.0, 1.5) == Approx(1.0));  // grazing
  // Reciprocity: the reflectance is the same for the incident and the refracted angle
  // seen from the other side.
  double i = radians(40.0), r = std::asin(std::sin(i) / 1.5);
  CHECK(fresnelDielectric(std::cos(i), 1.0, 1.5) ==
        Approx(fresnelDielectric(std::cos(r), 1.5, 1.0)).epsilon(1e-12));
  // Glass 1.5 at 45 degrees: Rs = 0.0920134, and Rp = Rs^2 at 45 degrees (Abeles 1950).
  const double rs = 0.0920133630;
  CHECK(fresnelDielectric(std::cos(radians(45.0)), 1.0, 1.5) ==
        Approx(0.5 * (rs + rs * rs)).epsilon(1e-9));
}

TEST_CASE("Beer-Lambert transmittance is exp(-a d) per channel", "[render][optics]") {
  Color t = beerLambert(Color(0.5f, 1.0f, 0.0f), 2.0);
  CHECK(t.r == Approx(std::exp(-1.0)).epsilon(1e-7));
  CHECK(t.g == Approx(std::exp(-2.0)).epsilon(1e-7));
  CHECK(t.b == 1.0f);
  CHECK(beerLambert(Color(0.1f, 0.0f, 0.0f), kInf) == Color(0.0f, 1.0f, 1.0f));
}

TEST_CASE("distance attenuation min(1, 1/(a + b r + c r^2)) is clamped at 1", "[render][light]") {
  CHECK(distanceAttenuation(Vec3(1, 0, 0), 123.0) == 1.0);
  CHECK(distanceAttenuation(Vec3(0.25, 0, 0), 3.0) == 1.0);  // 4 clamped to 1
  CHECK(distanceAttenuation(Vec3(0, 0, 1), 0.5) == 1.0);     // 4 clamped to 1
  CHECK(distanceAttenuation(Vec3(1, 1, 1), 2.0) == Approx(1.0 / 7.0));
  CHECK(distanceAttenuation(Vec3(0, 0, 0.5), 4.0) == Approx(1.0 / 8.0));
}

TEST_CASE("spot light: full inside inner, zero beyond angle, smoothstep between",
          "[render][light]") {
  Light spot;
  spot.type = LightType::Spot;
  spot.angle = 30.0;
  spot.inner = 10.0;
  CHECK(spotFactor(spot, std::cos(radians(5.0))) == 1.0);
  CHECK(spotFactor(spot, std::cos(radians(10.0))) == 1.0);
  CHECK(spotFactor(spot, std::cos(radians(30.0))) == 0.0);
  CHECK(spotFactor(spot, std::cos(radians(45.0))) == 0.0);
  double c = std::cos(radians(20.0));
  double u = (c - std::cos(radians(30.0))) / (std::cos(radians(10.0)) - std::cos(radians(30.0)));
  CHECK(spotFactor(spot, c) == Approx((3.0 - 2.0 * u) * u * u).epsilon(1e-14));
  // Without an inner cone the edge is hard.
  spot.inner = spot.angle;
  CHECK(spotFactor(spot, std::cos(radians(29.9))) == 1.0);
  CHECK(spotFactor(spot, std::cos(radians(30.1))) == 0.0);
}

TEST_CASE("spot light tightness: POV-Ray's cos^tightness times the cone", "[render][light]") {
  Light spot;
  spot.type = LightType::Spot;
  spot.angle = 30.0;
  spot.inner = 10.0;
  spot.tightness = 4.0;
  // Hand-computed: cos^4 5° = 0.984865 (inside inner); at 20°, u = 0.620186 of the
  // smoothstep (0.676808) times cos^4 20° (0.779728) = 0.527726; none beyond the angle.
  CHECK(spotFactor(spot, std::cos(radians(0.0))) == 1.0);
  CHECK(spotFactor(spot, std::cos(radians(5.0))) == Approx(0.984865).epsilon(1e-6));
  CHECK(spotFactor(spot, std::cos(radians(20.0))) == Approx(0.527726).epsilon(1e-6));
  CHECK(spotFactor(spot, std::cos(radians(31.0))) == 0.0);
}

TEST_CASE("POV-Ray's fade 2/(1 + (r/fd)^fp) replaces the attenuation", "[render][light]") {
  CHECK(povFade(0.0, 2.0, 3.0) == 2.0);
  CHECK(povFade(1.0, 2.0, 3.0) == Approx(16.0 / 9.0));  // 2/(1 + 1/8)
  CHECK(povFade(2.0, 2.0, 3.0) == 1.0);
  CHECK(povFade(4.0, 2.0, 3.0) == Approx(2.0 / 9.0));  // 2/(1 + 8)
  CHECK(povFade(8.0, 2.0, 0.5) == Approx(2.0 / 3.0));  // 2/(1 + 2)
  Light l;
  l.attenuation = Vec3(1.0, 0.0, 1.0);
  CHECK(lightDistanceFactor(l, 1.0) == 0.5);  // the attenuation without a fade
  l.attenuation = Vec3(1.0, 0.0, 0.0);
  l.fadeDistance = 2.0;
  l.fadePower = 3.0;
  CHECK(lightDistanceFactor(l, 1.0) == Approx(16.0 / 9.0));
  l.position = Vec3(0.0, 5.0, 0.0);
  CHECK(lightIncidence(l, Vec3(0.0, 1.0, 0.0)).radiance.g == Approx(2.0 / 9.0));
}

TEST_CASE("area light samples form a grid that includes the rectangle's edges", "[render][light]") {
  Light area;
  area.type = LightType::Area;
  area.position = Vec3(1, 5, 0);
  area.u = Vec3(2, 0, 0);
  area.v = Vec3(0, 0, 4);
  area.samplesU = 3;
  area.samplesV = 2;
  REQUIRE(shadowSampleCount(area) == 6);
  CHECK(lightSamplePoint(area, 0, Vec2(0.5)) == Vec3(0, 5, -2));
  CHECK(lightSamplePoint(area, 1, Vec2(0.5)) == Vec3(1, 5, -2));
  CHECK(lightSamplePoint(area, 2, Vec2(0.5)) == Vec3(2, 5, -2));
  CHECK(lightSamplePoint(area, 5, Vec2(0.5)) == Vec3(2, 5, 2));
  // Jitter stays inside the rectangle.
  area.jitter = true;
  Vec3 corner = lightSamplePoint(area, 0, Vec2(0.0, 0.0));
  CHECK(corner == Vec3(0, 5, -2));
  Vec3 moved = lightSamplePoint(area, 4, Vec2(0.9, 0.1));  // grid point (1, 1)
  CHECK(moved.x == Approx(1.4));                           // +0.4 of a step of 1
  CHECK(moved.z == Approx(0.4));                           // -0.4 of a step of 4
  moved = lightSamplePoint(area, 4, Vec2(0.9, 0.9));
  CHECK(moved.z == Approx(2.0));  // clamped to the edge
}

TEST_CASE("a spot-shaped area light's cone is seen from its centre, for every sample",
          "[render][light]") {
  Light area;
  area.type = LightType::Area;
  area.cone = true;
  area.position = Vec3(0, 4, 0);
  area.direction = Vec3(0, -1, 0);
  area.u = Vec3(2, 0, 0);
  area.v = Vec3(0, 0, 2);
  area.angle = 20.0;
  area.inner = 10.0;
  REQUIRE(area.hasCone());
  // Straight below the centre: full light (attenuation 1 by default).
  CHECK(lightIncidence(area, Vec3(0, 0, 0)).radiance == Color(1.0f));
  // 4·tan 15° off the axis: between inner and angle, the smoothstep of the centre's angle,
  // though a corner sample at x = 1 sees the point at a smaller angle.
  const Vec3 p(4.0 * std::tan(radians(15.0)), 0, 0);
  const double u = (std::cos(radians(15.0)) - std::cos(radians(20.0))) /
                   (std::cos(radians(10.0)) - std::cos(radians(20.0)));
  CHECK(lightIncidence(area, p).radiance.r == Approx((3.0 - 2.0 * u) * u * u).epsilon(1e-6));
  // Outside the centre's cone: dark, though the rectangle's edge at x = 1 is above.
  CHECK(lightIncidence(area, Vec3(4.0 * std::tan(radians(21.0)), 0, 0)).radiance == Color(0.0f));
  // The same rectangle without a cone lights every point.
  area.cone = false;
  CHECK(lightIncidence(area, Vec3(4.0 * std::tan(radians(21.0)), 0, 0)).radiance == Color(1.0f));
}

TEST_CASE("reflectAboveSurface turns mirror rays below the surface back as POV-Ray",
          "[render][optics]") {
  const Vec3 raw(0, 0, -1);  // the wall's own normal, facing the viewer
  const Vec3 d(0, -0.8, 0.6);
  // Above the surface already: the plain mirror direction, to the last bit.
  const Vec3 tilted = glm::normalize(Vec3(0, -0.2, -1));
  CHECK(reflectAboveSurface(d, tilted, raw) == reflect(d, tilted));
  CHECK(reflectAboveSurface(d, raw, raw) == reflect(d, raw));
  // The bent normal (0, -5, -12)/13 faces the viewer (d·n = -3.2/13) but sends d to
  // (0, -0.8 - 32/169, 0.6 - 76.8/169), below the wall: reflected again about raw.
  const Vec3 r1 = reflectAboveSurface(d, Vec3(0, -5, -12) / 13.0, raw);
  CHECK(r1.x == Approx(0).margin(1e-12));
  CHECK(r1.y == Approx(-0.8 - 32 / 169.0).epsilon(1e-12));
  CHECK(r1.z == Approx(-(0.6 - 76.8 / 169.0)).epsilon(1e-12));
  // The bent normal (0, -2, -1)/√5 faces away (d·n = 1/√5) and sends d to (0, 0, 1), behind
  // both: d is reflected about raw instead, to (0, -0.8, -0.6).
  const Vec3 r2 = reflectAboveSurface(d, glm::normalize(Vec3(0, -2, -1)), raw);
  CHECK(r2.x == Approx(0).margin(1e-12));
  CHECK(r2.y == Approx(-0.8).epsilon(1e-12));
  CHECK(r2.z == Approx(-0.6).epsilon(1e-12));
}
