// Small scenes built from the importer's structs (sdl/pov_*.h) and rendered by Lucent,
// held to POV-Ray's image of the same scene written by hand, with the gallery's bounds.
// The geometry is read from XML already in Lucent's space (z negated); the camera, lights,
// materials and settings come from the structs.
#include "pov_meaning_support.h"

#include "sdl/pov_camera.h"
#include "sdl/pov_finish.h"
#include "sdl/pov_light.h"
#include "sdl/pov_settings.h"

using namespace lucent;
using namespace lucent::sdl;
using namespace lucent::test;

namespace {

const char* const kHeader = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n";

PovPigment rgb(float r, float g, float b) {
  PovPigment p;
  p.color = Color(r, g, b);
  return p;
}

void setMaterial(Scene& scene, const std::string& id, const PovPigment& pigment,
                 const PovFinish& finish = {}, const PovInterior& interior = {}) {
  const MaterialImport imported = importMaterial(pigment, finish, interior);
  for (const std::string& note : imported.differences) UNSCOPED_INFO(id << ": " << note);
  Material& m = materialNamed(scene, id);
  m = imported.material;
  m.id = id;
}

void setCamera(Scene& scene, const sdl::PovCamera& camera) {
  const CameraImport imported = importCamera(camera, scene.render.width, scene.render.height);
  REQUIRE(imported.error.empty());
  for (const std::string& note : imported.differences) UNSCOPED_INFO("camera: " << note);
  scene.cameras = {imported.camera};
}

void addLight(Scene& scene, const PovLight& light) {
  const LightImport imported = importLight(light);
  for (const std::string& note : imported.differences) UNSCOPED_INFO("light: " << note);
  scene.lights.push_back(imported.light);
}

// Three spheres on a floor, with placeholder materials a, b, floor.
const char* const kSpheresXml = R"XML(
  <material id="a" diffuse="1"/><material id="b" diffuse="1"/><material id="floor" diffuse="1"/>
  <sphere center="0 0 -4" radius="1.2" material="a"/>
  <sphere center="1.8 -0.5 -6" radius="0.7" material="b"/>
  <sphere center="-2 -0.6 -7" radius="0.6" material="b"/>
  <plane normal="0 1 0" offset="-1.2" material="floor"/>)XML";
const char* const kSpheresPov = R"POV(
sphere { <0, 0, 4>, 1.2 pigment { rgb <0.9, 0.3, 0.2> } }
sphere { <1.8, -0.5, 6>, 0.7 pigment { rgb <0.2, 0.5, 0.9> } }
sphere { <-2, -0.6, 7>, 0.6 pigment { rgb <0.2, 0.5, 0.9> } }
plane { y, -1.2 pigment { rgb <0.7, 0.7, 0.6> } }
)POV";

void defaultSpheres(Scene& scene) {
  setMaterial(scene, "a", rgb(0.9f, 0.3f, 0.2f));
  setMaterial(scene, "b", rgb(0.2f, 0.5f, 0.9f));
  setMaterial(scene, "floor", rgb(0.7f, 0.7f, 0.6f));
}

}  // namespace

TEST_CASE("a scene without a camera is seen by POV-Ray's default camera", "[sdl][image][povray]") {
  // 133 x 100: the default right <1.33,0,0> and up <0,1,0> make square pixels.
  auto scene = geometryScene(kSpheresXml, 133, 100);
  defaultSpheres(*scene);
  setCamera(*scene, sdl::PovCamera{});
  PovLight light;
  light.location = Vec3(-4.0, 6.0, -3.0);
  addLight(*scene, light);
  requireSameImage(
      *scene, std::string(kHeader) + "light_source { <-4, 6, -3> color rgb 1 }\n" + kSpheresPov);
}

