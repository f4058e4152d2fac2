// Refraction, total internal reflection, Fresnel, absorption, nested media and the
// recursion limits, traced through real scenes.
#include "scene_builder.h"

#include "app/image_output.h"

#include <catch2/catch.hpp>

#include <filesystem>

#include <unistd.h>

using namespace lucent;
using namespace lucent::test;

namespace {

Material glass(double ior, const Color& kt = Color(1.0f)) {
  Material m;
  m.transmissive = kt;
  m.ior = ior;
  return m;
}

// A wall z = zWall facing +z.
void addWall(Scene& scene, double zWall, uint32_t material) {
  addShape(scene, PlaneSpec{Vec3(0, 0, 1), zWall}, material);
}

// A 2 x 1 float image (0 and 1): bilinear interpolation makes its value a linear ramp
// between the pixel centres, so a texture lookup measures where a ray landed.
std::string writeRamp() {
  auto path = std::filesystem::temp_directory_path() /
              ("lucent-ramp-" + std::to_string(::getpid()) + ".exr");
  Image ramp(2, 1);
  ramp.at(0, 0) = Color(0.0f);
  ramp.at(1, 0) = Color(1.0f);
  writeImageFile(ramp, path.string());
  return path.string();
}

// The wall's u (= world x) from the ramp's value: value = 2 s - 0.5 with s = u / scale
// for s in [0.25, 0.75].
constexpr double kRampScale = 60.0;
double landingX(const Color& c) { return kRampScale * (c.r + 0.5) / 2.0; }

}  // namespace

TEST_CASE("a ray through a glass slab lands displaced by the analytic amount, parallel",
          "[render][refraction]") {
  const std::string ramp = writeRamp();
  const double n = 1.5, thickness = 1.0;
  const double theta = radians(30.0), thetaT = std::asin(std::sin(theta) / n);
  const Vec3 origin(20, 0, 0), d(std::sin(theta), 0, -std::cos(theta));

  auto land = [&](double zWall, bool withSlab) {
    Scene scene;
    scene.render.ambient = Color(1.0f);
    Material wall;
    wall.ambient = Color(1.0f);
    wall.ambientIsScalar = true;
    ImageTexture image;
    image.path = ramp;
    image.scale = Vec2(kRampScale, 1.0);
    wall.texture = image;
    addWall(scene, zWall, addMaterial(scene, wall));
    if (withSlab)
      addShape(scene, BoxSpec{Vec3(-100, -100, -3), Vec3(100, 100, -3 + thickness)},
               addMaterial(scene, glass(n)));
    World world(scene);
    return landingX(traceOne(world, Ray(origin, d)));
  };

  // Without the slab the ray lands where it points.
  CHECK(land(-10, false) == Approx(20 + 10 * std::tan(theta)).margin(1e-4));
  // With it, the path inside the slab is steeper: tan(theta) - tan(thetaT) per unit.
  const double shift = thickness * (std::tan(theta) - std::tan(thetaT));
  CHECK(land(-10, true) == Approx(20 + 10 * std::tan(theta) - shift).margin(1e-4));
  // Parallel: ten units further the landing point moves by 10 tan(theta), as without glass.
  CHECK(land(-20, true) - land(-10, true) == Approx(10 * std::tan(theta)).margin(2e-4));
  std::filesystem::remove(ramp);
}

