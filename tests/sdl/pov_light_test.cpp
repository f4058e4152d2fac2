// POV-Ray's light_source (sdl/pov_light.h): POV-Ray's spotlight and fade formulas against
// the light Lucent renders from the import, the area light's axes, and what is said.
#include "sdl/pov_light.h"
#include "render/light_sample.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace lucent;
using namespace lucent::sdl;

namespace {

bool mentions(const std::vector<std::string>& notes, const std::string& word) {
  return std::any_of(notes.begin(), notes.end(),
                     [&](const std::string& n) { return n.find(word) != std::string::npos; });
}

// POV-Ray's area light sample (u, v) at the lit point p, in POV-Ray's space, as its
// tracer computes it: circular pulls the grid's shells onto circles; orient first turns
// the axes across the direction to the centre, crossing with z (y within 0.01 of ±z).
Vec3 povAreaSample(const PovLight& l, const Vec3& p, int u, int v) {
  const PovAreaLight& a = *l.area;
  const Vec3 centre = l.transform.point(l.location);
  Vec3 axis1 = l.transform.vector(a.axis1), axis2 = l.transform.vector(a.axis2);
  if (a.orient) {
    const Vec3 d = glm::normalize(centre - p);
    const Vec3 t = std::fabs(std::fabs(d.z) - 1.0) < 0.01 ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
    const double length = glm::length(axis1);
    axis1 = glm::normalize(glm::cross(d, t));
    axis2 = glm::normalize(glm::cross(d, axis1)) * length;
    axis1 *= length;
  }
  double x = double(u) / (a.size1 - 1) - 0.5, y = double(v) / (a.size2 - 1) - 0.5;
  if (a.circular || a.orient) {
    x += 0.001;
    y += 0.001;
    const double scale = std::max(std::fabs(x), std::fabs(y)) / std::sqrt(x * x + y * y);
    x *= scale;
    y *= scale;
  }
  return centre + axis1 * x + axis2 * y;
}

}  // namespace

TEST_CASE("a spotlight lights as POV-Ray's at every angle from its axis", "[sdl][light]") {
  // A falloff beyond 90 degrees too: POV-Ray's cone reaches only the front half (its factor
  // is 0 where cos θ <= 0), its smoothstep still running from cos falloff.
  // A radius beyond the falloff too (POV-Ray's full light then ends at the radius).
  const std::pair<double, double> cones[] = {
      {12.0, 25.0}, {60.0, 135.0}, {100.0, 170.0}, {40.0, 20.0}, {120.0, 60.0}};
  for (const auto& [radius, falloff] : cones)
    for (double tightness : {0.0, 7.5}) {
      PovLight pov;
      pov.kind = PovLightKind::Spotlight;
      pov.location = Vec3(1.0, 4.0, -2.0);
      pov.pointAt = Vec3(0.0, 0.0, 1.0);
      pov.radius = radius;
      pov.falloff = falloff;
      pov.tightness = tightness;
      pov.color = Color(0.9f, 0.8f, 0.7f);
      const LightImport imported = importLight(pov);
      CHECK(imported.differences.empty());
      const Light& light = imported.light;
      CHECK(light.type == LightType::Spot);
      CHECK(light.inner == radius);
      CHECK(light.angle == std::max(falloff, radius));
      CHECK(light.tightness == tightness);
      // Points at 0 to 180 degrees from the axis, 5 units from the light (POV-Ray's space).
      const Vec3 axis = glm::normalize(pov.pointAt - pov.location);
      const Vec3 side = glm::normalize(glm::cross(axis, Vec3(0.0, 1.0, 0.0)));
      for (double deg = 0.0; deg <= 180.0; deg += 1.5) {
        const double a = radians(deg);
        const Vec3 p = pov.location + 5.0 * (std::cos(a) * axis + std::sin(a) * side);
        const LightIncidence in = lightIncidence(light, lucentFromPov(p));
        const double expected = povSpotFactor(pov, std::cos(a));
        INFO("radius " << radius << ", falloff " << falloff << ", tightness " << tightness << ", "
                       << deg << " degrees: POV-Ray " << expected);
        CHECK(in.radiance.g == Approx(0.8 * expected).margin(1e-6));
      }
    }
  // The defaults: radius 30, falloff 45; the tightness is the light's.
  PovLight plain;
  plain.kind = PovLightKind::Spotlight;
  plain.tightness = 10.0;
  const LightImport d = importLight(plain);
  CHECK(d.light.inner == 30.0);
  CHECK(d.light.angle == 45.0);
  CHECK(d.light.tightness == 10.0);
  CHECK(d.differences.empty());
  // Inside the radius POV-Ray's factor is cos^10 θ alone (hand-computed: cos 20° = 0.939693,
  // its square 0.883022, its 8th power 0.607976, its 10th 0.536856).
  CHECK(povSpotFactor(plain, std::cos(radians(20.0))) == Approx(0.536856).epsilon(1e-5));
  CHECK(spotFactor(d.light, std::cos(radians(20.0))) == Approx(0.536856).epsilon(1e-5));
  // Below 0 POV-Ray brightens away from the axis; imported as 0, said.
  plain.tightness = -2.0;
  const LightImport negative = importLight(plain);
  CHECK(negative.light.tightness == 0.0);
  CHECK(mentions(negative.differences, "tightness -2"));
}