TEST_CASE("POV-Ray's default camera on a 4:3 image: its frame kept, pixels 0.25 % off square",
          "[sdl][image][povray]") {
  auto scene = geometryScene(kSpheresXml, 160, 120);
  defaultSpheres(*scene);
  const CameraImport camera = importCamera(sdl::PovCamera{}, 160, 120);
  CHECK(camera.differences.empty());
  CHECK(camera.camera.frameAspect == Approx(1.33).epsilon(1e-15));
  setCamera(*scene, sdl::PovCamera{});
  PovLight light;
  light.location = Vec3(-4.0, 6.0, -3.0);
  addLight(*scene, light);
  // POV-Ray's own default camera spans 0.251 % more of the height than square pixels would;
  // Lucent's frame-aspect 1.33 does the same (37.9 dB without it).
  requireSameImage(
      *scene, std::string(kHeader) + "light_source { <-4, 6, -3> color rgb 1 }\n" + kSpheresPov);
}

TEST_CASE("a wide image with right, up, angle, sky and look_at", "[sdl][image][povray]") {
  auto scene = geometryScene(kSpheresXml, 200, 100);
  defaultSpheres(*scene);
  sdl::PovCamera camera;
  camera.location = Vec3(1.0, 2.0, -3.0);
  camera.right = Vec3(2.0, 0.0, 0.0);
  camera.rightGiven = true;
  camera.upGiven = true;
  camera.angle = 70.0;
  camera.sky = Vec3(0.2, 1.0, 0.0);
  camera.lookAt = Vec3(0.0, -0.3, 5.0);
  setCamera(*scene, camera);
  PovLight light;
  light.location = Vec3(3.0, 5.0, -4.0);
  addLight(*scene, light);
  requireSameImage(*scene, std::string(kHeader) +
                               "camera { location <1, 2, -3> right x*2 up y angle 70 "
                               "sky <0.2, 1, 0> look_at <0, -0.3, 5> }\n"
                               "light_source { <3, 5, -4> color rgb 1 }\n" +
                               kSpheresPov);
}

TEST_CASE("an orthographic camera sized by its look_at distance", "[sdl][image][povray]") {
  auto scene = geometryScene(kSpheresXml, 133, 100);
  defaultSpheres(*scene);
  sdl::PovCamera camera;
  camera.type = PovCameraType::Orthographic;
  camera.location = Vec3(0.0, 3.0, -4.0);
  camera.lookAt = Vec3(0.0, 0.0, 4.0);
  setCamera(*scene, camera);
  PovLight light;
  light.location = Vec3(-4.0, 6.0, -3.0);
  addLight(*scene, light);
  requireSameImage(*scene, std::string(kHeader) +
                               "camera { orthographic location <0, 3, -4> look_at <0, 0, 4> }\n"
                               "light_source { <-4, 6, -3> color rgb 1 }\n" +
                               kSpheresPov);
}

TEST_CASE("a spotlight with radius, falloff and point_at", "[sdl][image][povray]") {
  auto scene = geometryScene(kSpheresXml, 160, 120);
  defaultSpheres(*scene);
  sdl::PovCamera camera;
  camera.location = Vec3(0.0, 2.0, -3.0);
  camera.right = Vec3(4.0 / 3.0, 0.0, 0.0);
  camera.rightGiven = true;
  camera.lookAt = Vec3(0.0, -0.5, 5.0);
  setCamera(*scene, camera);
  PovLight spot;
  spot.kind = PovLightKind::Spotlight;
  spot.location = Vec3(2.0, 6.0, 1.0);
  spot.pointAt = Vec3(0.0, -1.2, 5.0);
  spot.radius = 12.0;
  spot.falloff = 22.0;
  spot.color = Color(1.0f, 0.95f, 0.8f);
  addLight(*scene, spot);
  requireSameImage(*scene, std::string(kHeader) +
                               "camera { location <0, 2, -3> right x*4/3 look_at <0, -0.5, 5> }\n"
                               "light_source { <2, 6, 1> color rgb <1, 0.95, 0.8> spotlight "
                               "point_at <0, -1.2, 5> radius 12 falloff 22 }\n" +
                               kSpheresPov);
}