TEST_CASE("total internal reflection sends the k_t share into the mirror ray",
          "[render][refraction]") {
  // A right-angle prism: the cube [-1,1]^3 cut by the plane x + z = 0 (the half x + z > 0
  // is kept). A ray coming down -z enters the face z = 1 head-on, meets the hypotenuse at
  // 45 degrees (critical angle 41.8 for ior 1.5), is reflected towards +x, leaves through
  // x = 1 head-on and reaches the wall x = 5.
  Scene scene;
  const Color wallColor(0.2f, 0.5f, 0.7f);
  uint32_t prismMaterial = addMaterial(scene, glass(1.5));
  auto prism = std::make_unique<Node>();
  prism->kind = NodeKind::Intersection;
  prism->element = "intersection";
  prism->material = prismMaterial;
  prism->children.push_back(shapeNode(BoxSpec{Vec3(-1), Vec3(1)}, std::nullopt));
  prism->children.push_back(
      shapeNode(PlaneSpec{glm::normalize(Vec3(-1, 0, -1)), 0.0}, std::nullopt));
  scene.root->children.push_back(std::move(prism));
  addShape(scene, PlaneSpec{Vec3(-1, 0, 0), -5.0}, addMaterial(scene, emissive(wallColor)));
  addWall(scene, -20, addMaterial(scene, emissive(Color(0.9f, 0.1f, 0.1f))));  // not seen

  const Ray ray(Vec3(0.3, 0, 5), Vec3(0, 0, -1));
  // Depths: prism entry 1, inside 2 (bent: the indices differ), after TIR 3, out 4.
  scene.render.maxDepth = 4;
  {
    World world(scene);
    RayStats stats;
    CHECK(traceOne(world, ray, &stats) == wallColor);
    CHECK(stats.reflected == 1);
    CHECK(stats.refracted == 2);
  }
  scene.render.maxDepth = 3;
  {
    World world(scene);
    CHECK(traceOne(world, ray) == Color(0.0f));  // beyond max-depth: black, not background
  }
}

TEST_CASE("Fresnel: k_r F at normal incidence is ((n-1)/(n+1))^2", "[render][refraction]") {
  Scene scene;
  Material mirror;
  mirror.reflective = Color(1.0f);
  mirror.fresnel = true;
  mirror.ior = 1.5;
  addWall(scene, 0.0, addMaterial(scene, mirror));
  // A wall behind the camera (z = 10, facing -z) that the reflection sees.
  addShape(scene, PlaneSpec{Vec3(0, 0, -1), -10.0}, addMaterial(scene, emissive(Color(1.0f))));
  World world(scene);
  Color c = traceOne(world, Ray(Vec3(0, 0, 5), Vec3(0, 0, -1)));
  CHECK(c.r == Approx(0.04).epsilon(1e-6));
  // Glass with fresnel: the transmitted share is k_t (1 - F).
  Scene g;
  Material pane = glass(1.5);
  pane.fresnel = true;
  addShape(g, BoxSpec{Vec3(-5, -5, -1), Vec3(5, 5, 0)}, addMaterial(g, pane));
  addWall(g, -10, addMaterial(g, emissive(Color(1.0f))));
  World gw(g);
  CHECK(traceOne(gw, Ray(Vec3(0, 0, 5), Vec3(0, 0, -1))).r == Approx(0.96 * 0.96).epsilon(1e-6));
}

TEST_CASE("Beer-Lambert absorption through a slab of thickness d is exp(-a d)",
          "[render][refraction]") {
  for (double ior : {1.0, 1.5}) {  // straight through, and bent (at normal incidence)
    Scene scene;
    Material m = glass(ior);
    m.absorption = Color(0.5f, 1.0f, 2.0f);
    addShape(scene, BoxSpec{Vec3(-5, -5, -2), Vec3(5, 5, 0)}, addMaterial(scene, m));
    addWall(scene, -10, addMaterial(scene, emissive(Color(1.0f))));
    World world(scene);
    Color c = traceOne(world, Ray(Vec3(0, 0, 5), Vec3(0, 0, -1)));
    INFO("ior " << ior);
    CHECK(c.r == Approx(std::exp(-0.5 * 2)).epsilon(1e-6));
    CHECK(c.g == Approx(std::exp(-1.0 * 2)).epsilon(1e-6));
    CHECK(c.b == Approx(std::exp(-2.0 * 2)).epsilon(1e-6));
  }
}

TEST_CASE("a transmitted ray that does not bend keeps its parent's depth", "[render][refraction]") {
  Scene scene;
  scene.render.maxDepth = 1;  // only the primary ray
  uint32_t pane = addMaterial(scene, glass(1.0, Color(0.5f)));
  addShape(scene, BoxSpec{Vec3(-5, -5, -2), Vec3(5, 5, 0)}, pane);
  addWall(scene, -10, addMaterial(scene, emissive(Color(1.0f))));
  {
    World world(scene);
    CHECK(traceOne(world, Ray(Vec3(0, 0, 5), Vec3(0, 0, -1))).r == Approx(0.25).epsilon(1e-7));
  }
  scene.materials[pane].ior = 1.5;  // now the ray bends (even head-on): depth 2 is too deep
  {
    World world(scene);
    CHECK(traceOne(world, Ray(Vec3(0, 0, 5), Vec3(0, 0, -1))) == Color(0.0f));
  }
}

