// The local shading formula, pixel by pixel, against an independent computation.
#include "scene_builder.h"

#include "render/renderer.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

// What pixel (i, j) of a w x h pinhole image from (0,0,5) looking down -z should show of a
// sphere of radius R at the origin, computed here from the formulas, not the renderer.
struct Expected {
  bool hit = false;
  bool lit = false;
  glm::dvec3 color{0.0};
  double margin = 0.0;  // |discriminant|: pixels grazing the silhouette are skipped
};

}  // namespace

TEST_CASE("one sphere, one point light: every pixel follows the shading formula",
          "[render][shading]") {
  const int w = 64, h = 48;
  const double R = 1.5, fov = 60.0;
  const glm::dvec3 ke(0.01, 0.02, 0.03), kd(0.7, 0.5, 0.3), ks(0.4), ila(0.2, 0.3, 0.4),
      background(0.05, 0.1, 0.15), lightColor(1.0, 0.9, 0.8);
  const double ka = 0.1, ns = 20.0, intensity = 1.2;
  const Vec3 lightPos(4, 5, 6), abc(0.5, 0.02, 0.01), eye(0, 0, 5);

  Scene scene;
  scene.render.width = w;
  scene.render.height = h;
  scene.render.ambient = Color(ila);
  scene.render.background = Color(background);
  scene.cameras.push_back(lookingFrom(eye, Vec3(0), fov));
  Material m;
  m.emissive = Color(ke);
  m.ambient = Color(static_cast<float>(ka));
  m.diffuse = Color(kd);
  m.specular = Color(ks);
  m.shininess = ns;
  addShape(scene, SphereSpec{Vec3(0), R}, addMaterial(scene, m));
  Light light = pointLight(lightPos, Color(lightColor));
  light.intensity = intensity;
  light.attenuation = abc;
  scene.lights.push_back(light);

  World world(scene);
  Renderer renderer(world, scene.cameras[0]);
  RenderResult result = renderer.render();
  REQUIRE(result.image.width == w);

  const double halfW = std::tan(radians(fov / 2)), halfH = halfW * h / w;
  int hits = 0, lit = 0, unlit = 0, misses = 0;
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const glm::dvec3 d = glm::normalize(glm::dvec3((2.0 * (i + 0.5) / w - 1.0) * halfW,
                                                     (1.0 - 2.0 * (j + 0.5) / h) * halfH, -1.0));
      const double b = glm::dot(eye, d), c = glm::dot(eye, eye) - R * R;
      const double disc = b * b - c;
      glm::dvec3 expected = background;
      if (std::abs(disc) < 1e-3) continue;  // silhouette: leave to the geometry tests
      if (disc > 0) {
        const double t = -b - std::sqrt(disc);
        const glm::dvec3 p = eye + t * d, n = p / R, v = -d;
        expected = ke + ka * ila;
        const glm::dvec3 toLight = lightPos - p;
        const double r = glm::length(toLight);
        const glm::dvec3 l = toLight / r;
        const double nl = glm::dot(n, l);
        if (nl > 0) {
          const double att = std::min(1.0, 1.0 / (abc.x + abc.y * r + abc.z * r * r));
          const glm::dvec3 hv = glm::normalize(l + v);
          expected += att * intensity * lightColor *
                      (kd * nl + ks * std::pow(std::max(0.0, glm::dot(n, hv)), ns));
          ++lit;
        } else {
          ++unlit;
        }
        ++hits;
      } else {
        ++misses;
      }
      const Color got = result.image.at(i, j);
      INFO("pixel " << i << "," << j);
      CHECK(got.r == Approx(expected.r).margin(1e-4));
      CHECK(got.g == Approx(expected.g).margin(1e-4));
      CHECK(got.b == Approx(expected.b).margin(1e-4));
    }
  }
  // The test covers all three cases.
  CHECK(lit > 300);
  CHECK(unlit > 50);
  CHECK(misses > 1000);
  CHECK(hits == lit + unlit);
  CHECK(result.stats.primary == static_cast<uint64_t>(w * h));
  CHECK(result.stats.shadow == static_cast<uint64_t>(lit));  // no shadow rays where N.L <= 0
}

TEST_CASE("a light behind the surface gives nothing, highlight included", "[render][shading]") {
  Scene scene;
  Material m;
  m.specular = Color(1.0f);
  m.shininess = 2.0;
  m.diffuse = Color(1.0f);
  addShape(scene, PlaneSpec{Vec3(0, 0, 1), 0.0}, addMaterial(scene, m));
  // Slightly behind the plane z = 0: N.L < 0 while N.H > 0 for a viewer in front.
  Light behind = pointLight(Vec3(0, 10, -0.1));
  behind.shadows = false;
  scene.lights.push_back(behind);
  World world(scene);
  Color c = traceOne(world, Ray(Vec3(0, 0, 5), Vec3(0, 0, -1)));
  CHECK(c == Color(0.0f));
  // The same light moved just in front lights the plane.
  scene.lights[0].position = Vec3(0, 10, 0.1);
  World lit(scene);
  CHECK(traceOne(lit, Ray(Vec3(0, 0, 5), Vec3(0, 0, -1))).r > 0.1f);
}

