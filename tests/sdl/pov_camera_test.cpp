// POV-Ray's camera (sdl/pov_camera.h): its modifiers as POV-Ray applies them, the Lucent
// camera that traces POV-Ray's rays, the round trip through the exporter, and images
// against POV-Ray's.
#include "pov_meaning_support.h"

#include "povray/pov_export.h"
#include "render/projection.h"
#include "sdl/pov_camera.h"

#include <regex>

using namespace lucent;
using namespace lucent::sdl;
using namespace lucent::test;

namespace {

// Lucent's ray through the centre of pixel (i, j).
Ray lucentRay(const Camera& camera, int i, int j, int width, int height) {
  auto projection = makeProjection(camera, width, height);
  Ray ray;
  REQUIRE(projection->generateRay(Vec2(i + 0.5, j + 0.5), Vec2(0.5), ray));
  return ray;
}

void requireSameVector(const Vec3& a, const Vec3& b, double tolerance = 1e-12) {
  INFO("<" << a.x << ", " << a.y << ", " << a.z << "> vs <" << b.x << ", " << b.y << ", " << b.z
           << ">");
  CHECK(glm::length(a - b) <= tolerance * (1.0 + glm::length(b)));
}

// Every few pixels of the image: the imported camera's ray is POV-Ray's, mirrored into
// Lucent's space.
void requirePovRays(const sdl::PovCamera& pov, int width, int height) {
  const CameraImport imported = importCamera(pov, width, height);
  REQUIRE(imported.error.empty());
  const PovCameraVectors v = povCameraVectors(pov);
  for (int j = 0; j < height; j += 7)
    for (int i = 0; i < width; i += 9) {
      Vec3 origin, direction;
      if (!povPrimaryRay(pov, v, i, j, width, height, origin, direction)) continue;
      const Ray ray = lucentRay(imported.camera, i, j, width, height);
      requireSameVector(ray.o, lucentFromPov(origin));
      requireSameVector(ray.d, lucentFromPov(direction));
    }
}

}  // namespace

TEST_CASE("POV-Ray's default camera: right 1.33, up 1, direction 1 along +z", "[sdl][camera]") {
  const sdl::PovCamera pov;
  const PovCameraVectors v = povCameraVectors(pov);
  CHECK(v.right == Vec3(1.33, 0.0, 0.0));
  CHECK(v.up == Vec3(0.0, 1.0, 0.0));
  CHECK(v.direction == Vec3(0.0, 0.0, 1.0));
  // 2·atan(1.33/2): the horizontal field of view; looking down Lucent's -z.
  const CameraImport imported = importCamera(pov, 320, 240);
  CHECK(imported.camera.type == CameraType::Pinhole);
  CHECK(imported.camera.fov == Approx(2.0 * std::atan(0.665) * 180.0 / kPi).epsilon(1e-14));
  CHECK(imported.camera.lookAt - imported.camera.position == Vec3(0.0, 0.0, -1.0));
  // 1.33 is not 320/240: POV-Ray's pixels are 0.25 % wider than tall, which the camera's
  // frame-aspect reproduces: POV-Ray's rays at every size, nothing to say.
  CHECK(imported.differences.empty());
  CHECK(imported.camera.frameAspect == Approx(1.33).epsilon(1e-15));
  requirePovRays(pov, 320, 240);
  requirePovRays(pov, 133, 100);
  requirePovRays(pov, 100, 300);
}