TEST_CASE("min-weight: a secondary ray whose weight falls below it is not traced",
          "[render][refraction]") {
  Scene scene;
  Material mirror;
  mirror.reflective = Color(0.003f, 0.001f, 0.0f);  // largest channel 0.003 < 0.0039
  uint32_t m = addMaterial(scene, mirror);
  addWall(scene, 0.0, m);
  addShape(scene, PlaneSpec{Vec3(0, 0, -1), -10.0}, addMaterial(scene, emissive(Color(1.0f))));
  const Ray ray(Vec3(0, 0, 5), Vec3(0, 0, -1));
  {
    World world(scene);
    RayStats stats;
    CHECK(traceOne(world, ray, &stats) == Color(0.0f));
    CHECK(stats.reflected == 0);
  }
  scene.materials[m].reflective = Color(0.004f, 0.001f, 0.0f);
  {
    World world(scene);
    RayStats stats;
    CHECK(traceOne(world, ray, &stats).r == Approx(0.004).epsilon(1e-6));
    CHECK(stats.reflected == 1);
  }
}

namespace {

// From the centre of a glowing glass ball (ior 1.5, a Fresnel mirror), optionally inside a
// water ball (1.33), head-on: what the camera ray brings back, with depth 2 (the reflected
// ray sees the glow again; depth 3 is cut off).
double glowingBallSeenFromInside(bool inWater, bool nestedExitFresnel) {
  Scene scene;
  scene.render.maxDepth = 2;
  scene.render.minWeight = 0.0;
  Material ball;
  ball.emissive = Color(1.0f);
  ball.reflective = Color(1.0f);
  ball.fresnel = true;
  ball.ior = 1.5;
  ball.nestedExitFresnel = nestedExitFresnel;
  addShape(scene, SphereSpec{Vec3(0), 1.0}, addMaterial(scene, ball));
  if (inWater) addShape(scene, SphereSpec{Vec3(0), 3.0}, addMaterial(scene, glass(1.33)));
  World world(scene);
  return traceOne(world, Ray(Vec3(0), Vec3(0, 0, -1))).r;
}

}  // namespace

TEST_CASE("nested media: leaving glass into water uses the water's index", "[render][refraction]") {
  // Head-on, the inner surface reflects F = ((1.5 - 1.33)/2.83)^2 of the glow.
  const double f = std::pow((1.5 - 1.33) / (1.5 + 1.33), 2.0);
  CHECK(glowingBallSeenFromInside(true, true) == Approx(1.0 + f).epsilon(1e-6));
}

TEST_CASE("nested-exit-fresnel false: leaving a nested solid, Fresnel reflects nothing",
          "[render][refraction][pov-rules]") {
  // POV-Ray 3.7's rule: the ray leaves the glass ball while inside the water ball too, and
  // POV-Ray's Fresnel ratio there is the last medium entered (the glass) over the glass, 1:
  // no reflection, only the glow. Alone (not nested) the rule is the physical one,
  // F = ((1.5 - 1)/2.5)^2 = 0.04. Refraction keeps the true indices.
  CHECK(glowingBallSeenFromInside(true, false) == Approx(1.0).epsilon(1e-6));
  CHECK(glowingBallSeenFromInside(false, false) == Approx(1.04).epsilon(1e-6));
}

TEST_CASE("<render epsilon> moves secondary origins by epsilon along the normal",
          "[render][refraction]") {
  // An exaggerated epsilon of 0.5: the ray entering the slab z in [-2, 0] starts again at
  // z = -0.5, so it travels 1.5 (not 2) inside the absorbing glass.
  Scene scene;
  scene.render.epsilon = 0.5;
  Material m = glass(1.0);
  m.absorption = Color(1.0f);
  addShape(scene, BoxSpec{Vec3(-5, -5, -2), Vec3(5, 5, 0)}, addMaterial(scene, m));
  addWall(scene, -10, addMaterial(scene, emissive(Color(1.0f))));
  World world(scene);
  CHECK(traceOne(world, Ray(Vec3(0, 0, 5), Vec3(0, 0, -1))).r ==
        Approx(std::exp(-1.5)).epsilon(1e-6));
}