TEST_CASE("attenuation is clamped at 1 near the light", "[render][shading]") {
  Scene scene;
  Material m;
  m.diffuse = Color(0.5f);
  addShape(scene, PlaneSpec{Vec3(0, 1, 0), 0.0}, addMaterial(scene, m));
  Light l = pointLight(Vec3(0, 1, 0), Color(0.8f));
  l.attenuation = Vec3(0.25, 0.0, 0.0);  // 1/0.25 = 4 unclamped
  scene.lights.push_back(l);
  World world(scene);
  Color c = traceOne(world, Ray(Vec3(0, 5, 0), Vec3(0, -1, 0)));
  CHECK(c.r == Approx(0.5 * 0.8).epsilon(1e-6));  // k_d (N.L = 1) I_L, factor 1
  // Far away the formula applies: r = 1 + 2 r^2 ... with c = 2, r = 1: 1/2.
  scene.lights[0].attenuation = Vec3(0.0, 0.0, 2.0);
  World far(scene);
  CHECK(traceOne(far, Ray(Vec3(0, 5, 0), Vec3(0, -1, 0))).r == Approx(0.5 * 0.8 / 2).epsilon(1e-6));
}

TEST_CASE("inside an object the ambient term is multiplied by k_t", "[render][shading]") {
  Scene scene;
  scene.render.ambient = Color(1.0f);
  scene.render.background = Color(0.3f, 0.6f, 0.9f);
  Material glass;
  glass.ambient = Color(0.5f);
  glass.transmissive = Color(0.4f);
  glass.ior = 1.0;  // no bending: the ray goes straight out to the background
  addShape(scene, SphereSpec{Vec3(0), 2.0}, addMaterial(scene, glass));
  World world(scene);
  // From the centre (the camera stands inside the sphere).
  Color inside = traceOne(world, Ray(Vec3(0), Vec3(0, 0, -1)));
  CHECK(inside.r == Approx(0.5 * 0.4 + 0.4 * 0.3).epsilon(1e-6));
  CHECK(inside.b == Approx(0.5 * 0.4 + 0.4 * 0.9).epsilon(1e-6));
  // From outside: the front surface has the full ambient, the back one (seen from
  // inside) the k_t-scaled one, each seen through the surfaces before it.
  Color outside = traceOne(world, Ray(Vec3(0, 0, 5), Vec3(0, 0, -1)));
  CHECK(outside.r == Approx(0.5 + 0.4 * (0.5 * 0.4 + 0.4 * 0.3)).epsilon(1e-6));
}

TEST_CASE("inner-ambient keeps the whole ambient term on the inner side, as POV-Ray",
          "[render][shading]") {
  Scene scene;
  scene.render.ambient = Color(1.0f);
  scene.render.background = Color(0.3f, 0.6f, 0.9f);
  Material wall;  // opaque: without inner-ambient its inner side would be black
  wall.ambient = Color(0.25f, 0.5f, 0.75f);
  wall.innerAmbient = true;
  Material glass;
  glass.ambient = Color(0.5f);
  glass.transmissive = Color(0.4f);
  glass.ior = 1.0;
  glass.innerAmbient = true;
  addShape(scene, SphereSpec{Vec3(0), 2.0}, addMaterial(scene, wall));
  addShape(scene, SphereSpec{Vec3(10, 0, 0), 2.0}, addMaterial(scene, glass));
  World world(scene);
  const Color inWall = traceOne(world, Ray(Vec3(0), Vec3(0, 0, -1)));
  CHECK(inWall.r == Approx(0.25).epsilon(1e-6));
  CHECK(inWall.b == Approx(0.75).epsilon(1e-6));
  // Inside the glass: the full ambient plus what shows through.
  const Color inGlass = traceOne(world, Ray(Vec3(10, 0, 0), Vec3(0, 0, -1)));
  CHECK(inGlass.r == Approx(0.5 + 0.4 * 0.3).epsilon(1e-6));
  CHECK(inGlass.b == Approx(0.5 + 0.4 * 0.9).epsilon(1e-6));
}

TEST_CASE("emissive and ambient with a texture: k_a = ambient * T only for a single-number ambient",
          "[render][shading]") {
  Scene scene;
  scene.render.ambient = Color(1.0f);
  Material m;
  m.ambient = Color(0.5f);
  m.ambientIsScalar = true;
  m.diffuse = Color(1.0f);
  m.texture = CheckerTexture{Color(0.2f, 0.4f, 0.6f), Color(1.0f), 1.0, {}};
  uint32_t scalar = addMaterial(scene, m);
  m.ambient = Color(0.5f, 0.5f, 0.5f);
  m.ambientIsScalar = false;
  uint32_t colour = addMaterial(scene, m);
  addShape(scene, BoxSpec{Vec3(0.1, 0.1, 0.1), Vec3(0.9, 0.9, 0.9)}, scalar);
  addShape(scene, BoxSpec{Vec3(2.1, 0.1, 0.1), Vec3(2.9, 0.9, 0.9)}, colour);
  World world(scene);
  Color a = traceOne(world, Ray(Vec3(0.5, 0.5, 5), Vec3(0, 0, -1)));
  CHECK(a.r == Approx(0.5 * 0.2).epsilon(1e-6));
  CHECK(a.b == Approx(0.5 * 0.6).epsilon(1e-6));
  // The cell [2,3) x [0,1) x [0,1) is even (color1) as well, but a colour ambient ignores T.
  Color b = traceOne(world, Ray(Vec3(2.5, 0.5, 5), Vec3(0, 0, -1)));
  CHECK(b.r == Approx(0.5).epsilon(1e-6));
}
