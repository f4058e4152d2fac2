// The camera's normal read from POV-Ray (camera { normal { } }): the imported camera traces
// POV-Ray's rays bent as POV-Ray bends them, by the rule written out here (tracepixel.cpp,
// CreateCameraRay; normal.cpp, waves), in POV-Ray's space before the z negation.
#include "scene_read_support.h"

#include "primitives/noise.h"
#include "render/projection.h"
#include "sdl/pov_camera.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>

using namespace lucent;
using namespace lucent::sdl;

namespace {

// POV-Ray's waves normal from its first source (number_of_waves 1), depth 0.375, frequency
// 3, scaled by <0.5, 1, 1>, bending the unit direction d at the image point (x0, y0, 0).
Vec3 povBent(const Vec3& d, double x0, double y0) {
  const Vec3 source = glm::normalize(dnoise(Vec3(0.0)));
  const int32_t next = static_cast<int32_t>(-560851967LL * 1812433253LL + 12345LL);
  const double f = ((next >> 16) & 0x7FFF) * 0.000030518509476 + 0.01;
  const Vec3 q(2.0 * x0, y0, 0.0);  // the point through the inverse of the scale
  Vec3 n = glm::normalize(Vec3(0.5 * d.x, d.y, d.z));
  const Vec3 toQ = q - source;
  const double l = glm::length(toQ), v = l * 3.0 * f;
  n += std::sin(2.0 * kPi * (v - std::floor(v))) * 0.375 / f / l * toQ;
  return glm::normalize(Vec3(2.0 * n.x, n.y, n.z));
}

}  // namespace

TEST_CASE("a POV-Ray camera's normal bends the imported rays as POV-Ray's",
          "[sdl][camera][normal]") {
  // The camera's own rotation leaves the normal in place (POV-Ray transforms only the
  // camera's vectors); global_settings after the camera still counts.
  auto r = sdltest::readScene(R"(
camera { location <0.5, 1, -3> look_at <0, 1.2, 0> angle 50
  normal { waves 0.375 frequency 3 scale <0.5, 1, 1> } rotate y*10 }
global_settings { number_of_waves 1 }
sphere { 0, 1 pigment { rgb 1 } }
)");
  REQUIRE(r->load.scene);
  const Camera& imported = r->load.scene->cameras.front();
  REQUIRE(imported.normal);
  CHECK(imported.normal->pattern.waveSources == 1);
  sdl::PovCamera pov;
  pov.location = Vec3(0.5, 1, -3);
  pov.lookAt = Vec3(0, 1.2, 0);
  pov.angle = 50.0;
  pov.transform.rotate(Vec3(0, 10, 0));
  const PovCameraVectors v = povCameraVectors(pov);
  const auto projection = makeProjection(imported, 160, 120);
  for (int j = 0; j < 120; j += 17)
    for (int i = 0; i < 160; i += 23) {
      Vec3 origin, direction;
      REQUIRE(povPrimaryRay(pov, v, i, j, 160, 120, origin, direction));
      const double x0 = (i + 0.5) / 160.0 - 0.5, y0 = 0.5 - (j + 0.5) / 120.0;
      const Vec3 want = lucentFromPov(povBent(glm::normalize(direction), x0, y0));
      Ray ray;
      REQUIRE(projection->generateRay(Vec2(i + 0.5, j + 0.5), Vec2(0.5), ray));
      INFO("pixel " << i << " " << j);
      for (int k = 0; k < 3; ++k) CHECK(ray.d[k] == Approx(want[k]).margin(1e-9));
    }
}

TEST_CASE("a camera's bump_map or a normal without a pattern is refused at the normal",
          "[sdl][camera][normal]") {
  CHECK(sdltest::errorsOf("camera { normal { bump_size 0.5 } }\n") ==
        std::vector<std::string>{"test.pov:1:10: error: a normal without a pattern (POV-Ray: "
                                 "'No normal type given')"});
}
