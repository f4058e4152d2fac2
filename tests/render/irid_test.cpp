// POV-Ray's irid (thin-film interference): the factor 1 + amount·cos(φ/λ) per channel with
// φ = 2π·t·(|N·L| + |N·V|) and λ = 0.70 0.52 0.48, on the light from each light and on the
// mirror ray, against the formula written out here and against POV-Ray 3.7's own pixels
// (docs/povray-semantics.md, "irid": an orthographic view of the plane z = 0 lit by a
// parallel light from <0, 100, -100>, so N·L = 1/√2 and N·V = 1).
#include "scene_builder.h"

#include "render/finish.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lucent;
using namespace lucent::test;

namespace {

const double kWavelengths[3] = {0.70, 0.52, 0.48};

// The factor of one channel, from the formula.
double factor(double amount, double thickness, double cosLight, double cosView, int channel) {
  const double phase = 2.0 * M_PI * thickness * (std::abs(cosLight) + std::abs(cosView));
  return 1.0 + amount * std::cos(phase / kWavelengths[channel]);
}

// The viewer looks along +z at the plane z = 0 (its normal towards the viewer is -z); the
// light comes from <0, 100, -100>.
const Vec3 kNormal(0, 0, -1), kToViewer(0, 0, -1);
const Vec3 kToLight = glm::normalize(Vec3(0, 1, -1));

void checkColor(const Color& c, double r, double g, double b, double margin) {
  CHECK(c.r == Approx(r).margin(margin));
  CHECK(c.g == Approx(g).margin(margin));
  CHECK(c.b == Approx(b).margin(margin));
}

// The scene of the POV-Ray test: the plane z = z0 (0 in POV-Ray's) with `m`, the parallel
// light, no ambient; the colour seen along +z through (x, y).
Color planeSeenAt(const Material& m, double x, double y, double z0 = 0.0) {
  Scene scene;
  scene.render.ambient = Color(0.0f);
  scene.render.background = Color(1.0f);
  scene.cameras.push_back(lookingFrom(Vec3(0, 0, -5), Vec3(0)));
  addShape(scene, PlaneSpec{Vec3(0, 0, -1), -z0}, addMaterial(scene, m));
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = -kToLight;
  scene.lights.push_back(sun);
  World world(scene);
  return traceOne(world, Ray(Vec3(x, y, -5), Vec3(0, 0, 1)));
}

}  // namespace

TEST_CASE("irid multiplies the light of each light by 1 + amount·cos(φ/λ) per channel",
          "[render][finish][irid]") {
  Material m;
  m.diffuse = Color(1.0f);
  m.irid = 0.5;
  m.iridThickness = 0.3;
  const double nl = glm::dot(kNormal, kToLight);
  const Color c =
      surfaceResponse(m, m.diffuse, ShadingPoint{Vec3(0), kNormal, kToViewer}, kToLight);
  for (int i = 0; i < 3; ++i) {
    INFO("channel " << i);
    CHECK(c[i] == Approx(nl * factor(0.5, 0.3, nl, 1.0, i)).epsilon(1e-6));
  }
  // POV-Ray's: 0.66636, 1.0591, 1.0298 (it clips the last two to 1 in its image).
  checkColor(c, 0.66636, 1.0591, 1.0298, 1e-4);
  // Without irid the same surface gives N·L.
  m.irid = 0.0;
  checkColor(surfaceResponse(m, m.diffuse, ShadingPoint{Vec3(0), kNormal, kToViewer}, kToLight), nl,
             nl, nl, 1e-7);
}

TEST_CASE("irid multiplies the highlights too, and is 1 + amount at thickness 0",
          "[render][finish][irid]") {
  // POV-Ray: phong 0.5 irid { 0.3 thickness 0.15 }, the light behind the viewer: R·L = 1.
  Material m;
  m.phong = Color(0.5f);
  m.irid = 0.3;
  m.iridThickness = 0.15;
  const Color c =
      surfaceResponse(m, m.diffuse, ShadingPoint{Vec3(0), kNormal, kToViewer}, kToViewer);
  checkColor(c, 0.36485, 0.36718, 0.39393, 1e-5);
  checkColor(c, 0.3649, 0.3672, 0.3939, 1e-4);  // POV-Ray's pixels

  // No thickness: φ = 0, the same factor 1 + amount on every channel, whatever the angles.
  Material flat;
  flat.diffuse = Color(0.4f);
  flat.irid = 0.5;
  const Color f =
      surfaceResponse(flat, flat.diffuse, ShadingPoint{Vec3(0), kNormal, kToViewer}, kToLight);
  const double nl = glm::dot(kNormal, kToLight);
  checkColor(f, 0.4 * nl * 1.5, 0.4 * nl * 1.5, 0.4 * nl * 1.5, 1e-6);
}

