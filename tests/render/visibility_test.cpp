// image="false", reflection="false" (POV-Ray's no_image, no_reflection with its ray kinds:
// a camera ray and what goes on from it through surfaces without a reflection does not see
// an image="false" object; a reflected ray, and what goes on from it, does not see a
// reflection="false" one; shadow rays see both), double-illuminate (a light behind the
// surface lights it by |N.L|) and interior-material (the surface met from inside).
#include "lit_floor.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lucent;
using namespace lucent::test;

namespace {

const Color kSky(0.0f, 0.0f, 0.5f);
const Color kRed(1.0f, 0.0f, 0.0f);

// A mirror facing +z at z = -0.9, a red ball of emission (0, 0, 3) in front of it and the
// camera between them at (0, 0, 1): looking at the mirror (-z) the camera sees the ball
// reflected; looking at the ball (+z) it sees it directly.
struct MirrorScene {
  Scene scene;
  Node* ball;
  MirrorScene() {
    scene.render.background = kSky;
    Material mirror;
    mirror.reflective = Color(1.0f);
    addShape(scene, BoxSpec{Vec3(-5, -5, -1), Vec3(5, 5, -0.9)}, addMaterial(scene, mirror));
    ball = &addShape(scene, SphereSpec{Vec3(0, 0, 3), 0.5}, addMaterial(scene, emissive(kRed)));
  }
  // A clear sheet across the ray to the ball, z in [1.5, 1.6], of index `ior`.
  void addSheet(double ior) {
    Material clear;
    clear.transmissive = Color(1.0f);
    clear.ior = ior;
    addShape(scene, BoxSpec{Vec3(-5, -5, 1.5), Vec3(5, 5, 1.6)}, addMaterial(scene, clear));
  }
  Color inMirror() {
    World world(scene);
    return traceOne(world, Ray(Vec3(0, 0, 1), Vec3(0, 0, -1)));
  }
  Color direct() {
    World world(scene);
    return traceOne(world, Ray(Vec3(0, 0, 1), Vec3(0, 0, 1)));
  }
};

}  // namespace

TEST_CASE("image=false: not seen by the camera, seen in a mirror", "[render][visibility]") {
  MirrorScene s;
  CHECK(s.direct() == kRed);
  CHECK(s.inMirror() == kRed);
  s.ball->image = false;
  CHECK(s.direct() == kSky);
  CHECK(s.inMirror() == kRed);
}

TEST_CASE("reflection=false: seen by the camera, not in a mirror", "[render][visibility]") {
  MirrorScene s;
  s.ball->reflection = false;
  CHECK(s.direct() == kRed);
  CHECK(s.inMirror() == kSky);
}

TEST_CASE("image=false: rays that went on from the camera through clear sheets do not see it",
          "[render][visibility]") {
  for (double ior : {1.0, 1.5}) {  // the unbent loop and the refracted branch
    INFO("ior " << ior);
    MirrorScene s;
    s.addSheet(ior);
    CHECK(s.direct() == kRed);
    s.ball->image = false;
    CHECK(s.direct() == kSky);
  }
}

TEST_CASE("a reflected ray stays reflected through clear sheets", "[render][visibility]") {
  // The sheet between the camera and the ball also lies on the mirror ray's way back.
  MirrorScene s;
  s.addSheet(1.5);
  s.ball->image = false;
  CHECK(s.inMirror() == kRed);
  s.ball->image = true;
  s.ball->reflection = false;
  CHECK(s.inMirror() == kSky);
}

TEST_CASE("a ray that went through glass and then reflected does not see reflection=false",
          "[render][visibility]") {
  // The camera behind a sheet in front of the mirror: through it, off the mirror, back
  // through it to the ball behind the camera.
  MirrorScene s;
  Material clear;
  clear.transmissive = Color(1.0f);
  clear.ior = 1.5;
  addShape(s.scene, BoxSpec{Vec3(-5, -5, -0.5), Vec3(5, 5, -0.4)}, addMaterial(s.scene, clear));
  s.scene.render.maxDepth = 10;  // four refractions and a reflection
  CHECK(s.inMirror() == kRed);
  s.ball->reflection = false;
  CHECK(s.inMirror() == kSky);
}

TEST_CASE("image=false and reflection=false still cast shadows", "[render][visibility]") {
  LitFloor f;
  Node& hidden = f.add(f.blocker(0.0));
  Node& unreflected = f.add(f.blocker(2.0));
  CHECK(f.fromAbove(0.0) == Color(0.25f));
  hidden.image = false;
  unreflected.reflection = false;
  CHECK(f.fromAbove(0.0) == Color(0.0f));   // the floor, in the hidden box's shadow
  CHECK(f.fromAbove(2.0) == Color(0.25f));  // seen
  CHECK(f.fromAbove(4.0) == Color(1.0f));   // lit floor
}

