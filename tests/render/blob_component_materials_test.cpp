// A blob whose components carry materials of their own (Tracer::shadeComponents): POV-Ray's
// multi-textured blob shades each component's texture whole and sums the colours weighted
// by the components' |field| at the hit over their sum (those below adc_bailout left out);
// a component without a material takes the blob's. The weights here are worked out from POV-Ray's
// field formula, s·(1 − r²/R²)², at the point the ray meets the surface.
#include "scene_builder.h"

#include "../support/scene_text.h"
#include "lang/parser.h"
#include "primitives/blob.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

using namespace lucent;
using namespace lucent::test;

namespace {

std::unique_ptr<Scene> parse(const std::string& body) {
  return parseValid(body, "blob_components.xml", "<camera position=\"0 5 5\" look-at=\"0 0 0\"/>");
}

void checkColor(const Color& got, const Color& want) {
  for (int i = 0; i < 3; ++i) CHECK(got[i] == Approx(want[i]).margin(1e-5));
}

// POV-Ray's field of one sphere component at p, by its formula.
double field(const Vec3& p, const Vec3& c, double r, double s) {
  const double q = glm::dot(p - c, p - c) / (r * r);
  return q < 1.0 ? s * (1.0 - q) * (1.0 - q) : 0.0;
}

// Where the ray straight down at (x, z) meets the blob's surface, by bisection of the field.
Vec3 surfaceBelow(double x, double z, double threshold,
                  const std::function<double(const Vec3&)>& sum) {
  double lo = 0.0, hi = 1.5;  // y: inside at 0, outside at 1.5 for these points
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (sum(Vec3(x, mid, z)) > threshold ? lo : hi) = mid;
  }
  return Vec3(x, 0.5 * (lo + hi), z);
}

// Ambient light only: a red component at x = -0.4, a blue one at 0.4, one without a
// material (the blob's green) at z = -0.5, and a negative red one.
const char* const kColouredBlob = R"XML(<render ambient="1" background="0 0 0"/>
    <material id="red" ambient="1 0 0" diffuse="0"/>
    <material id="blue" ambient="0 0 1" diffuse="0"/>
    <blob threshold="0.4">
      <material ambient="0 1 0" diffuse="0"/>
      <component type="sphere" center="-0.4 0 0" radius="1" strength="1" material="red"/>
      <component type="sphere" center="0.4 0 0" radius="1" strength="1" material="blue"/>
      <component type="sphere" center="0 0 -0.5" radius="1" strength="0.8"/>
      <component type="sphere" center="0 0.9 0.6" radius="0.5" strength="-0.3" material="red"/>
    </blob>)XML";

}  // namespace

TEST_CASE("blob component materials: each shaded whole, weighted by its field at the hit",
          "[render][blob]") {
  // A negative component's |field| weighs too.
  auto scene = parse(kColouredBlob);
  World world(*scene);
  struct C {
    Vec3 c;
    double r, s;
    Color color;
  };
  const C comps[] = {{Vec3(-0.4, 0, 0), 1, 1, Color(1, 0, 0)},
                     {Vec3(0.4, 0, 0), 1, 1, Color(0, 0, 1)},
                     {Vec3(0, 0, -0.5), 1, 0.8, Color(0, 1, 0)},
                     {Vec3(0, 0.9, 0.6), 0.5, -0.3, Color(1, 0, 0)}};
  auto sum = [&](const Vec3& p) {
    double f = 0.0;
    for (const C& k : comps) f += field(p, k.c, k.r, k.s);
    return f;
  };
  for (const Vec2 at : {Vec2(0.0, 0.0), Vec2(-0.5, 0.2), Vec2(0.3, -0.4), Vec2(0.1, 0.35)}) {
    const Vec3 p = surfaceBelow(at.x, at.y, 0.4, sum);
    double total = 0.0;
    Color want(0.0f);
    for (const C& k : comps) total += std::abs(field(p, k.c, k.r, k.s));
    // POV-Ray leaves out a texture whose weight is below adc_bailout (1/255 by default).
    for (const C& k : comps) {
      const double w = std::abs(field(p, k.c, k.r, k.s)) / total;
      if (w >= 0.0039) want += static_cast<float>(w) * k.color;
    }
    INFO("at " << at.x << " " << at.y);
    checkColor(traceOne(world, Ray(Vec3(at.x, 2, at.y), Vec3(0, -1, 0))), want);
  }
}

TEST_CASE("blob component materials: a shadow ray takes the weighted share of each",
          "[render][blob]") {
  // A flat blob over a lit floor, one component clear and one opaque: where both weigh the
  // same (x = 0 between equal spheres) half the light passes, through both surfaces.
  auto scene = parse(R"XML(<light type="directional" direction="0 -1 0" color="1"/>
    <material id="clear" transmissive="1"/>
    <blob threshold="0.5" transform="scale(1 0.1 1) translate(0 1 0)">
      <material/>
      <component type="sphere" center="-0.5 0 0" radius="1.5" strength="1" material="clear"/>
      <component type="sphere" center="0.5 0 0" radius="1.5" strength="1"/>
    </blob>
    <plane normal="0 1 0" offset="0"><material diffuse="1"/></plane>)XML");
  World world(*scene);
  checkColor(traceOne(world, Ray(Vec3(0, 0.5, 0), Vec3(0, -1, 0))), Color(0.25f));
}

TEST_CASE("blob component materials: an inline <material> is the component's as an id is",
          "[render][blob]") {
  // kColouredBlob with its components' materials inline.
  const std::string inlined = R"XML(<render ambient="1" background="0 0 0"/>
    <blob threshold="0.4">
      <material ambient="0 1 0" diffuse="0"/>
      <component type="sphere" center="-0.4 0 0" radius="1" strength="1">
        <material ambient="1 0 0" diffuse="0"/>
      </component>
      <component type="sphere" center="0.4 0 0" radius="1" strength="1">
        <material ambient="0 0 1" diffuse="0"/>
      </component>
      <component type="sphere" center="0 0 -0.5" radius="1" strength="0.8"/>
      <component type="sphere" center="0 0.9 0.6" radius="0.5" strength="-0.3">
        <material ambient="1 0 0" diffuse="0"/>
      </component>
    </blob>)XML";
  auto a = parse(kColouredBlob);
  auto b = parse(inlined);
  const auto& blob = std::get<BlobSpec>(*b->root->children.back()->shape);
  REQUIRE(blob.componentMaterials.size() == 4);
  REQUIRE(blob.componentMaterials[0]);
  CHECK(b->materials[*blob.componentMaterials[0]].ambient == Color(1, 0, 0));
  CHECK(b->materials[*blob.componentMaterials[1]].ambient == Color(0, 0, 1));
  CHECK_FALSE(blob.componentMaterials[2]);
  CHECK(b->materials[*blob.componentMaterials[3]].ambient == Color(1, 0, 0));
  World wa(*a), wb(*b);
  for (const Vec2 at : {Vec2(0.0, 0.0), Vec2(-0.5, 0.2), Vec2(0.3, -0.4), Vec2(0.6, 0.1)}) {
    const Ray ray(Vec3(at.x, 2, at.y), Vec3(0, -1, 0));
    const Color want = traceOne(wa, ray);
    CHECK(maxComponent(want) > 0.2f);  // the blob is hit (the background is black)
    CHECK(traceOne(wb, ray) == want);
  }
}