TEST_CASE("an area light's soft shadows", "[sdl][image][povray]") {
  auto scene = geometryScene(kSpheresXml, 160, 120);
  defaultSpheres(*scene);
  sdl::PovCamera camera;
  camera.location = Vec3(0.0, 2.5, -2.0);
  camera.right = Vec3(4.0 / 3.0, 0.0, 0.0);
  camera.rightGiven = true;
  camera.lookAt = Vec3(0.0, -0.8, 5.0);
  setCamera(*scene, camera);
  PovLight area;
  area.location = Vec3(-3.0, 5.0, 2.0);
  area.area = PovAreaLight{
      Vec3(3.0, 0.0, 0.0), Vec3(0.0, 0.0, 3.0), 4, 4, std::nullopt, false, false, false};
  addLight(*scene, area);
  requireSameImage(*scene, std::string(kHeader) +
                               "camera { location <0, 2.5, -2> right x*4/3 look_at <0, -0.8, 5> }\n"
                               "light_source { <-3, 5, 2> color rgb 1 "
                               "area_light <3, 0, 0>, <0, 0, 3>, 4, 4 }\n" +
                               kSpheresPov);
}

TEST_CASE("a finish with ambient, diffuse, brilliance, phong, specular and reflection",
          "[sdl][image][povray]") {
  auto scene = geometryScene(kSpheresXml, 160, 120);
  PovFinish shiny;
  shiny.ambient = Color(0.2f, 0.15f, 0.1f);
  shiny.diffuse = 0.7;
  shiny.brilliance = 2.0;
  shiny.phong = 0.8;
  shiny.phongSize = 60.0;
  shiny.specular = 0.3;
  shiny.roughness = 0.02;
  shiny.reflection.min = shiny.reflection.max = Color(0.3f);
  setMaterial(*scene, "a", rgb(0.9f, 0.3f, 0.2f), shiny);
  setMaterial(*scene, "b", rgb(0.2f, 0.5f, 0.9f));
  PovFinish floor;
  floor.reflection.min = floor.reflection.max = Color(0.2f, 0.25f, 0.3f);
  setMaterial(*scene, "floor", rgb(0.7f, 0.7f, 0.6f), floor);
  PovGlobalSettings settings;
  settings.ambientLight = Color(0.8f, 0.9f, 1.0f);
  settings.maxTraceLevel = 4;
  CHECK(
      applyGlobalSettings(settings, PovBackground{Color(0.1f, 0.1f, 0.2f)}, scene->render).empty());
  sdl::PovCamera camera;
  camera.location = Vec3(0.5, 1.0, -2.0);
  camera.right = Vec3(4.0 / 3.0, 0.0, 0.0);
  camera.rightGiven = true;
  camera.lookAt = Vec3(0.0, 0.0, 4.0);
  setCamera(*scene, camera);
  PovLight light;
  light.location = Vec3(-4.0, 6.0, -3.0);
  addLight(*scene, light);
  requireSameImage(*scene, R"POV(#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <0.8, 0.9, 1> max_trace_level 4 }
background { rgb <0.1, 0.1, 0.2> }
camera { location <0.5, 1, -2> right x*4/3 look_at <0, 0, 4> }
light_source { <-4, 6, -3> color rgb 1 }
sphere { <0, 0, 4>, 1.2 pigment { rgb <0.9, 0.3, 0.2> }
  finish { ambient rgb <0.2, 0.15, 0.1> diffuse 0.7 brilliance 2 phong 0.8 phong_size 60
           specular 0.3 roughness 0.02 reflection 0.3 } }
sphere { <1.8, -0.5, 6>, 0.7 pigment { rgb <0.2, 0.5, 0.9> } }
sphere { <-2, -0.6, 7>, 0.6 pigment { rgb <0.2, 0.5, 0.9> } }
plane { y, -1.2 pigment { rgb <0.7, 0.7, 0.6> } finish { reflection rgb <0.2, 0.25, 0.3> } }
)POV");
}