TEST_CASE("angle sets |direction| from |right|, look_at turns the vectors keeping lengths",
          "[sdl][camera]") {
  sdl::PovCamera pov;
  pov.location = Vec3(1.0, 2.0, -5.0);
  pov.right = Vec3(4.0 / 3.0, 0.0, 0.0);
  pov.rightGiven = true;
  pov.up = Vec3(0.0, 2.0, 0.0);
  pov.upGiven = true;
  pov.angle = 60.0;
  pov.lookAt = Vec3(0.0, 1.0, 0.0);
  const PovCameraVectors v = povCameraVectors(pov);
  // |direction| = |right| / (2 tan(angle/2))
  CHECK(glm::length(v.direction) == Approx((4.0 / 3.0) / (2.0 * std::tan(radians(30.0)))));
  CHECK(glm::length(v.right) == Approx(4.0 / 3.0));
  CHECK(glm::length(v.up) == Approx(2.0));
  requireSameVector(glm::normalize(v.direction), glm::normalize(Vec3(-1.0, -1.0, 5.0)));
  // POV-Ray's frame stays left-handed: (up × direction)·right > 0.
  CHECK(glm::dot(glm::cross(v.up, v.direction), v.right) > 0.0);
  CHECK(glm::dot(v.right, v.up) == Approx(0.0).margin(1e-12));
  CHECK(glm::dot(v.right, v.direction) == Approx(0.0).margin(1e-12));
  // Written with up 2 for a 4:3 right: POV-Ray's pixels are twice as tall as wide, which
  // the camera's frame-aspect keeps: POV-Ray's rays.
  const CameraImport imported = importCamera(pov, 160, 120);
  CHECK(imported.differences.empty());
  CHECK(imported.camera.fov == Approx(60.0).epsilon(1e-12));
  CHECK(imported.camera.frameAspect == Approx(2.0 / 3.0).epsilon(1e-15));
  requirePovRays(pov, 160, 120);

  // With right/up matching the image, every ray is POV-Ray's.
  pov.up = Vec3(0.0, 1.0, 0.0);
  CHECK(importCamera(pov, 160, 120).differences.empty());
  requirePovRays(pov, 160, 120);
}

TEST_CASE("sky tilts the camera and the camera's transforms apply after look_at", "[sdl][camera]") {
  sdl::PovCamera pov;
  pov.location = Vec3(0.0, 0.0, -4.0);
  pov.right = Vec3(1.6, 0.0, 0.0);
  pov.rightGiven = true;
  pov.sky = Vec3(1.0, 1.0, 0.0);
  pov.lookAt = Vec3(0.0, 0.0, 0.0);
  pov.transform.rotate(Vec3(0.0, 30.0, 0.0)).translate(Vec3(1.0, 0.5, 0.0));
  const PovCameraVectors v = povCameraVectors(pov);
  // The transform moves the location after look_at aimed the camera at the origin.
  requireSameVector(v.location, pov.transform.point(Vec3(0.0, 0.0, -4.0)));
  requireSameVector(glm::normalize(v.direction),
                    glm::normalize(pov.transform.vector(Vec3(0, 0, 1))));
  // Up leans towards the sky (right = sky × direction, up = direction × right).
  requireSameVector(glm::normalize(v.up),
                    glm::normalize(pov.transform.vector(Vec3(1.0, 1.0, 0.0))));
  requirePovRays(pov, 160, 100);
}

TEST_CASE("an orthographic camera without right and up is sized by the look_at distance",
          "[sdl][camera]") {
  sdl::PovCamera pov;
  pov.type = PovCameraType::Orthographic;
  pov.location = Vec3(0.0, 0.0, -10.0);
  pov.lookAt = Vec3(0.0, 0.0, 0.0);
  PovCameraVectors v = povCameraVectors(pov);
  CHECK(glm::length(v.right) == Approx(13.3));
  CHECK(glm::length(v.up) == Approx(10.0));
  // With angle: the width is 2·distance·tan(angle/2), whatever right says.
  pov.angle = 90.0;
  pov.right = Vec3(4.0 / 3.0, 0.0, 0.0);
  pov.rightGiven = true;
  v = povCameraVectors(pov);
  CHECK(glm::length(v.right) == Approx(20.0));
  // With right and up and no angle: as written.
  pov.angle.reset();
  pov.up = Vec3(0.0, 3.0, 0.0);
  pov.upGiven = true;
  pov.right = Vec3(4.0, 0.0, 0.0);
  v = povCameraVectors(pov);
  CHECK(glm::length(v.right) == Approx(4.0));
  const CameraImport imported = importCamera(pov, 160, 120);
  CHECK(imported.camera.type == CameraType::Orthographic);
  CHECK(imported.camera.width == Approx(4.0));
  CHECK(imported.differences.empty());
  requirePovRays(pov, 160, 120);
}

