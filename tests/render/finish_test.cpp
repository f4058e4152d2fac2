// The contract's "Finish" (phong, phong-size, brilliance, metallic), pixel by pixel against
// POV-Ray's formulas computed here independently of render/finish.cpp.
#include "scene_builder.h"

#include "render/finish.h"
#include "render/renderer.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

// POV-Ray's metallic reflectivity written out from its documentation's formula: the angle
// in units of a right angle, F = 0.014567225/(x-1.12)^2 - 0.011612903, clamped to [0,1].
double fresnelOfAngle(double cosAngle) {
  const double x = std::acos(cosAngle) / (M_PI / 2);
  const double f = 0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903;
  return std::min(1.0, std::max(0.0, f));
}

glm::dvec3 tint(const glm::dvec3& c, double cosAngle) {
  return glm::dvec3(1.0) + (1.0 - fresnelOfAngle(cosAngle)) * (c - glm::dvec3(1.0));
}

struct Finish {
  glm::dvec3 kd{0.6, 0.4, 0.2}, ks{0.0}, kp{0.0};
  double ns = 30.0, size = 40.0, brilliance = 1.0;
  bool metallic = false;
  bool lightHighlights = true;  // the light's highlights attribute
};

// The expected colour of a sphere of radius R at the origin, seen from (0,0,5), lit by one
// white point light at lightPos, for every pixel of a w x h image; renders and compares.
void checkSphere(const Finish& f, const Vec3& lightPos, int minLit) {
  const int w = 64, h = 48;
  const double R = 1.5, fov = 60.0;
  const Vec3 eye(0, 0, 5);
  Scene scene;
  scene.render.width = w;
  scene.render.height = h;
  scene.render.ambient = Color(0.0f);
  scene.render.background = Color(0.0f);
  scene.cameras.push_back(lookingFrom(eye, Vec3(0), fov));
  Material m;
  m.diffuse = Color(f.kd);
  m.specular = Color(f.ks);
  m.shininess = f.ns;
  m.phong = Color(f.kp);
  m.phongSize = f.size;
  m.brilliance = f.brilliance;
  m.metallic = f.metallic;
  addShape(scene, SphereSpec{Vec3(0), R}, addMaterial(scene, m));
  scene.lights.push_back(pointLight(lightPos));
  scene.lights.back().highlights = f.lightHighlights;
  World world(scene);
  Renderer renderer(world, scene.cameras[0]);
  RenderResult result = renderer.render();

  const double halfW = std::tan(radians(fov / 2)), halfH = halfW * h / w;
  int lit = 0;
  double brightest = 0.0;
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const glm::dvec3 d = glm::normalize(glm::dvec3((2.0 * (i + 0.5) / w - 1.0) * halfW,
                                                     (1.0 - 2.0 * (j + 0.5) / h) * halfH, -1.0));
      const double b = glm::dot(eye, d), c = glm::dot(eye, eye) - R * R;
      const double disc = b * b - c;
      if (disc < 1e-3) continue;  // misses and the silhouette: other tests cover them
      const double t = -b - std::sqrt(disc);
      const glm::dvec3 p = eye + t * d, n = p / R, v = -d;
      const glm::dvec3 l = glm::normalize(glm::dvec3(lightPos) - p);
      const double nl = glm::dot(n, l);
      glm::dvec3 expected(0.0);
      if (nl > 0) {
        expected = f.kd * std::pow(nl, f.brilliance);
        const glm::dvec3 hv = glm::normalize(l + v);
        if (f.lightHighlights && glm::dot(n, hv) > 0) {
          glm::dvec3 s = f.ks * std::pow(glm::dot(n, hv), f.ns);
          if (f.metallic) s *= tint(f.kd, glm::dot(hv, l));
          expected += s;
        }
        const glm::dvec3 r = 2.0 * glm::dot(n, v) * n - v;  // the view mirrored about n
        const double rl = glm::dot(r, l);
        if (f.lightHighlights && rl > 0 && (f.size < 60 || rl > 0.0008)) {
          glm::dvec3 s = f.kp * std::pow(rl, f.size);
          if (f.metallic) s *= tint(f.kd, nl);
          expected += s;
        }
        ++lit;
      }
      brightest = std::max(brightest, expected.r);
      const Color got = result.image.at(i, j);
      INFO("pixel " << i << "," << j);
      CHECK(got.r == Approx(expected.r).margin(2e-5));
      CHECK(got.g == Approx(expected.g).margin(2e-5));
      CHECK(got.b == Approx(expected.b).margin(2e-5));
    }
  }
  CHECK(lit > minLit);
  // Each case reaches a highlight or a bright diffuse region, so a missing term shows.
  CHECK(brightest > 0.5);
}

}  // namespace