TEST_CASE("fade_distance and fade_power: POV-Ray's 2/(1 + (d/fd)^fp) at every distance",
          "[sdl][light]") {
  for (double power : {1.0, 2.0, 3.0, 0.5}) {
    PovLight pov;
    pov.location = Vec3(0.0, 0.0, 3.0);
    pov.fadeDistance = 2.5;
    pov.fadePower = power;
    const LightImport imported = importLight(pov);
    CHECK(povLightFade(pov, 0.0) == 2.0);
    CHECK(povLightFade(pov, 2.5) == Approx(1.0));
    CHECK(imported.differences.empty());
    CHECK(imported.light.fadeDistance == 2.5);
    CHECK(imported.light.fadePower == power);
    // Within fd too, where POV-Ray's fade brightens the light up to twice its colour.
    for (double d : {0.0, 1.0, 2.5, 3.0, 5.0, 11.0, 40.0}) {
      const LightIncidence in =
          lightIncidence(imported.light, lucentFromPov(pov.location + Vec3(0.0, d, 0.0)));
      INFO("power " << power << ", distance " << d);
      CHECK(in.radiance.r == Approx(povLightFade(pov, d)).epsilon(1e-6));
    }
  }
  // fade_power 3 at 1 and 2 times fd = 2 (hand-computed): 2/(1 + 1/8) = 16/9, 2/(1 + 1) = 1.
  PovLight third;
  third.fadeDistance = 2.0;
  third.fadePower = 3.0;
  const Light cubic = importLight(third).light;
  CHECK(lightIncidence(cubic, Vec3(0.0, 1.0, 0.0)).radiance.r == Approx(16.0 / 9.0));
  CHECK(lightIncidence(cubic, Vec3(0.0, 2.0, 0.0)).radiance.r == Approx(1.0));
  // fade_distance without fade_power: no fading in POV-Ray, none imported.
  PovLight half;
  half.fadeDistance = 1.0;
  CHECK(povLightFade(half, 10.0) == 1.0);
  CHECK(importLight(half).light.attenuation == Vec3(1.0, 0.0, 0.0));
  CHECK(!importLight(half).light.fades());
  CHECK(importLight(half).differences.empty());
}

TEST_CASE("area lights keep their axes (mirrored, transformed) and grid", "[sdl][light]") {
  PovLight pov;
  pov.location = Vec3(2.0, 5.0, -3.0);
  pov.area = PovAreaLight{Vec3(2.0, 0.0, 0.0), Vec3(0.0, 0.0, 1.0), 4, 8, 1, false, false, false};
  pov.transform.rotate(Vec3(0.0, 90.0, 0.0));
  const LightImport imported = importLight(pov);
  CHECK(imported.differences.empty());
  const Light& l = imported.light;
  CHECK(l.type == LightType::Area);
  CHECK(l.samplesU == 4);
  CHECK(l.samplesV == 8);
  CHECK(l.adaptive == 1);
  // rotate y*90 takes x to -z and z to x in POV-Ray's space; then z is negated.
  CHECK(glm::length(l.u - Vec3(0.0, 0.0, 2.0)) < 1e-12);
  CHECK(glm::length(l.v - Vec3(1.0, 0.0, 0.0)) < 1e-12);
  CHECK(glm::length(l.position - lucentFromPov(pov.transform.point(pov.location))) < 1e-12);

  // 5 x 5 without adaptive: POV-Ray's edge samples weigh less; said.
  pov.area->size1 = 5;
  pov.area->size2 = 5;
  pov.area->adaptive.reset();
  pov.area->circular = true;
  const LightImport uneven = importLight(pov);
  CHECK(mentions(uneven.differences, "unevenly"));
  CHECK(uneven.light.circular);
  CHECK_FALSE(mentions(uneven.differences, "circular"));

  // A line of lights (one sample across): two coincident rows.
  pov.area->size2 = 1;
  const LightImport line = importLight(pov);
  CHECK(line.light.samplesV == 2);
  CHECK(glm::length(line.light.v) < 1e-8);
  CHECK(glm::length(glm::cross(line.light.u, line.light.v)) > 0.0);
  // An axis of length 0, which POV-Ray takes (its samples along it coincide): a line too.
  pov.area->size2 = 3;
  pov.area->axis2 = Vec3(0.0);
  const LightImport flat = importLight(pov);
  CHECK(flat.light.type == LightType::Area);
  CHECK(flat.light.samplesV == 2);
  CHECK(glm::length(flat.light.v) < 1e-8);
  CHECK(glm::length(glm::cross(flat.light.u, flat.light.v)) > 0.0);
  // Parallel axes (POV-Ray's samples on one line, as far as both reach): a line of lights.
  pov.area->axis1 = Vec3(2.0, 0.0, 0.0);
  pov.area->axis2 = Vec3(-1.0, 0.0, 0.0);
  pov.area->size1 = 3;
  pov.area->size2 = 3;
  const LightImport parallel = importLight(pov);
  CHECK(parallel.light.type == LightType::Area);
  CHECK(glm::length(parallel.light.u) == Approx(3.0));
  CHECK(parallel.light.samplesU == 5);
  CHECK(parallel.light.samplesV == 2);
  CHECK(glm::length(parallel.light.v) < 1e-8);
  CHECK(mentions(parallel.differences, "parallel"));
  // Both of length 0: every sample at the centre, a point light.
  pov.area->axis1 = Vec3(0.0);
  pov.area->axis2 = Vec3(0.0);
  CHECK(importLight(pov).light.type == LightType::Point);
}