TEST_CASE("fisheye and spherical cameras trace POV-Ray's rays", "[sdl][camera]") {
  sdl::PovCamera fish;
  fish.type = PovCameraType::Fisheye;
  fish.angle = 180.0;
  fish.right = Vec3(1.0, 0.0, 0.0);
  fish.up = Vec3(0.0, 0.75, 0.0);
  fish.location = Vec3(0.0, 1.0, 0.0);
  fish.lookAt = Vec3(0.0, 1.0, 3.0);
  const CameraImport f = importCamera(fish, 160, 120);
  CHECK(f.differences.empty());
  CHECK(f.camera.fovAxis == FovAxis::Horizontal);
  CHECK(f.camera.fov == Approx(180.0));
  requirePovRays(fish, 160, 120);

  sdl::PovCamera sphere;
  sphere.type = PovCameraType::Spherical;
  sphere.angle = 270.0;
  sphere.verticalAngle = 120.0;
  sphere.location = Vec3(0.5, 1.0, -2.0);
  sphere.lookAt = Vec3(1.0, 1.5, 0.0);
  CHECK(importCamera(sphere, 160, 80).differences.empty());
  requirePovRays(sphere, 160, 80);
}

// Where POV-Ray traces no ray (outside the omnimax's circle), Lucent has none either.
static void requireSameCoverage(const sdl::PovCamera& pov, int width, int height) {
  const CameraImport imported = importCamera(pov, width, height);
  REQUIRE(imported.error.empty());
  const PovCameraVectors v = povCameraVectors(pov);
  const auto projection = makeProjection(imported.camera, width, height);
  int without = 0;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      Vec3 origin, direction;
      Ray ray;
      const bool povHasRay = povPrimaryRay(pov, v, i, j, width, height, origin, direction);
      CHECK(projection->generateRay(Vec2(i + 0.5, j + 0.5), Vec2(0.5), ray) == povHasRay);
      without += povHasRay ? 0 : 1;
    }
  CHECK(without > 0);
}

TEST_CASE("ultra_wide_angle, cylinder 1-4, panoramic and omnimax import with POV-Ray's rays",
          "[sdl][camera]") {
  // The sample scenes' form: right x*image_width/image_height, look_at, POV-Ray's default
  // angle 90 where none is written; then right -x, a scaled transform and odd lengths.
  for (const PovCameraType type : {PovCameraType::UltraWideAngle, PovCameraType::Cylinder,
                                   PovCameraType::Panoramic, PovCameraType::Omnimax})
    for (int cylinder = 1; cylinder <= (type == PovCameraType::Cylinder ? 4 : 1); ++cylinder) {
      INFO("type " << static_cast<int>(type) << " cylinder " << cylinder);
      sdl::PovCamera pov;
      pov.type = type;
      pov.cylinderType = cylinder;
      pov.location = Vec3(5.0, 3.0, 8.0);
      pov.lookAt = Vec3(0.0, 4.0, 2.0);
      pov.right = Vec3(320.0 / 240.0, 0.0, 0.0);
      pov.rightGiven = true;
      requirePovRays(pov, 320, 240);
      CHECK(importCamera(pov, 320, 240).differences.empty());
      pov.angle = 220.0;
      requirePovRays(pov, 320, 240);
      requirePovRays(pov, 100, 300);

      pov.right = Vec3(-2.5, 0.0, 0.0);
      pov.up = Vec3(0.0, 0.7, 0.0);
      pov.direction = Vec3(0.0, 0.0, 1.6);
      pov.sky = Vec3(0.2, 1.0, -0.1);
      pov.transform =
          PovTransform::scaling(Vec3(1.5)).then(PovTransform::rotation(Vec3(10.0, 30.0, 0.0)));
      const CameraImport imported = importCamera(pov, 200, 100);
      REQUIRE(imported.error.empty());
      CHECK(imported.camera.mirror);
      CHECK(imported.differences.empty());
      requirePovRays(pov, 200, 100);
    }
}

TEST_CASE("omnimax: POV-Ray's pixels without a ray are Lucent's, for narrow and wide frames",
          "[sdl][camera]") {
  sdl::PovCamera pov;
  pov.type = PovCameraType::Omnimax;
  // |right|/|up| below 1, between 1 and 1.283458, and above.
  for (const double right : {0.8, 1.0, 1.2, 1.33, 2.0}) {
    INFO("right " << right);
    pov.right = Vec3(right, 0.0, 0.0);
    requireSameCoverage(pov, 64, 48);
    requirePovRays(pov, 64, 48);
  }
}