TEST_CASE("phong: k_p (R.L)^size with R the mirrored view, per pixel", "[render][finish]") {
  Finish f;
  f.kp = glm::dvec3(0.9, 0.7, 0.5);
  f.size = 25;
  checkSphere(f, Vec3(3, 4, 6), 600);
  // A size of 60 or more drops the far tail below 0.0008, as POV-Ray does.
  f.size = 80;
  checkSphere(f, Vec3(-2, 1, 7), 600);
}

TEST_CASE("a light with highlights=\"false\" gives the diffuse term alone, per pixel",
          "[render][finish]") {
  // POV-Ray's shadowless light: neither the phong nor the specular highlight.
  Finish f;
  f.kd = glm::dvec3(0.9, 0.8, 0.7);
  f.ks = glm::dvec3(0.8);
  f.kp = glm::dvec3(0.9, 0.7, 0.5);
  f.size = 25;
  f.lightHighlights = false;
  checkSphere(f, Vec3(3, 4, 6), 600);
}

TEST_CASE("brilliance: k_d (N.L)^brilliance, per pixel", "[render][finish]") {
  Finish f;
  f.kd = glm::dvec3(0.9, 0.8, 0.7);
  f.brilliance = 4.0;
  checkSphere(f, Vec3(2, 2, 6), 600);
  f.brilliance = 0.3;
  checkSphere(f, Vec3(2, 2, 6), 600);
}

TEST_CASE("metallic: specular and phong highlights take the diffuse colour", "[render][finish]") {
  Finish f;
  f.kd = glm::dvec3(0.9, 0.6, 0.1);
  f.ks = glm::dvec3(0.8);
  f.ns = 15;
  f.kp = glm::dvec3(0.7);
  f.size = 10;
  f.metallic = true;
  checkSphere(f, Vec3(4, 3, 5), 600);
}

TEST_CASE("metallic reflectivity is POV-Ray's empirical curve", "[render][finish]") {
  // Normal incidence: x = 0, F = 0.014567225/1.2544 - 0.011612903 = 0 (to 1e-9).
  CHECK(metallicReflectivity(1.0) == Approx(0.0).margin(1e-8));
  // Grazing: x = 1, F = 0.014567225/0.0144 - 0.011612903 = 0.99999994 (the constants
  // were chosen to reach 1 there).
  CHECK(metallicReflectivity(0.0) == Approx(0.014567225 / 0.0144 - 0.011612903).epsilon(1e-12));
  CHECK(metallicReflectivity(0.0) == Approx(1.0).margin(1e-6));
  // 60 degrees: x = 2/3.
  const double x = 2.0 / 3.0;
  CHECK(metallicReflectivity(0.5) ==
        Approx(0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903).epsilon(1e-12));
}

TEST_CASE("metallic without a highlight changes nothing, and the defaults give plain diffuse",
          "[render][finish]") {
  Material plain;
  plain.diffuse = Color(0.5f);
  Material metal = plain;
  metal.metallic = true;
  const Vec3 n(0, 0, 1), v(0, 0, 1), l = glm::normalize(Vec3(0.3, 0.2, 1));
  const Color a = surfaceResponse(plain, plain.diffuse, ShadingPoint{Vec3(0), n, v}, l);
  const Color b = surfaceResponse(metal, metal.diffuse, ShadingPoint{Vec3(0), n, v}, l);
  CHECK(a == b);
  CHECK(a.r == Approx(0.5 * l.z).epsilon(1e-6));
}