TEST_CASE("circular area lights sample POV-Ray's disc, oriented ones turn to the point",
          "[sdl][light]") {
  PovLight pov;
  pov.location = Vec3(2.0, 5.0, -3.0);
  pov.area = PovAreaLight{Vec3(1.5, 0.0, 0.0), Vec3(0.0, 0.5, 1.0), 4, 5, 1, false, true, false};
  pov.transform.rotate(Vec3(20.0, 30.0, 0.0));
  const LightImport circular = importLight(pov);
  CHECK(circular.differences.empty());
  const Light& c = circular.light;
  CHECK(c.circular);
  CHECK_FALSE(c.orient);
  // Each sample is POV-Ray's, mirrored into Lucent's space.
  for (int k = 0; k < 20; ++k)
    CHECK(glm::length(lightSamplePoint(c, k, Vec2(0.5)) -
                      lucentFromPov(povAreaSample(pov, Vec3(0.0), k % 4, k / 4))) < 1e-12);

  // orient without circular: POV-Ray makes it circular; its unequal axes use the first's
  // length, so v takes u's.
  pov.area->circular = false;
  pov.area->orient = true;
  const LightImport oriented = importLight(pov);
  const Light& o = oriented.light;
  CHECK(o.circular);
  CHECK(o.orient);
  CHECK(glm::length(o.v) == Approx(glm::length(o.u)).epsilon(1e-12));
  CHECK(glm::length(o.u) == Approx(1.5).epsilon(1e-12));
  CHECK(o.handedness == Handedness::Left);
  CHECK(oriented.differences.empty());
  // The disc turned by POV-Ray's cross products in its own space: every sample is POV-Ray's,
  // mirrored into Lucent's, at points all around and below the light along z (where the
  // cross product takes y).
  const Vec3 points[] = {Vec3(0.0), Vec3(9.0, -2.0, 4.0), Vec3(-3.0, 1.0, -8.0),
                         pov.transform.point(pov.location) + Vec3(0.001, 0.002, -6.0)};
  for (const Vec3& p : points) {
    const AreaAxes axes = areaAxes(o, lucentFromPov(p));
    for (int k = 0; k < 20; ++k)
      CHECK(glm::length(lightSamplePoint(o, axes, k, Vec2(0.5)) -
                        lucentFromPov(povAreaSample(pov, p, k % 4, k / 4))) < 1e-12);
  }
  // Lucent's own handedness turns the grid the mirrored way: the same disc, other samples.
  Light right = o;
  right.handedness = Handedness::Right;
  const Vec3 p(9.0, -2.0, 4.0);
  const AreaAxes mirrored = areaAxes(right, lucentFromPov(p));
  CHECK(glm::length(lightSamplePoint(right, mirrored, 1, Vec2(0.5)) -
                    lucentFromPov(povAreaSample(pov, p, 1, 0))) > 0.1);

  // A line of lights: POV-Ray's orient keeps the line's own circular off; not imported.
  pov.area->size2 = 1;
  const LightImport line = importLight(pov);
  CHECK_FALSE(line.light.orient);
  CHECK_FALSE(line.light.circular);
  CHECK(mentions(line.differences, "line of lights"));
}

TEST_CASE("parallel, shadowless, cylinder and looks_like lights", "[sdl][light]") {
  PovLight parallel;
  parallel.location = Vec3(0.0, 10.0, -10.0);
  parallel.pointAt = Vec3(0.0, 0.0, 0.0);
  parallel.parallel = true;
  const LightImport p = importLight(parallel);
  CHECK(p.light.type == LightType::Directional);
  CHECK(glm::length(p.light.direction - glm::normalize(Vec3(0.0, -10.0, -10.0))) < 1e-12);
  CHECK(mentions(p.differences, "plane through its location"));

  PovLight cylinder;
  cylinder.kind = PovLightKind::Cylinder;
  cylinder.tightness = 2.0;
  const LightImport c = importLight(cylinder);
  CHECK(c.light.type == LightType::Cylindrical);
  CHECK(c.light.radius == 0.75);
  CHECK(c.light.falloff == 1.0);
  CHECK(c.light.tightness == 2.0);
  CHECK(c.differences.empty());

  PovLight quiet;
  quiet.shadowless = true;
  const LightImport q = importLight(quiet);
  CHECK(!q.light.shadows);
  CHECK(!q.light.highlights);  // POV-Ray's shadowless light adds no highlight
  CHECK(!mentions(q.differences, "shadowless"));
}