TEST_CASE("POV-Ray's cylinder camera types are 1 to 4, its angle below 360 in Lucent",
          "[sdl][camera]") {
  sdl::PovCamera pov;
  pov.type = PovCameraType::Cylinder;
  pov.angle = 400.0;
  CHECK(importCamera(pov, 160, 120).error ==
        "cylinder: angle 400 is outside Lucent's range (above 0, at most 360)");
  pov.type = PovCameraType::UltraWideAngle;
  CHECK(importCamera(pov, 160, 120).error ==
        "ultra_wide_angle: angle 400 is outside Lucent's range (above 0, at most 360)");
}

TEST_CASE("direction, up and right that are not perpendicular skew the image as POV-Ray's do",
          "[sdl][camera]") {
  // objects/quartic/witch.pov's camera: the direction leans up, right and up stay on the axes.
  sdl::PovCamera pov;
  pov.location = Vec3(0.0, 0.0, -3.0);
  pov.direction = Vec3(0.0, 0.1, 1.5);
  pov.right = Vec3(4.0 / 3.0, 0.0, 0.0);
  pov.rightGiven = true;
  CameraImport imported = importCamera(pov, 160, 120);
  CHECK(imported.differences.empty());
  REQUIRE(imported.camera.imagePlane);
  // Right is along the frame's own right; up has a part along the view (up·direction over
  // |direction|², as the plane is at distance 1).
  CHECK(imported.camera.imagePlane->right.y == Approx(0.0).margin(1e-15));
  CHECK(imported.camera.imagePlane->up.z == Approx(0.1 / (0.01 + 2.25)).epsilon(1e-14));
  requirePovRays(pov, 160, 120);
  requirePovRays(pov, 90, 200);

  // camera/shear.pov's kind: a matrix shears right into up; and a `right -x` camera.
  pov.direction = Vec3(0.0, 0.0, 1.0);
  pov.transform = pov.transform.then(
      sdl::PovTransform::matrix({1.0, 0.0, 0.0, 0.3, 1.0, 0.2, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0}));
  requirePovRays(pov, 160, 120);
  pov.right = Vec3(-4.0 / 3.0, 0.0, 0.0);
  requirePovRays(pov, 160, 120);

  // Orthographic: origins on a parallelogram, all along the direction.
  pov.type = PovCameraType::Orthographic;
  pov.up = Vec3(0.0, 3.0, 0.5);
  pov.upGiven = true;
  imported = importCamera(pov, 160, 120);
  CHECK(imported.differences.empty());
  REQUIRE(imported.camera.imagePlane);
  requirePovRays(pov, 160, 120);

  // A fisheye cannot skew: said.
  pov.type = PovCameraType::Fisheye;
  imported = importCamera(pov, 160, 120);
  REQUIRE(!imported.differences.empty());
  CHECK(imported.differences[0].find("not perpendicular") != std::string::npos);
}

