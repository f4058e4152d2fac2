// <focal-blur> exported as POV-Ray's focal blur (aperture twice the lens's diameter, the
// focus as a point on the view axis) and rendered by POV-Ray to Lucent's image.
#include "pov_test_support.h"

#include "../sdl/pov_meaning_support.h"

using namespace lucent;
using namespace lucent::test;

namespace {

// Focused on the green ball, off the view axis: POV-Ray's focal distance is measured to
// the point, Lucent's plane passes through it, so the export puts the point on the axis.
const char* kScene = R"XML(
  <render width="120" height="90" background="0.4 0.6 0.9"/>
  <camera position="0.5 1.6 6" look-at="0 0.8 0" fov="45">
    <focal-blur aperture="0.6" focal-point="0.6 0.8 0" samples="300" variance="0"/>
  </camera>
  <light position="4 8 6"/>
  <plane normal="0 1 0"><material diffuse="0.8" ambient="0.2"><checker color1="0.9" color2="0.15"/></material></plane>
  <sphere center="-1.6 0.6 2.5" radius="0.6"><material diffuse="1 0.3 0.2" phong="0.6"/></sphere>
  <sphere center="0.6 0.8 0" radius="0.8"><material diffuse="0.3 1 0.3" phong="0.6"/></sphere>
  <box min="1.6 0 -5" max="3.4 2.4 -4"><material diffuse="0.3 0.4 1"/></box>)XML";

}  // namespace

TEST_CASE("focal blur is written as POV-Ray's", "[povray][focal-blur]") {
  Exported e = exportScene(kScene);
  REQUIRE(e.pov.ok());
  CHECK(e.has("aperture 1.2\n"));
  CHECK(e.has("blur_samples 300\n"));
  CHECK(e.has("confidence 0.9\n"));
  CHECK(e.has("variance 0\n"));
  // The focus on the view axis at the plane's distance (the focal point's depth along it).
  const Camera& c = e.scene->cameras.front();
  const Vec3 forward = glm::normalize(c.lookAt - c.position);
  const double depth = glm::dot(Vec3(0.6, 0.8, 0.0) - c.position, forward);
  const Vec3 onAxis = c.position + depth * forward;
  const size_t at = e.pov.text.find("focal_point <");
  REQUIRE(at != std::string::npos);
  double x = 0.0, y = 0.0, z = 0.0;
  REQUIRE(std::sscanf(e.pov.text.c_str() + at, "focal_point <%lf, %lf, %lf>", &x, &y, &z) == 3);
  CHECK(x == Approx(onAxis.x).margin(1e-9));
  CHECK(y == Approx(onAxis.y).margin(1e-9));
  CHECK(z == Approx(onAxis.z).margin(1e-9));
}

TEST_CASE("focal blur with min-samples writes both counts", "[povray][focal-blur]") {
  Exported e = exportScene(
      R"(<camera position="0 1 5"><focal-blur aperture="0.5" samples="40" min-samples="8"/></camera><sphere/>)");
  REQUIRE(e.pov.ok());
  CHECK(e.has("blur_samples 8, 40\n"));
}

// Every ray taken: both converge on the same blur; what is left is sampling noise (measured
// 42 dB; POV-Ray's hexagonal lens grid against Lucent's Sobol points).
TEST_CASE("exported focal blur renders in POV-Ray as in Lucent", "[povray][focal-blur][image]") {
  Exported e = exportScene(kScene);
  REQUIRE(e.pov.ok());
  const RgbImage lucent = srgbEncoded(renderWithLucent(*e.scene));
  const RgbImage povray = srgbEncoded(renderWithPovray(e.pov.text, 120, 90));
  const ImageMetrics m = compareImages(lucent, povray, 2.0 / 255.0);
  INFO("PSNR " << m.psnr << " dB, SSIM " << m.ssim);
  CHECK(m.psnr >= 40.0);
  CHECK(m.ssim >= 0.98);
}