TEST_CASE("image=false: a union's children keep their own, a difference is seen as a whole",
          "[render][visibility]") {
  LitFloor f;
  auto hidden = f.blocker(0.0);
  hidden->image = false;
  auto u = std::make_unique<Node>();
  u->kind = NodeKind::Union;
  u->children.push_back(std::move(hidden));
  u->children.push_back(f.blocker(2.0));
  f.add(std::move(u));
  CHECK(f.fromAbove(0.0) == Color(0.0f));
  CHECK(f.fromAbove(2.0) == Color(0.25f));

  auto d = std::make_unique<Node>();
  d->kind = NodeKind::Difference;
  d->children.push_back(f.blocker(4.0));
  d->children.push_back(shapeNode(BoxSpec{Vec3(3.9, 2.4, -0.1), Vec3(4.1, 2.6, 0.1)}, f.grey));
  d->children.back()->image = false;  // a part's flag: ignored
  Node& difference = f.add(std::move(d));
  CHECK(f.fromAbove(4.0) == Color(0.25f));
  difference.image = false;
  CHECK(f.fromAbove(4.0) == Color(0.0f));
}

TEST_CASE("image=false: inherited through groups, on unbounded objects too",
          "[render][visibility]") {
  LitFloor f;
  auto group = std::make_unique<Node>();
  group->image = false;
  group->children.push_back(f.blocker(0.0));
  f.add(std::move(group));
  f.scene.root->children.front()->image = false;  // the floor plane
  f.scene.render.background = kSky;
  CHECK(f.fromAbove(0.0) == kSky);
  CHECK(f.fromAbove(4.0) == kSky);
}

TEST_CASE("double-illuminate: a light behind a disc lights it by |N.L|", "[render][visibility]") {
  Scene scene;
  Material paper;
  paper.diffuse = Color(1.0f);
  Node& disc = addShape(scene, DiscSpec{Vec3(0), Vec3(0, 0, 1), 2.0}, addMaterial(scene, paper));
  scene.lights.push_back(pointLight(Vec3(0, 0, -3)));
  auto seen = [&] {
    World world(scene);
    return traceOne(world, Ray(Vec3(1, 0, 4), Vec3(0, 0, -1)));
  };
  CHECK(seen() == Color(0.0f));
  disc.doubleIlluminate = true;
  // At (1, 0, 0) the light lies along (-1, 0, -3)/sqrt(10): |N.L| = 3/sqrt(10).
  const Color c = seen();
  CHECK(c.r == Approx(3.0 / std::sqrt(10.0)).epsilon(1e-6));
  CHECK(c.g == c.r);
  CHECK(c.b == c.r);
}

TEST_CASE("interior-material: the surface met from inside shows it", "[render][visibility]") {
  Scene scene;
  const uint32_t green = addMaterial(scene, emissive(Color(0, 1, 0)));
  const uint32_t blue = addMaterial(scene, emissive(Color(0, 0, 1)));
  Node& ball = addShape(scene, SphereSpec{Vec3(0), 2.0}, green);
  ball.interiorMaterial = blue;
  World world(scene);
  CHECK(traceOne(world, Ray(Vec3(0, 0, 5), Vec3(0, 0, -1))) == Color(0, 1, 0));
  CHECK(traceOne(world, Ray(Vec3(0, 0, 0), Vec3(0, 0, 1))) == Color(0, 0, 1));
}

TEST_CASE("interior-material: shadow rays leaving the solid take its transmission",
          "[render][visibility]") {
  // A lit floor inside an opaque ball whose interior material lets half the light through.
  LitFloor f;
  Material clearInside;
  clearInside.transmissive = Color(0.5f);
  const uint32_t inside = addMaterial(f.scene, clearInside);
  const uint32_t opaque = addMaterial(f.scene, Material());
  Node& ball = addShape(f.scene, SphereSpec{Vec3(0), 2.0}, opaque);
  World dark(f.scene);
  const Ray ray(Vec3(0, 1, 0.5), glm::normalize(Vec3(0, -1, -0.5)));
  CHECK(traceOne(dark, ray) == Color(0.0f));
  ball.interiorMaterial = inside;
  World lit(f.scene);
  CHECK(traceOne(lit, ray) == Color(0.5f));
}