TEST_CASE("a surface without an inside is a thin sheet: transmission does not bend",
          "[render][refraction]") {
  // A disc of "glass" with ior 1.5 between the camera and a wall: light goes straight
  // through (no medium to enter) and keeps its depth, so max-depth 1 still sees the wall.
  Scene scene;
  scene.render.maxDepth = 1;
  addShape(scene, DiscSpec{Vec3(0, 0, -2), Vec3(0, 0, 1), 3.0, 0.0},
           addMaterial(scene, glass(1.5, Color(0.5f))));
  addWall(scene, -10, addMaterial(scene, emissive(Color(1.0f))));
  World world(scene);
  RayStats stats;
  // Oblique, so that a bent ray would have a reason to be at depth 2 (and black).
  const double a = radians(20.0);
  CHECK(traceOne(world, Ray(Vec3(0, 0, 0), Vec3(std::sin(a), 0, -std::cos(a))), &stats).r ==
        Approx(0.5).epsilon(1e-7));
  CHECK(stats.refracted == 1);
}

namespace {

// A glass slab z in [-5, -1] minus a slab z in [cutNear, cutFar] of material `cut` (narrower
// in x and y, so the glass surrounds it there), as a <difference> or, with `asInverse`, an
// <intersection> with the inverse slab. `spared`: a slab z in [near, far] taken out of the
// cut (the cut part is then itself a difference, whose parts wear its material).
void addCutSlab(Scene& scene, uint32_t glassMaterial, uint32_t cut, double cutNear, double cutFar,
                bool asInverse = false,
                std::optional<std::pair<double, double>> spared = std::nullopt) {
  auto node = std::make_unique<Node>();
  node->kind = asInverse ? NodeKind::Intersection : NodeKind::Difference;
  node->element = asInverse ? "intersection" : "difference";
  node->children.push_back(
      shapeNode(BoxSpec{Vec3(-100, -100, -5), Vec3(100, 100, -1)}, glassMaterial));
  std::unique_ptr<Node> part = shapeNode(BoxSpec{Vec3(-50, -50, cutFar), Vec3(50, 50, cutNear)},
                                         spared ? std::nullopt : std::optional(cut));
  if (spared) {
    auto piece = std::make_unique<Node>();
    piece->kind = NodeKind::Difference;
    piece->element = "difference";
    piece->material = cut;
    piece->children.push_back(std::move(part));
    piece->children.push_back(shapeNode(
        BoxSpec{Vec3(-40, -40, spared->second), Vec3(40, 40, spared->first)}, std::nullopt));
    part = std::move(piece);
  }
  part->inverse = asInverse;
  node->children.push_back(std::move(part));
  scene.root->children.push_back(std::move(node));
}

}  // namespace