TEST_CASE("a transparent sphere with an ior refracts as POV-Ray's", "[sdl][image][povray]") {
  auto scene = geometryScene(kSpheresXml, 160, 120);
  PovPigment glass = rgb(1.0f, 1.0f, 1.0f);
  glass.filter = 1.0f;
  PovFinish glassFinish;
  glassFinish.ambient = Color(0.0f);
  glassFinish.diffuse = 0.0;
  glassFinish.phong = 0.6;
  glassFinish.phongSize = 80.0;
  PovInterior interior;
  interior.ior = 1.5;
  setMaterial(*scene, "a", glass, glassFinish, interior);
  setMaterial(*scene, "b", rgb(0.2f, 0.5f, 0.9f));
  setMaterial(*scene, "floor", rgb(0.7f, 0.7f, 0.6f));
  sdl::PovCamera camera;
  camera.location = Vec3(0.0, 0.6, -1.5);
  camera.right = Vec3(4.0 / 3.0, 0.0, 0.0);
  camera.rightGiven = true;
  camera.lookAt = Vec3(0.3, -0.2, 5.0);
  setCamera(*scene, camera);
  PovLight light;
  light.location = Vec3(-4.0, 6.0, -3.0);
  addLight(*scene, light);
  requireSameImage(*scene, std::string(kHeader) + R"POV(
camera { location <0, 0.6, -1.5> right x*4/3 look_at <0.3, -0.2, 5> }
light_source { <-4, 6, -3> color rgb 1 }
sphere { <0, 0, 4>, 1.2 pigment { rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 phong 0.6 phong_size 80 } interior { ior 1.5 } }
sphere { <1.8, -0.5, 6>, 0.7 pigment { rgb <0.2, 0.5, 0.9> } }
sphere { <-2, -0.6, 7>, 0.6 pigment { rgb <0.2, 0.5, 0.9> } }
plane { y, -1.2 pigment { rgb <0.7, 0.7, 0.6> } }
)POV");
}

TEST_CASE("fisheye and spherical cameras make POV-Ray's images", "[sdl][image][povray]") {
  PovLight light;
  light.location = Vec3(-4.0, 6.0, -3.0);
  const std::string lightPov = "light_source { <-4, 6, -3> color rgb 1 }\n";
  {
    // The image circle across the width: the corners are black in both.
    auto scene = geometryScene(kSpheresXml, 160, 120);
    defaultSpheres(*scene);
    sdl::PovCamera camera;
    camera.type = PovCameraType::Fisheye;
    camera.angle = 160.0;
    camera.right = Vec3(1.0, 0.0, 0.0);
    camera.up = Vec3(0.0, 0.75, 0.0);
    camera.location = Vec3(0.0, 0.5, 0.0);
    camera.lookAt = Vec3(0.0, -0.5, 5.0);
    setCamera(*scene, camera);
    addLight(*scene, light);
    requireSameImage(*scene, std::string(kHeader) +
                                 "camera { fisheye angle 160 right x up y*0.75 location <0, 0.5, "
                                 "0> look_at <0, -0.5, 5> }\n" +
                                 lightPov + kSpheresPov);
  }
  {
    auto scene = geometryScene(kSpheresXml, 160, 80);
    defaultSpheres(*scene);
    sdl::PovCamera camera;
    camera.type = PovCameraType::Spherical;
    camera.angle = 240.0;
    camera.verticalAngle = 120.0;
    camera.location = Vec3(0.0, 0.5, 0.0);
    camera.lookAt = Vec3(0.3, 0.0, 5.0);
    setCamera(*scene, camera);
    addLight(*scene, light);
    requireSameImage(*scene, std::string(kHeader) +
                                 "camera { spherical angle 240, 120 location <0, 0.5, 0> "
                                 "look_at <0.3, 0, 5> }\n" +
                                 lightPov + kSpheresPov);
  }
}