TEST_CASE("irid multiplies the mirror ray's light, with |N·L| = |N·V|", "[render][finish][irid]") {
  // POV-Ray: reflection 0.5 irid { 0.3 thickness 0.2 } over a white background.
  Material m;
  m.reflective = Color(0.5f);
  m.irid = 0.3;
  m.iridThickness = 0.2;
  const ShadingPoint at{Vec3(0), kNormal, kToViewer};
  const SecondaryRays rays = secondaryRays(m, at, true, 1.0, 1.0);
  for (int i = 0; i < 3; ++i) CHECK(rays.mirror[i] == Approx(0.5 * factor(0.3, 0.2, 1, 1, i)));
  checkColor(rays.mirror, 0.3649, 0.5181, 0.5750, 1e-4);  // POV-Ray's pixels
  checkColor(planeSeenAt(m, 0.1, 0.2), 0.3649, 0.5181, 0.5750, 1e-4);

  // Seen at 60 degrees from the normal: φ uses 2·cos 60° = 1.
  const Vec3 tilted(0, std::sqrt(0.75), -0.5);
  const SecondaryRays oblique =
      secondaryRays(m, ShadingPoint{Vec3(0), kNormal, tilted}, true, 1, 1);
  for (int i = 0; i < 3; ++i)
    CHECK(oblique.mirror[i] == Approx(0.5 * factor(0.3, 0.2, 0.5, 0.5, i)).epsilon(1e-6));

  // Totally reflected light is reflected light too: inside glass at 60 degrees.
  Material glass;
  glass.transmissive = Color(1.0f);
  glass.ior = 1.5;
  glass.irid = 0.3;
  glass.iridThickness = 0.2;
  const SecondaryRays tir =
      secondaryRays(glass, ShadingPoint{Vec3(0), kNormal, tilted}, true, 1.5, 1.0);
  CHECK(tir.transmitted == Color(0.0f));
  for (int i = 0; i < 3; ++i)
    CHECK(tir.mirror[i] == Approx(factor(0.3, 0.2, 0.5, 0.5, i)).epsilon(1e-6));
  // Light that passes is not changed.
  const SecondaryRays through = secondaryRays(glass, at, true, 1.0, 1.5);
  CHECK(through.transmitted == Color(1.0f));
  CHECK(through.mirror == Color(0.0f));
}

TEST_CASE("irid through the tracer: POV-Ray's pixels, turbulence at the world point",
          "[render][finish][irid]") {
  Material m;
  m.diffuse = Color(1.0f);
  m.irid = 0.5;
  m.iridThickness = 0.3;
  checkColor(planeSeenAt(m, 0.37, 0.21), 0.66636, 1.0591, 1.0298, 1e-4);

  // POV-Ray: diffuse 0.5 irid { 0.3 thickness 0.4 turbulence 0.7 } seen at <0.37, 0.21, 0>,
  // its value computed in POV-Ray's SDL from f_noise3d there (0.637658).
  Material film;
  film.diffuse = Color(0.5f);
  film.irid = 0.3;
  film.iridThickness = 0.4;
  film.iridTurbulence = 0.7;
  const Color c = planeSeenAt(film, 0.37, 0.21);
  checkColor(c, 0.40841, 0.25654, 0.31873, 2e-5);
  // Elsewhere the thickness, and so the colour, differs.
  const Color other = planeSeenAt(film, 1.37, -0.6);
  CHECK(std::abs(other.g - c.g) > 0.01);
}

TEST_CASE("irid-left-handed takes the film's noise at the world point mirrored in z",
          "[render][finish][irid]") {
  Material film;
  film.diffuse = Color(0.5f);
  film.irid = 0.3;
  film.iridThickness = 0.4;
  film.iridTurbulence = 0.7;
  Material left = film;
  left.iridLeftHanded = true;
  // At z = 0.8 the left-handed film is the right-handed one's at z = -0.8 (POV-Ray's point
  // of an imported scene), and differs from the right-handed one's own there.
  const Color a = planeSeenAt(left, 0.37, 0.21, 0.8);
  const Color b = planeSeenAt(film, 0.37, 0.21, -0.8);
  const Color c = planeSeenAt(film, 0.37, 0.21, 0.8);
  checkColor(a, b.r, b.g, b.b, 1e-6);
  CHECK(std::abs(a.g - c.g) + std::abs(a.r - c.r) > 0.01);
}