TEST_CASE("a cut of a difference holds its part's medium: rays bend from the glass into it",
          "[render][refraction][csg]") {
  // Snell's law across parallel layers keeps n sin(theta): each layer of thickness d and
  // index n shifts the landing point by d (tan(theta) - tan(theta_n)), sin(theta_n) =
  // sin(theta) / n, an index-1 layer not at all.
  const std::string ramp = writeRamp();
  const double theta = radians(30.0);
  const Vec3 origin(20, 0, 0), d(std::sin(theta), 0, -std::cos(theta));
  auto shift = [&](double thickness, double n) {
    return thickness * (std::tan(theta) - std::tan(std::asin(std::sin(theta) / n)));
  };
  const double straight = 20 + 10 * std::tan(theta);

  // `cutMaterial`: the cut part's own material, or none (it shares the glass's).
  // `insideOpaque`: the camera starts inside an opaque half-space x > 0 (of the default
  // medium, index 1, as the cut's), which the ray never leaves.
  auto land = [&](std::optional<Material> cutMaterial, double cutNear, double cutFar,
                  std::optional<std::pair<double, double>> spared = std::nullopt,
                  bool insideOpaque = false) {
    Scene scene;
    scene.render.ambient = Color(1.0f);
    scene.render.maxDepth = 10;  // up to six bends
    Material wall;
    wall.ambient = Color(1.0f);
    wall.ambientIsScalar = true;
    ImageTexture image;
    image.path = ramp;
    image.scale = Vec2(kRampScale, 1.0);
    wall.texture = image;
    addWall(scene, -10, addMaterial(scene, wall));
    const uint32_t g = addMaterial(scene, glass(1.5));
    addCutSlab(scene, g, cutMaterial ? addMaterial(scene, *cutMaterial) : g, cutNear, cutFar, false,
               spared);
    if (insideOpaque) addShape(scene, PlaneSpec{Vec3(-1, 0, 0), 0.0}, addMaterial(scene, {}));
    World world(scene);
    return landingX(traceOne(world, Ray(origin, d)));
  };

  SECTION("a cut part of index 1 is an air bubble: only the glass's 2 units shift the ray") {
    CHECK(land(glass(1.0), -2, -4) == Approx(straight - shift(2, 1.5)).margin(1e-4));
    // The opaque solid's medium, alike in its terms, is not the cut's.
    CHECK(land(glass(1.0), -2, -4, std::nullopt, true) ==
          Approx(straight - shift(2, 1.5)).margin(1e-4));
  }
  SECTION("a cut part of index 1.33 is water inside the glass") {
    CHECK(land(glass(1.33), -2, -4) ==
          Approx(straight - shift(2, 1.5) - shift(2, 1.33)).margin(1e-4));
  }
  SECTION("a cut part of the glass's own material leaves an empty cut") {
    CHECK(land(std::nullopt, -2, -4) == Approx(straight - shift(2, 1.5)).margin(1e-4));
  }
  SECTION("a cut part of the same index but another surface leaves it empty too") {
    Material shiny = glass(1.5);
    shiny.specular = Color(1.0f);  // no light: nothing of it shows
    CHECK(land(shiny, -2, -4) == Approx(straight - shift(2, 1.5)).margin(1e-4));
  }
  SECTION("a cut part that is itself a difference: what it spares is glass again") {
    // Glass 1, water 0.5, glass 1 (spared: z in [-3.5, -2.5]), water 0.5, glass 1, as
    // glasschess's pieces (differences) cut into glass blocks.
    CHECK(land(glass(1.33), -2, -4, std::pair{-2.5, -3.5}) ==
          Approx(straight - shift(3, 1.5) - shift(1, 1.33)).margin(1e-4));
  }
  SECTION("a cut open to the outside: a ray from outside enters the glass at its wall") {
    // The cut z in [-3, 0] opens the glass's front face: the ray crosses the cut in air,
    // then 2 units of glass behind it.
    CHECK(land(glass(1.0), 0, -3) == Approx(straight - shift(2, 1.5)).margin(1e-4));
  }
}

TEST_CASE("a cut's medium absorbs camera and shadow rays inside the cut, the glass outside it",
          "[render][refraction][csg]") {
  // Head-on through 1 + 1 units of glass (absorption 0.1) and 2 of cut (0.3 when it holds
  // a medium of its own, none when it is empty).
  Material g = glass(1.5);
  g.absorption = Color(0.1f);
  Material cut = glass(1.0);
  cut.absorption = Color(0.3f);
  const Ray camera(Vec3(0, 0, 5), Vec3(0, 0, -1));
  auto through = [&](bool ownMedium, bool asInverse) {
    Scene scene;
    addWall(scene, -10, addMaterial(scene, emissive(Color(1.0f))));
    const uint32_t gi = addMaterial(scene, g);
    addCutSlab(scene, gi, ownMedium ? addMaterial(scene, cut) : gi, -2, -4, asInverse);
    World world(scene);
    Tracer tracer(world);
    RayStats stats;
    const Color shadow =
        tracer.transmittance(Ray(camera.o, camera.d, 0.0, 13.0), MediaStack{}, stats);
    return std::pair{traceOne(world, camera).r, shadow.r};
  };
  const double filled = std::exp(-0.1 * 2 - 0.3 * 2), empty = std::exp(-0.1 * 2);
  for (bool asInverse : {false, true}) {
    CAPTURE(asInverse);
    const auto [seen, shadow] = through(true, asInverse);
    CHECK(seen == Approx(filled).epsilon(1e-5));
    CHECK(shadow == Approx(filled).epsilon(1e-5));
    const auto [seenEmpty, shadowEmpty] = through(false, asInverse);
    CHECK(seenEmpty == Approx(empty).epsilon(1e-5));
    CHECK(shadowEmpty == Approx(empty).epsilon(1e-5));
  }
}