TEST_CASE("round trip: a Lucent camera exported to POV-Ray and read back traces its rays",
          "[sdl][camera][povray]") {
  // The exporter's camera block for a Lucent camera (world coordinates unchanged,
  // `right -x*W/H` making POV-Ray's frame right-handed).
  ParseResult parsed = parseSceneString(R"XML(<scene version="1">
      <render width="160" height="120"/>
      <camera position="1 2 6" look-at="0 0.5 0" up="0 1 0" fov="50"/>
      <sphere radius="1"/></scene>)XML",
                                        "test.xml");
  REQUIRE(parsed.scene);
  const Camera& original = parsed.scene->cameras.front();
  const PovExport exported = exportPov(*parsed.scene);
  REQUIRE(exported.ok());
  INFO(exported.text);
  auto number = [&](const std::string& pattern) {
    std::smatch m;
    REQUIRE(std::regex_search(exported.text, m, std::regex(pattern)));
    return m;
  };
  auto vec = [](const std::smatch& m, int first) {
    return Vec3(std::stod(m[first]), std::stod(m[first + 1]), std::stod(m[first + 2]));
  };
  const std::string v3 = "<([-0-9.e]+), ([-0-9.e]+), ([-0-9.e]+)>";
  sdl::PovCamera pov;
  const std::smatch right = number(R"(right -x\*(\d+)/(\d+))");
  pov.right = Vec3(-std::stod(right[1]) / std::stod(right[2]), 0.0, 0.0);
  pov.rightGiven = true;
  REQUIRE(exported.text.find("  up y\n") != std::string::npos);
  pov.upGiven = true;
  pov.angle = std::stod(number(R"(angle ([-0-9.e]+))")[1]);
  pov.location = vec(number("location " + v3), 1);
  pov.sky = vec(number("sky " + v3), 1);
  pov.lookAt = vec(number("look_at " + v3), 1);

  // POV-Ray's rays in the exported scene's space are the original camera's.
  const PovCameraVectors v = povCameraVectors(pov);
  for (int j = 0; j < 120; j += 11)
    for (int i = 0; i < 160; i += 13) {
      Vec3 origin, direction;
      REQUIRE(povPrimaryRay(pov, v, i, j, 160, 120, origin, direction));
      const Ray ray = lucentRay(original, i, j, 160, 120);
      requireSameVector(origin, ray.o);
      requireSameVector(direction, ray.d, 1e-9);
    }

  // Read back as a POV-Ray scene (z negated), the camera is mirrored (`right -x`): the
  // import gives Lucent's camera mirror="true", and traces POV-Ray's rays pixel for pixel.
  const CameraImport imported = importCamera(pov, 160, 120);
  CHECK(imported.differences.empty());
  CHECK(imported.camera.mirror);
  for (int i = 0; i < 160; i += 13) {
    Vec3 origin, direction;
    REQUIRE(povPrimaryRay(pov, v, i, 60, 160, 120, origin, direction));
    const Ray ray = lucentRay(imported.camera, i, 60, 160, 120);
    requireSameVector(ray.d, lucentFromPov(direction), 1e-9);
  }
}

TEST_CASE("round trip: an image-plane camera exports as POV-Ray's own vectors",
          "[sdl][camera][povray]") {
  for (const char* type : {"pinhole", "orthographic"}) {
    INFO(type);
    ParseResult parsed = parseSceneString(
        std::string(R"XML(<scene version="1"><render width="160" height="120"/>
          <camera type=")XML") +
            type + R"XML(" position="1 2 6" look-at="0 0.5 0" image-plane="1.2 0.3 0.1  0 0.9 -0.2"
                  mirror="true" transform="rotate(20, 0 1 0)"/>
          <sphere radius="1"/></scene>)XML",
        "test.xml");
    REQUIRE(parsed.scene);
    const Camera& original = parsed.scene->cameras.front();
    REQUIRE(original.imagePlane);
    const PovExport exported = exportPov(*parsed.scene);
    REQUIRE(exported.ok());
    INFO(exported.text);
    CHECK(exported.text.find("look_at") == std::string::npos);
    const std::string v3 = "<([-0-9.e]+), ([-0-9.e]+), ([-0-9.e]+)>";
    auto vec = [&](const std::string& key) {
      std::smatch m;
      REQUIRE(std::regex_search(exported.text, m, std::regex(key + " " + v3)));
      return Vec3(std::stod(m[1]), std::stod(m[2]), std::stod(m[3]));
    };
    sdl::PovCamera pov;
    if (std::string(type) == "orthographic") pov.type = PovCameraType::Orthographic;
    pov.location = vec("location");
    pov.direction = vec("direction");
    pov.right = vec("right");
    pov.up = vec("up");
    pov.rightGiven = pov.upGiven = true;
    const PovCameraVectors v = povCameraVectors(pov);
    for (int j = 0; j < 120; j += 11)
      for (int i = 0; i < 160; i += 13) {
        Vec3 origin, direction;
        REQUIRE(povPrimaryRay(pov, v, i, j, 160, 120, origin, direction));
        const Ray ray = lucentRay(original, i, j, 160, 120);
        requireSameVector(origin, ray.o, 1e-9);
        requireSameVector(direction, ray.d, 1e-9);
      }
  }
}
