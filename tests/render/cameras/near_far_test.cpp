// near/far: every projection's primary rays carry them as tmin/tmax, and geometry before
// near or beyond far is not seen in a render through World and Renderer.
#include "camera_checks.h"

#include "../scene_builder.h"
#include "render/renderer.h"

using namespace lucent;
using namespace lucent::camtest;

TEST_CASE("every projection's primary rays have tmin = near and tmax = far", "[cameras][nearfar]") {
  for (CameraType type : {CameraType::Pinhole, CameraType::ThinLens, CameraType::Orthographic,
                          CameraType::Fisheye, CameraType::Panini, CameraType::Lenslet,
                          CameraType::Octahedral, CameraType::Cubemap, CameraType::Fibonacci}) {
    INFO(cameraTypeName(type));
    Camera cam = tiltedCamera(type);
    cam.near = 0.75;
    cam.far = 12.5;
    auto p = makeProjection(cam, 48, 36);
    // A point every type has a ray for: the front face's centre for the cube cross.
    Vec2 film = type == CameraType::Cubemap ? Vec2(18, 18) : Vec2(24.5, 18.5);
    Ray r = rayAt(*p, film, Vec2(0.3, 0.8));
    CHECK(r.tmin == 0.75);
    CHECK(r.tmax == 12.5);
    CHECK(glm::length(r.d) == Approx(1.0).epsilon(1e-15));
  }
}

TEST_CASE("geometry before near or beyond far is not seen", "[cameras][nearfar][render]") {
  using namespace lucent::test;
  Scene scene;
  scene.render.width = 3;
  scene.render.height = 3;
  scene.render.background = Color(0.0f, 0.0f, 1.0f);
  // A red ball spanning distances 4..5 in front of a green one spanning 9..11.
  addShape(scene, SphereSpec{Vec3(0, 0, -4.5), 0.5}, addMaterial(scene, emissive(Color(1, 0, 0))));
  addShape(scene, SphereSpec{Vec3(0, 0, -10), 1.0}, addMaterial(scene, emissive(Color(0, 1, 0))));
  World world(scene);
  // The image pixel that looks straight ahead: the centre of a 3x3 image, the front cell
  // of a 4x3 cube cross, the single pixel of a 1x1 Fibonacci sphere (y_0 = 0, phi_0 = 0).
  auto centreWith = [&](CameraType type, double near, double far) {
    Camera cam;
    cam.type = type;
    cam.fov = 2.0;
    cam.width = 0.1;
    cam.lensesX = cam.lensesY = 1;
    cam.near = near;
    cam.far = far;
    scene.render.width = type == CameraType::Cubemap ? 4 : type == CameraType::Fibonacci ? 1 : 3;
    scene.render.height = type == CameraType::Fibonacci ? 1 : 3;
    Renderer renderer(world, cam);
    return type == CameraType::Fibonacci ? renderer.render().image.at(0, 0)
                                         : renderer.render().image.at(1, 1);
  };
  const Color red(1, 0, 0), green(0, 1, 0), blue(0, 0, 1);
  for (CameraType type : {CameraType::Pinhole, CameraType::ThinLens, CameraType::Orthographic,
                          CameraType::Fisheye, CameraType::Panini, CameraType::Lenslet,
                          CameraType::Octahedral, CameraType::Cubemap, CameraType::Fibonacci}) {
    INFO(cameraTypeName(type));
    CHECK(centreWith(type, 0.0, kInf) == red);
    CHECK(centreWith(type, 5.5, kInf) == green);  // the red ball lies wholly before near
    CHECK(centreWith(type, 0.0, 3.5) == blue);    // both lie beyond far
    CHECK(centreWith(type, 5.5, 8.5) == blue);    // the gap between them
    CHECK(centreWith(type, 0.0, 4.2) == red);     // far cuts through the red ball's front
  }
}
